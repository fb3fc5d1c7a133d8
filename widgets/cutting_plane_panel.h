// The cutting plane panel: on/off, an axis-aligned orientation (x, y, z) or a free normal, the
// position (a slider across the data box, and for axis-aligned planes a spin box in the axis's
// own units: degrees, hPa, metres), the width eps of the intersection curves, and what the cut
// face is filled with (gl::SectionField). It produces a gl::CuttingPlane in display space;
// knows nothing of the renderer. GUI thread only.
#pragma once

#include <QString>
#include <QWidget>
#include <array>
#include <vector>

#include "gl/render_settings.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QSlider;

namespace ensil::ui {

// One axis of the data box: where each grid level lies across the box (-1 .. 1, the plane
// panel's position) and its coordinate there, so positions can be shown in data units.
struct PlaneAxis {
    QString name;   // "lon", "plev"
    QString units;  // "degrees_east", "hPa"
    std::vector<double> positions;
    std::vector<double> values;
};

class CuttingPlanePanel : public QWidget {
    Q_OBJECT
public:
    enum Orientation { AlongX, AlongY, AlongZ, Free };
    static constexpr int kSliderSteps = 1000;  // each side of the centre

    explicit CuttingPlanePanel(QWidget* parent = nullptr);

    // The data box in display space and its three axes; keeps the orientation and position.
    void setBox(const glm::vec3& boxMin, const glm::vec3& boxMax, std::array<PlaneAxis, 3> axes);
    // The plane as the renderer takes it (enabled or not).
    [[nodiscard]] gl::CuttingPlane plane() const;
    // Shows a plane (restoring a session) without emitting planeChanged.
    void setPlane(const gl::CuttingPlane& plane);

    // Programmatic control, as the user would (emits planeChanged).
    void setCutting(bool on);
    [[nodiscard]] bool cutting() const;
    void setOrientation(Orientation orientation);
    void setPosition(double position);  // -1 .. 1 across the box
    [[nodiscard]] double position() const;
    // The position in the axis's units for axis-aligned planes (NaN for a free normal).
    [[nodiscard]] double dataPosition() const;

signals:
    void planeChanged();

private:
    void onOrientationChosen(int index);
    void onNormalEdited();
    void onSliderMoved(int value);
    void onDataValueEdited(double value);
    void showPosition();
    [[nodiscard]] glm::vec3 normal() const;
    [[nodiscard]] const PlaneAxis* alignedAxis() const;

    QCheckBox* m_enabled;
    QComboBox* m_orientation;
    std::array<QDoubleSpinBox*, 3> m_normal{};
    QSlider* m_position;
    QDoubleSpinBox* m_dataValue;
    QLabel* m_dataLabel;
    QDoubleSpinBox* m_thickness;
    QComboBox* m_fill;
    glm::vec3 m_boxMin{0.0F};
    glm::vec3 m_boxMax{1.0F};
    std::array<PlaneAxis, 3> m_axes;
};

// Piecewise-linear lookups between an axis's positions and values (either may be decreasing).
double axisValueAt(const PlaneAxis& axis, double position);
double axisPositionOf(const PlaneAxis& axis, double value);

}  // namespace ensil::ui

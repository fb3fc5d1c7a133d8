// The rendering panel: how members are drawn (mode, silhouette thickness tau, surface
// opacity, the mean surface, axis labels and legend), density-based silhouette removal (o*_min,
// o*_max, group size s_G), vertical exaggeration, projection and background. It edits a
// gl::RenderSettings value and says when the user changed it; it knows nothing of the renderer. GUI
// thread only.
#pragma once

#include <QColor>
#include <QWidget>

#include "gl/render_settings.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QGroupBox;
class QSpinBox;
class QToolButton;

namespace ensil::ui {

class RenderPanel : public QWidget {
    Q_OBJECT
public:
    explicit RenderPanel(QWidget* parent = nullptr);

    // Shows these values without emitting anything. The cutting plane is not edited here.
    void setSettings(const gl::RenderSettings& settings);
    // `settings` with this panel's values written over it (the plane is left as it is).
    [[nodiscard]] gl::RenderSettings applyTo(gl::RenderSettings settings) const;

    // Switches the mode as the user would (emits settingsEdited).
    void setMode(gl::RenderMode mode);

    // The largest outlyingness of the meshes on screen, in the variable's units squared: the
    // removal thresholds range over [0, maximum] (wider when they hold larger values). The
    // first range also sets a first band, the lower half: returns true then (applyTo() holds
    // thresholds that differ from the settings last given).
    bool setOutlyingnessRange(double maximum, const QString& unitsSquared);
    void setVerticalExaggeration(double factor);
    [[nodiscard]] double verticalExaggeration() const;
    void setOrthographic(bool orthographic);
    [[nodiscard]] bool orthographic() const;
    void setBackground(const QColor& colour);
    [[nodiscard]] QColor background() const { return m_background; }

signals:
    // Any of the values applyTo() writes changed by the user.
    void settingsEdited();
    void verticalExaggerationChanged(double factor);
    void projectionChanged(bool orthographic);
    void backgroundChanged(const QColor& colour);

private:
    void chooseBackground();
    void showBackground();
    void updateEnabled();

    QComboBox* m_mode;
    QDoubleSpinBox* m_thickness;
    QDoubleSpinBox* m_opacity;
    QCheckBox* m_mean;
    QDoubleSpinBox* m_meanOpacity;
    QComboBox* m_context;
    QCheckBox* m_band;
    QCheckBox* m_contextSpread;
    QCheckBox* m_axes;
    QCheckBox* m_legend;
    QCheckBox* m_rims;
    QComboBox* m_floor;
    QSpinBox* m_floorLevel;
    QGroupBox* m_map;
    QCheckBox* m_coastlines;
    QCheckBox* m_borders;
    QCheckBox* m_graticule;
    QGroupBox* m_removal;
    QDoubleSpinBox* m_removalMin;
    QDoubleSpinBox* m_removalMax;
    QSpinBox* m_groupSize;
    QDoubleSpinBox* m_exaggeration;
    QComboBox* m_projection;
    QToolButton* m_backgroundButton;
    QColor m_background;
};

}  // namespace ensil::ui

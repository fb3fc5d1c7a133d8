// The toolbar of the silhouette view: the isovalue (with the variable's range, units and value
// histogram), the render mode, the silhouette thickness, the number of clusters and the mean
// surface. Emits what the user set; knows nothing of jobs or data. GUI thread only.
#pragma once

#include <QToolBar>
#include <cstdint>
#include <vector>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QSpinBox;

namespace ensil::ui {

class IsovalueControl;

class RenderToolbar : public QToolBar {
    Q_OBJECT
public:
    explicit RenderToolbar(QWidget* parent = nullptr);

    // Range and units of the variable; the value is set without emitting isovalueChanged.
    void setIsovalueRange(double minimum, double maximum, double value, const QString& units);
    // The histogram of the values over that range, drawn behind the isovalue.
    void setIsovalueHistogram(std::vector<std::uint64_t> counts);
    void setMemberCount(int members, int clusters);
    void setThickness(double tau);

    [[nodiscard]] double isovalue() const;
    [[nodiscard]] int clusterCount() const;
    [[nodiscard]] QDoubleSpinBox* isovalueBox() const;
    [[nodiscard]] IsovalueControl* isovalueControl() const { return m_isovalue; }

signals:
    void isovalueChanged(double value);
    void modeChanged(int mode);  // as gl::RenderMode: shaded, spaghetti, surfaces, opaque
    void thicknessChanged(double tau);
    void clusterCountChanged(int k);
    void meanToggled(bool shown);
    void verticalExaggerationChanged(double factor);

private:
    IsovalueControl* m_isovalue;
    QComboBox* m_mode;
    QDoubleSpinBox* m_thickness;
    QSpinBox* m_clusters;
    QCheckBox* m_mean;
    QDoubleSpinBox* m_exaggeration;
};

}  // namespace ensil::ui

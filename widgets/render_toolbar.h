// The toolbar of the silhouette view: the isovalue (with the variable's range, units and value
// histogram) and the number of clusters, the two settings that change what is computed; how
// it is drawn lives in the rendering dock (widgets/render_panel.h). Emits what the user set;
// knows nothing of jobs or data. GUI thread only.
#pragma once

#include <QToolBar>
#include <cstdint>
#include <vector>

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

    [[nodiscard]] double isovalue() const;
    [[nodiscard]] int clusterCount() const;
    [[nodiscard]] QDoubleSpinBox* isovalueBox() const;
    [[nodiscard]] IsovalueControl* isovalueControl() const { return m_isovalue; }

signals:
    void isovalueChanged(double value);
    // While the isovalue is dragged (IsovalueControl): the value under the pointer, then the end.
    void isovalueScrubbed(double value);
    void isovalueScrubEnded();
    void clusterCountChanged(int k);

private:
    IsovalueControl* m_isovalue;
    QSpinBox* m_clusters;
};

}  // namespace ensil::ui

// A thin strip that draws the histogram of a variable's values over [minimum, maximum], with the
// current value as a marker line. Bar heights follow log(1 + count), so the rare high values
// where interesting isosurfaces live stay visible next to the bulk of the distribution.
// Pressing or dragging on the strip previews a value; releasing the button picks it.
// GUI thread only.
#pragma once

#include <QWidget>
#include <cstdint>
#include <vector>

namespace ensil::ui {

class HistogramStrip : public QWidget {
    Q_OBJECT
public:
    explicit HistogramStrip(QWidget* parent = nullptr);

    // Bins of equal width over the range, as prep::FieldStatistics computes them.
    void setCounts(std::vector<std::uint64_t> counts);
    void setRange(double minimum, double maximum);
    void setMarker(double value);

    [[nodiscard]] double marker() const { return m_marker; }
    [[nodiscard]] const std::vector<std::uint64_t>& counts() const { return m_counts; }
    // The value under pixel column x (clamped to the strip), and the column of a value.
    [[nodiscard]] double valueAt(int x) const;
    [[nodiscard]] int columnOf(double value) const;

    [[nodiscard]] QSize sizeHint() const override;
    [[nodiscard]] QSize minimumSizeHint() const override;

signals:
    void valuePreviewed(double value);  // while the mouse button is down
    void valuePicked(double value);     // on release

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;

private:
    std::vector<std::uint64_t> m_counts;
    double m_minimum = 0.0;
    double m_maximum = 1.0;
    double m_marker = 0.0;
    bool m_dragging = false;
};

}  // namespace ensil::ui

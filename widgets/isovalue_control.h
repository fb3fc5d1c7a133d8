// The isovalue control of the toolbar: a histogram strip of the variable's values with the
// isovalue marked, a slider over [minimum, maximum] and a spin box (decimals suited to the
// range, units suffix), kept in step. isovalueChanged is emitted once per commit (slider
// release, a slider or spin-box step, Enter or focus leaving the spin box, release on the
// strip), never per dragged pixel, because each commit restarts preprocessing; while dragging,
// all three show the value under the mouse. PageUp/PageDown step by a tenth of the range.
// GUI thread only.
#pragma once

#include <QWidget>
#include <cstdint>
#include <vector>

class QDoubleSpinBox;
class QSlider;

namespace ensil::ui {

class HistogramStrip;

class IsovalueControl : public QWidget {
    Q_OBJECT
public:
    static constexpr int kSliderSteps = 1000;

    explicit IsovalueControl(QWidget* parent = nullptr);

    // Range, value and units of the variable; sets the value without emitting isovalueChanged.
    void setRange(double minimum, double maximum, double value, const QString& units);
    void setHistogram(std::vector<std::uint64_t> counts);
    // Shows a value without emitting isovalueChanged.
    void setValue(double value);

    // The value shown, rounded to the spin box's decimals: what a commit hands on.
    [[nodiscard]] double value() const;
    [[nodiscard]] double minimum() const { return m_minimum; }
    [[nodiscard]] double maximum() const { return m_maximum; }
    // Slider ticks map linearly over [minimum, maximum], exactly at both ends.
    [[nodiscard]] double valueAtSliderPosition(int position) const;
    [[nodiscard]] int sliderPositionOf(double value) const;

    [[nodiscard]] QDoubleSpinBox* spinBox() const { return m_spin; }
    [[nodiscard]] QSlider* slider() const { return m_slider; }
    [[nodiscard]] HistogramStrip* histogram() const { return m_strip; }

signals:
    void isovalueChanged(double value);

private:
    void onSliderMoved(int position);
    void onSpinCommitted(double value);
    // Shows `value` in the strip, slider and spin box without committing it.
    void showValue(double value);
    void commit(double value);

    HistogramStrip* m_strip;
    QSlider* m_slider;
    QDoubleSpinBox* m_spin;
    double m_minimum = 0.0;
    double m_maximum = 1.0;
    double m_committed = 0.0;  // the last value handed on, so a commit is not repeated
};

}  // namespace ensil::ui

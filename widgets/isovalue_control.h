// The isovalue control of the toolbar: a histogram strip of the variable's values with the
// isovalue marked, a slider over [minimum, maximum] and a spin box (decimals suited to the
// range, units suffix), kept in step. isovalueChanged is emitted once per commit (slider
// release, a slider or spin-box step, Enter or focus leaving the spin box, release on the
// strip, a pause in turning the wheel), never per dragged pixel, because each commit restarts
// the full preprocessing. While dragging (or turning the wheel over the slider or spin box),
// all three show the value under the pointer and isovalueScrubbed hands it on for a quick
// preview; scrubEnded follows the commit that ends it. PageUp/PageDown step by a tenth of the
// range. GUI thread only.
#pragma once

#include <QTimer>
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

    // Quiet time after the last wheel step before its value is committed.
    static constexpr int kWheelSettleMs = 300;

signals:
    void isovalueChanged(double value);
    // The value under the pointer while it moves (not committed): for a preview.
    void isovalueScrubbed(double value);
    // The scrub is over; emitted after the isovalueChanged of the value released, if any.
    void scrubEnded();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void onSliderMoved(int position);
    void onSpinCommitted(double value);
    // Shows `value` in the strip, slider and spin box without committing it.
    void showValue(double value);
    void commit(double value);
    void scrub(double value);
    void endScrub(double value);

    HistogramStrip* m_strip;
    QSlider* m_slider;
    QDoubleSpinBox* m_spin;
    double m_minimum = 0.0;
    double m_maximum = 1.0;
    double m_committed = 0.0;  // the last value handed on, so a commit is not repeated
    bool m_scrubbing = false;
    bool m_wheeling = false;  // wheel steps preview; the pause after them commits
    QTimer m_wheelSettle;
};

}  // namespace ensil::ui

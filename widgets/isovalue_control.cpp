#include "widgets/isovalue_control.h"

#include <QBoxLayout>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QSignalBlocker>
#include <QSlider>
#include <algorithm>
#include <cmath>

#include "widgets/histogram_strip.h"

namespace ensil::ui {
namespace {
constexpr int kSingleStepTicks = IsovalueControl::kSliderSteps / 100;
// A tenth of the range, the same on the slider and in the spin box (10 single steps there).
constexpr int kPageStepTicks = IsovalueControl::kSliderSteps / 10;
}  // namespace

IsovalueControl::IsovalueControl(QWidget* parent)
    : QWidget(parent),
      m_strip(new HistogramStrip(this)),
      m_slider(new QSlider(Qt::Horizontal, this)),
      m_spin(new QDoubleSpinBox(this)) {
    setObjectName(QStringLiteral("isovalueControl"));
    m_slider->setRange(0, kSliderSteps);
    m_slider->setSingleStep(kSingleStepTicks);
    m_slider->setPageStep(kPageStepTicks);
    m_slider->setToolTip(
        tr("Drag to choose the isovalue: the surfaces follow at reduced detail, in full on "
           "release"));
    // The spin box hands on a value when the user commits it (Enter, focus out, a step), not
    // on every keystroke.
    m_spin->setKeyboardTracking(false);
    m_spin->setMinimumWidth(110);
    m_spin->setToolTip(tr("The isovalue whose surfaces are drawn (Enter to apply)"));

    auto* track = new QVBoxLayout;
    track->setContentsMargins(0, 0, 0, 0);
    track->setSpacing(0);
    track->addWidget(m_strip);
    track->addWidget(m_slider);
    auto* row = new QHBoxLayout(this);
    row->setContentsMargins(0, 0, 0, 0);
    row->setSpacing(4);
    row->addLayout(track, 1);
    row->addWidget(m_spin);
    setFocusProxy(m_slider);
    setEnabled(false);
    m_slider->installEventFilter(this);
    m_spin->installEventFilter(this);
    m_wheelSettle.setSingleShot(true);
    m_wheelSettle.setInterval(kWheelSettleMs);
    connect(&m_wheelSettle, &QTimer::timeout, this, [this] {
        m_wheeling = false;
        endScrub(value());
    });

    connect(m_slider, &QSlider::valueChanged, this, &IsovalueControl::onSliderMoved);
    connect(m_slider, &QSlider::sliderReleased, this,
            [this] { endScrub(valueAtSliderPosition(m_slider->value())); });
    connect(m_spin, &QDoubleSpinBox::valueChanged, this, &IsovalueControl::onSpinCommitted);
    connect(m_spin, &QDoubleSpinBox::editingFinished, this,
            [this] { onSpinCommitted(m_spin->value()); });
    connect(m_strip, &HistogramStrip::valuePreviewed, this, [this](double v) {
        m_slider->setFocus(Qt::MouseFocusReason);  // so PageUp/PageDown work after a click
        scrub(v);
    });
    connect(m_strip, &HistogramStrip::valuePicked, this, &IsovalueControl::endScrub);
}

void IsovalueControl::setRange(double minimum, double maximum, double value, const QString& units) {
    m_minimum = minimum;
    m_maximum = std::max(minimum, maximum);
    const double span = std::max(m_maximum - m_minimum, 1e-12);
    // Enough decimals to step through 1/1000 of the range, as many as the slider has ticks.
    const int decimals = std::clamp(static_cast<int>(std::ceil(-std::log10(span / 1000.0))), 0, 6);
    {
        const QSignalBlocker block(m_spin);
        m_spin->setDecimals(decimals);
        m_spin->setRange(m_minimum, m_maximum);
        m_spin->setSingleStep(span / 100.0);
        m_spin->setSuffix(units.isEmpty() ? QString() : QLatin1Char(' ') + units);
    }
    m_strip->setRange(m_minimum, m_maximum);
    setEnabled(true);
    setValue(value);
}

void IsovalueControl::setHistogram(std::vector<std::uint64_t> counts) {
    m_strip->setCounts(std::move(counts));
}

void IsovalueControl::setValue(double value) {
    showValue(value);
    m_committed = m_spin->value();
}

double IsovalueControl::value() const { return m_spin->value(); }

double IsovalueControl::valueAtSliderPosition(int position) const {
    if (position <= 0) return m_minimum;
    if (position >= kSliderSteps) return m_maximum;  // exact, not min + span * 1.0
    return m_minimum + (m_maximum - m_minimum) * position / kSliderSteps;
}

int IsovalueControl::sliderPositionOf(double value) const {
    const double span = m_maximum - m_minimum;
    if (span <= 0.0) return 0;
    const double t = std::clamp((value - m_minimum) / span, 0.0, 1.0);
    return static_cast<int>(std::lround(t * kSliderSteps));
}

void IsovalueControl::onSliderMoved(int position) {
    const double v = valueAtSliderPosition(position);
    // A drag or the wheel previews, committing on release or a pause; a step by key or a click
    // on the groove commits now.
    if (m_slider->isSliderDown() || m_wheeling) {
        scrub(v);
    } else {
        showValue(v);
        commit(v);
    }
}

void IsovalueControl::onSpinCommitted(double value) {
    if (m_wheeling) return scrub(value);
    showValue(value);
    commit(value);
}

bool IsovalueControl::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() == QEvent::Wheel && isEnabled()) {
        // The steps this wheel event makes (valueChanged, just after) preview; the pause
        // after the last one commits.
        m_wheeling = true;
        m_wheelSettle.start();
    }
    return QWidget::eventFilter(watched, event);
}

void IsovalueControl::scrub(double value) {
    showValue(value);
    m_scrubbing = true;
    emit isovalueScrubbed(m_spin->value());
}

void IsovalueControl::endScrub(double value) {
    commit(value);
    if (!m_scrubbing) return;
    m_scrubbing = false;
    emit scrubEnded();
}

void IsovalueControl::showValue(double value) {
    {
        const QSignalBlocker blockSpin(m_spin);
        const QSignalBlocker blockSlider(m_slider);
        m_spin->setValue(value);
        // The slider stays where the user holds it; only the other widgets follow a drag.
        if (!m_slider->isSliderDown()) m_slider->setValue(sliderPositionOf(value));
    }
    m_strip->setMarker(value);
}

void IsovalueControl::commit(double value) {
    showValue(value);
    const double shown = m_spin->value();
    if (shown == m_committed) return;
    m_committed = shown;
    emit isovalueChanged(shown);
}

}  // namespace ensil::ui

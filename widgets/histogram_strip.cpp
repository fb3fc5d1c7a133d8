#include "widgets/histogram_strip.h"

#include <QMouseEvent>
#include <QPainter>
#include <algorithm>
#include <cmath>

namespace ensil::ui {

HistogramStrip::HistogramStrip(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("histogramStrip"));
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    setCursor(Qt::SizeHorCursor);
    setToolTip(tr("How often each value occurs (log scale); click or drag to pick the isovalue"));
}

void HistogramStrip::setCounts(std::vector<std::uint64_t> counts) {
    m_counts = std::move(counts);
    update();
}

void HistogramStrip::setRange(double minimum, double maximum) {
    m_minimum = minimum;
    m_maximum = maximum;
    update();
}

void HistogramStrip::setMarker(double value) {
    m_marker = value;
    update();
}

double HistogramStrip::valueAt(int x) const {
    const int last = std::max(1, width() - 1);
    const double t = std::clamp(static_cast<double>(x) / last, 0.0, 1.0);
    // The ends map exactly, so the whole range can be picked.
    if (t >= 1.0) return m_maximum;
    return m_minimum + t * (m_maximum - m_minimum);
}

int HistogramStrip::columnOf(double value) const {
    const double span = m_maximum - m_minimum;
    if (span <= 0.0) return 0;
    const double t = std::clamp((value - m_minimum) / span, 0.0, 1.0);
    return static_cast<int>(std::lround(t * std::max(1, width() - 1)));
}

QSize HistogramStrip::sizeHint() const { return {220, 22}; }
QSize HistogramStrip::minimumSizeHint() const { return {80, 14}; }

void HistogramStrip::paintEvent(QPaintEvent* /*event*/) {
    QPainter painter(this);
    painter.fillRect(rect(), palette().color(QPalette::Base));
    const std::uint64_t most =
        m_counts.empty() ? 0 : *std::max_element(m_counts.begin(), m_counts.end());
    if (most > 0) {
        // log1p keeps a bin with a single value visible (at least a pixel) next to millions.
        const double top = std::log1p(static_cast<double>(most));
        const auto bins = static_cast<double>(m_counts.size());
        const QColor bar = palette().color(QPalette::Dark);
        for (std::size_t b = 0; b < m_counts.size(); ++b) {
            if (m_counts[b] == 0) continue;
            const auto x0 = static_cast<int>(std::lround(static_cast<double>(b) * width() / bins));
            const auto x1 =
                static_cast<int>(std::lround(static_cast<double>(b + 1) * width() / bins));
            const double fraction = std::log1p(static_cast<double>(m_counts[b])) / top;
            const int h = std::max(1, static_cast<int>(std::lround(fraction * height())));
            painter.fillRect(x0, height() - h, std::max(1, x1 - x0), h, bar);
        }
    }
    if (isEnabled()) {
        painter.fillRect(columnOf(m_marker) - 1, 0, 2, height(),
                         palette().color(QPalette::Highlight));
    }
}

void HistogramStrip::mousePressEvent(QMouseEvent* event) {
    if (event->button() != Qt::LeftButton) return;
    m_dragging = true;
    setMarker(valueAt(event->position().toPoint().x()));
    emit valuePreviewed(m_marker);
}

void HistogramStrip::mouseMoveEvent(QMouseEvent* event) {
    if (!m_dragging) return;
    setMarker(valueAt(event->position().toPoint().x()));
    emit valuePreviewed(m_marker);
}

void HistogramStrip::mouseReleaseEvent(QMouseEvent* event) {
    if (!m_dragging || event->button() != Qt::LeftButton) return;
    m_dragging = false;
    setMarker(valueAt(event->position().toPoint().x()));
    emit valuePicked(m_marker);
}

}  // namespace ensil::ui

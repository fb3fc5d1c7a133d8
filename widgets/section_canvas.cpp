#include "widgets/section_canvas.h"

#include <QHelpEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QToolTip>
#include <cmath>

#include "data/number_text.h"
#include "widgets/segment_distance.h"

namespace ensil::ui {
namespace {

constexpr double kPickPixels = 6.0;  // how near the pointer a contour must pass to be picked

}  // namespace

engine::SectionStyle SectionCanvas::sectionStyle() const {
    engine::SectionStyle style;
    style.compact = true;  // the dock's controls say what the figure's title would
    style.fontPoints = font().pointSizeF() > 0 ? font().pointSizeF() : style.fontPoints;
    return style;
}

SectionCanvas::SectionCanvas(QWidget* parent) : QWidget(parent) {
    setMouseTracking(true);
    setMinimumSize(120, 60);
    setAttribute(Qt::WA_OpaquePaintEvent);
}

void SectionCanvas::setView(std::shared_ptr<const engine::SectionView> view) {
    m_view = std::move(view);
    m_drawnValid = false;
    if (m_view) m_message.clear();
    update();
}

void SectionCanvas::setMessage(const QString& message) {
    m_message = message;
    m_view.reset();
    update();
}

void SectionCanvas::setEmphasis(engine::SectionEmphasis emphasis) {
    // The hover alone is drawn over the kept image; anything else redraws it.
    if (emphasis.selected != m_emphasis.selected || emphasis.hidden != m_emphasis.hidden) {
        m_drawnValid = false;
    }
    m_emphasis = std::move(emphasis);
    update();
}

void SectionCanvas::setOverlay(std::vector<engine::SectionLine> overlay) {
    m_overlay = std::move(overlay);
    update();
}

void SectionCanvas::resizeEvent(QResizeEvent* event) {
    m_drawnValid = false;
    QWidget::resizeEvent(event);
}

std::optional<glm::dvec2> SectionCanvas::unitAt(QPointF pos) const {
    if (!m_view) return std::nullopt;
    const QRectF plot = engine::sectionPlotRect(*m_view, QRectF(rect()), sectionStyle());
    if (!plot.contains(pos)) return std::nullopt;
    return glm::dvec2((pos.x() - plot.left()) / plot.width(),
                      (plot.bottom() - pos.y()) / plot.height());
}

std::optional<std::size_t> SectionCanvas::memberAt(QPointF pos) const {
    if (!unitAt(pos)) return std::nullopt;
    const QRectF plot = engine::sectionPlotRect(*m_view, QRectF(rect()), sectionStyle());
    const auto toWidget = [&](glm::dvec2 p) {
        return QPointF(plot.left() + p.x * plot.width(), plot.bottom() - p.y * plot.height());
    };
    std::optional<std::size_t> best;
    double nearest = kPickPixels;
    for (const engine::MemberContour& c : m_view->members) {
        if (c.member < m_emphasis.hidden.size() && m_emphasis.hidden[c.member]) continue;
        for (const engine::SectionLine& line : c.lines) {
            const std::size_t n = line.points.size();
            for (std::size_t i = 0; i + 1 < n + (line.closed ? 1 : 0); ++i) {
                const double d = distanceToSegment(pos, toWidget(line.points[i]),
                                                   toWidget(line.points[(i + 1) % n]));
                if (d < nearest) {
                    nearest = d;
                    best = c.member;
                }
            }
        }
    }
    return best;
}

QString SectionCanvas::describe(QPointF pos) const {
    const auto unit = unitAt(pos);
    if (!unit) return {};
    const auto number = [this](float v) {
        return std::isnan(v) ? tr("no value")
                             : QString::fromStdString(data::readableNumber(v)) +
                                   (m_view->units.empty()
                                        ? QString()
                                        : QLatin1Char(' ') + QString::fromStdString(m_view->units));
    };
    if (const auto member = memberAt(pos)) {
        return tr("%1 (#%2): %3 here")
            .arg(QString::fromStdString(m_view->memberNames.at(*member)))
            .arg(*member + 1)
            .arg(number(engine::sectionValueAt(*m_view, m_view->memberValues[*member], *unit)));
    }
    if (m_view->fill.empty()) return {};
    return QStringLiteral("%1: %2").arg(
        QString::fromStdString(m_view->fillCaption),
        number(engine::sectionValueAt(*m_view, m_view->fill, *unit)));
}

void SectionCanvas::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    if (!m_view) {
        painter.fillRect(rect(), palette().window());
        painter.setPen(palette().color(QPalette::PlaceholderText));
        painter.drawText(rect().adjusted(12, 12, -12, -12), Qt::AlignCenter | Qt::TextWordWrap,
                         m_message);
        return;
    }
    const engine::SectionStyle style = sectionStyle();
    const qreal ratio = devicePixelRatioF();
    if (!m_drawnValid || m_drawn.size() != size() * ratio) {
        m_drawn = QImage(size() * ratio, QImage::Format_ARGB32_Premultiplied);
        m_drawn.setDevicePixelRatio(ratio);
        QPainter drawn(&m_drawn);
        engine::SectionEmphasis still = m_emphasis;
        still.hovered = -1;
        engine::paintSection(drawn, *m_view, QRectF(rect()), still, style);
        m_drawnValid = true;
    }
    painter.drawImage(0, 0, m_drawn);
    // The other section's place, and a path being drawn: dashed, over a white underlay so that
    // it reads on any fill.
    std::vector<engine::SectionLine> overlay = m_overlay;
    if (m_pathStart) overlay.push_back({{*m_pathStart, m_pathEnd}, false});
    if (!overlay.empty()) {
        const QRectF plot = engine::sectionPlotRect(*m_view, QRectF(rect()), style);
        painter.save();
        painter.setRenderHint(QPainter::Antialiasing);
        painter.setClipRect(plot);
        for (const engine::SectionLine& line : overlay) {
            QPolygonF polygon;
            for (const glm::dvec2& p : line.points) {
                polygon << QPointF(plot.left() + p.x * plot.width(),
                                   plot.bottom() - p.y * plot.height());
            }
            painter.setPen(QPen(QColor(255, 255, 255, 200), 3.5));
            painter.drawPolyline(polygon);
            painter.setPen(QPen(Qt::black, 1.5, Qt::DashLine));
            painter.drawPolyline(polygon);
        }
        painter.restore();
    }
    const int hovered = m_hovered >= 0 ? m_hovered : m_emphasis.hovered;
    if (hovered >= 0 && (static_cast<std::size_t>(hovered) >= m_emphasis.hidden.size() ||
                         !m_emphasis.hidden[static_cast<std::size_t>(hovered)])) {
        engine::paintHoveredMember(painter, *m_view, QRectF(rect()),
                                   static_cast<std::size_t>(hovered), style);
    }
}

void SectionCanvas::mouseMoveEvent(QMouseEvent* event) {
    if (m_pathStart) {
        if (const auto unit = unitAt(event->position())) m_pathEnd = *unit;
        update();
        return;
    }
    const auto member = memberAt(event->position());
    const int hovered = member ? static_cast<int>(*member) : -1;
    if (hovered != m_hovered) {
        m_hovered = hovered;
        update();
        emit memberHovered(hovered);
    }
}

void SectionCanvas::mousePressEvent(QMouseEvent* event) {
    if (event->button() == Qt::RightButton && m_drawsPaths) {
        if (const auto unit = unitAt(event->position())) {
            m_pathStart = *unit;
            m_pathEnd = *unit;
        }
        return;
    }
    if (event->button() != Qt::LeftButton || !unitAt(event->position())) return;
    const auto member = memberAt(event->position());
    emit memberClicked(member ? static_cast<int>(*member) : -1, event->modifiers());
}

void SectionCanvas::mouseReleaseEvent(QMouseEvent* event) {
    if (event->button() != Qt::RightButton || !m_pathStart) return;
    const glm::dvec2 from = *m_pathStart;
    m_pathStart.reset();
    update();
    // A click is no path: the ends must lie a few pixels apart.
    const QRectF plot = engine::sectionPlotRect(*m_view, QRectF(rect()), sectionStyle());
    if (std::hypot((m_pathEnd.x - from.x) * plot.width(), (m_pathEnd.y - from.y) * plot.height()) <
        2 * kPickPixels) {
        return;
    }
    emit pathDrawn(from, m_pathEnd);
}

void SectionCanvas::leaveEvent(QEvent*) {
    if (m_hovered < 0) return;
    m_hovered = -1;
    update();
    emit memberHovered(-1);
}

bool SectionCanvas::event(QEvent* event) {
    if (event->type() == QEvent::ToolTip) {
        auto* help = static_cast<QHelpEvent*>(event);
        const QString text = describe(help->pos());
        if (text.isEmpty()) {
            QToolTip::hideText();
        } else {
            QToolTip::showText(help->globalPos(), text, this);
        }
        return true;
    }
    return QWidget::event(event);
}

}  // namespace ensil::ui

#include "widgets/cluster_timeline.h"

#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QToolButton>
#include <QToolTip>
#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

#include "gl/palette.h"
#include "workbench/member_selection.h"

namespace ensil::ui {
namespace {

constexpr double kMargin = 8.0;
constexpr double kLabelHeight = 18.0;
constexpr double kBarWidth = 14.0;
constexpr double kClusterGap = 1.0;  // rows between two clusters' bars

QColor colourOf(int identity) {
    const glm::vec3 c = gl::clusterColor(identity);
    return QColor::fromRgbF(c.r, c.g, c.b);
}

}  // namespace

ClusterTimeline::ClusterTimeline(workbench::MemberSelection* selection, QWidget* parent)
    : QWidget(parent), m_selection(selection), m_filling(new QToolButton(this)) {
    m_filling->setAutoRaise(true);
    m_filling->setToolTip(
        tr("The clusters of the steps not visited are computed in the "
           "background (no surfaces); click to stop"));
    m_filling->hide();
    connect(m_filling, &QToolButton::clicked, this, &ClusterTimeline::stopFillingRequested);
    setObjectName(QStringLiteral("clusterTimeline"));
    setMouseTracking(true);
    setMinimumHeight(110);
    setToolTip(
        tr("Clusters over time: each column a time step, each bar a cluster (click to "
           "select its members), each line a member"));
    for (auto signal : {&workbench::MemberSelection::selectionChanged,
                        &workbench::MemberSelection::membersReset}) {
        connect(selection, signal, this, qOverload<>(&QWidget::update));
    }
    connect(selection, &workbench::MemberSelection::hoverChanged, this,
            qOverload<>(&QWidget::update));
}

void ClusterTimeline::setSteps(QStringList labels) {
    m_labels = std::move(labels);
    m_identities.assign(static_cast<std::size_t>(m_labels.size()), {});
    m_current = -1;
    layOut();
    update();
}

void ClusterTimeline::setStepClusters(int step, std::vector<int> identities) {
    if (step < 0 || step >= m_labels.size()) return;
    m_identities[static_cast<std::size_t>(step)] = std::move(identities);
    layOut();
    update();
}

const std::vector<int>& ClusterTimeline::stepClusters(int step) const {
    static const std::vector<int> none;
    return step >= 0 && step < m_labels.size() ? m_identities[static_cast<std::size_t>(step)]
                                               : none;
}

void ClusterTimeline::setCurrentStep(int step) {
    m_current = step;
    update();
}

void ClusterTimeline::setFilling(int done, int total) {
    m_filling->setVisible(total > 0 && done < total);
    if (!m_filling->isVisible()) return;
    m_filling->setText(tr("Clustering the other steps: %1 of %2 - stop").arg(done).arg(total));
    m_filling->adjustSize();
    m_filling->move(width() - m_filling->width() - 2, 0);
}

void ClusterTimeline::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    m_filling->move(width() - m_filling->width() - 2, 0);
}

void ClusterTimeline::layOut() {
    m_slots.assign(m_identities.size(), {});
    m_slotCount = 0.0;
    const std::vector<double>* previous = nullptr;
    for (std::size_t s = 0; s < m_identities.size(); ++s) {
        const std::vector<int>& ids = m_identities[s];
        if (ids.empty()) continue;
        std::vector<int> order(ids.size());
        std::iota(order.begin(), order.end(), 0);
        std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
            const auto ua = static_cast<std::size_t>(a), ub = static_cast<std::size_t>(b);
            if (ids[ua] != ids[ub]) return ids[ua] < ids[ub];
            if (previous != nullptr && previous->size() == ids.size()) {
                return (*previous)[ua] < (*previous)[ub];
            }
            return a < b;
        });
        std::vector<double>& rows = m_slots[s];
        rows.assign(ids.size(), 0.0);
        double y = 0.0;
        for (std::size_t r = 0; r < order.size(); ++r) {
            const auto m = static_cast<std::size_t>(order[r]);
            if (r > 0 && ids[m] != ids[static_cast<std::size_t>(order[r - 1])]) y += kClusterGap;
            rows[m] = y;
            y += 1.0;
        }
        m_slotCount = std::max(m_slotCount, y);
        previous = &rows;
    }
}

double ClusterTimeline::columnX(int step) const {
    const int n = std::max<int>(1, static_cast<int>(m_labels.size()));
    const double inner = width() - 2 * kMargin - kBarWidth;
    return kMargin + kBarWidth / 2 + (n == 1 ? inner / 2 : inner * step / (n - 1));
}

double ClusterTimeline::slotY(double slot) const {
    const double inner = height() - 2 * kMargin - kLabelHeight;
    return kMargin + inner * (slot + 0.5) / std::max(1.0, m_slotCount);
}

QList<int> ClusterTimeline::membersAt(int step, int identity) const {
    QList<int> members;
    const std::vector<int>& ids = stepClusters(step);
    for (std::size_t m = 0; m < ids.size(); ++m) {
        if (ids[m] == identity) members << static_cast<int>(m);
    }
    return members;
}

QRectF ClusterTimeline::barRect(int step, int identity) const {
    const QList<int> members = membersAt(step, identity);
    if (members.isEmpty()) return {};
    const std::vector<double>& rows = m_slots[static_cast<std::size_t>(step)];
    double lo = 1e300, hi = -1e300;
    for (const int m : members) {
        lo = std::min(lo, rows[static_cast<std::size_t>(m)]);
        hi = std::max(hi, rows[static_cast<std::size_t>(m)]);
    }
    const double rowHeight = slotY(1.0) - slotY(0.0);
    return {columnX(step) - kBarWidth / 2, slotY(lo) - rowHeight / 2, kBarWidth,
            slotY(hi) - slotY(lo) + rowHeight};
}

void ClusterTimeline::paintEvent(QPaintEvent* /*event*/) {
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.fillRect(rect(), palette().base());
    const int steps = static_cast<int>(m_labels.size());
    if (steps < 2) {
        painter.setPen(palette().color(QPalette::PlaceholderText));
        painter.drawText(rect(), Qt::AlignCenter,
                         tr("Clusters over time appear here for data with several time steps."));
        return;
    }
    // Tracks first, under the bars: each member from each built step to the next built one.
    const int hovered = m_selection->hovered();
    for (int pass = 0; pass < 2; ++pass) {  // the selected and hovered on top
        for (std::size_t m = 0; m < static_cast<std::size_t>(m_selection->memberCount()); ++m) {
            const bool emphasised =
                m_selection->isSelected(static_cast<int>(m)) || static_cast<int>(m) == hovered;
            if (emphasised != (pass == 1)) continue;
            int from = -1;
            for (int s = 0; s < steps; ++s) {
                const std::vector<int>& ids = m_identities[static_cast<std::size_t>(s)];
                if (ids.size() <= m) continue;
                if (from >= 0) {
                    const QPointF a(columnX(from),
                                    slotY(m_slots[static_cast<std::size_t>(from)][m]));
                    const QPointF b(columnX(s), slotY(m_slots[static_cast<std::size_t>(s)][m]));
                    QPainterPath path(a);
                    const double mid = 0.5 * (a.x() + b.x());
                    path.cubicTo(QPointF(mid, a.y()), QPointF(mid, b.y()), b);
                    QColor c = colourOf(m_identities[static_cast<std::size_t>(from)][m]);
                    c.setAlphaF(emphasised ? 1.0 : 0.45);
                    painter.setPen(QPen(c, emphasised ? 2.5 : 1.2));
                    painter.drawPath(path);
                }
                from = s;
            }
        }
    }
    const QFontMetricsF metrics(font());
    // The dates under the columns: without the year when they share it, and every k-th one
    // where they would touch (the first, the last and the one on screen always).
    bool oneYear = true;
    for (const QString& l : m_labels) oneYear = oneYear && l.left(5) == m_labels.front().left(5);
    const auto shortLabel = [&](const QString& l) {
        return oneYear && l.size() > 5 && l[4] == QLatin1Char('-') ? l.mid(5) : l;
    };
    QFont bold = font();
    bold.setBold(true);
    double widest = 0.0;
    for (const QString& l : m_labels) {
        widest = std::max(widest, QFontMetricsF(bold).horizontalAdvance(shortLabel(l)));
    }
    const double spacing = columnX(1) - columnX(0);
    const int labelEvery = std::max(1, static_cast<int>(std::ceil((widest + 12.0) / spacing)));
    for (int s = 0; s < steps; ++s) {
        const std::vector<int>& ids = m_identities[static_cast<std::size_t>(s)];
        std::vector<int> clusters(ids.begin(), ids.end());
        std::sort(clusters.begin(), clusters.end());
        clusters.erase(std::unique(clusters.begin(), clusters.end()), clusters.end());
        if (clusters.empty()) {
            painter.setPen(QPen(palette().color(QPalette::Mid), 1.0, Qt::DotLine));
            painter.drawLine(QPointF(columnX(s), kMargin),
                             QPointF(columnX(s), height() - kMargin - kLabelHeight));
        }
        for (const int identity : clusters) {
            painter.setPen(QPen(palette().color(QPalette::Base), 1.0));
            painter.setBrush(colourOf(identity));
            painter.drawRoundedRect(barRect(s, identity), 2.0, 2.0);
        }
        if (s != m_current && s % labelEvery != 0 && s != steps - 1) continue;
        QFont f = font();
        f.setBold(s == m_current);
        painter.setFont(f);
        painter.setPen(
            palette().color(s == m_current ? QPalette::Text : QPalette::PlaceholderText));
        const QString label = shortLabel(m_labels[s]);
        const double w = QFontMetricsF(f).horizontalAdvance(label);
        const double x = std::clamp(columnX(s) - w / 2, 0.0, width() - w);
        painter.drawText(QPointF(x, height() - kMargin / 2 - metrics.descent()), label);
    }
}

int ClusterTimeline::memberNear(QPointF at) const {
    // The member whose track passes closest to the point, within 4 pixels, at the nearest
    // built column (tracks are most apart there).
    int best = -1;
    double bestDistance = 4.0;
    for (std::size_t s = 0; s < m_identities.size(); ++s) {
        if (m_identities[s].empty()) continue;
        if (std::abs(columnX(static_cast<int>(s)) - at.x()) > kBarWidth) continue;
        for (std::size_t m = 0; m < m_slots[s].size(); ++m) {
            const double d = std::abs(slotY(m_slots[s][m]) - at.y());
            if (d < bestDistance) {
                bestDistance = d;
                best = static_cast<int>(m);
            }
        }
    }
    return best;
}

void ClusterTimeline::mousePressEvent(QMouseEvent* event) {
    for (int s = 0; s < static_cast<int>(m_identities.size()); ++s) {
        for (const int identity : m_identities[static_cast<std::size_t>(s)]) {
            if (barRect(s, identity).contains(event->position())) {
                emit membersClicked(membersAt(s, identity), event->modifiers());
                return;
            }
        }
    }
    emit membersClicked({}, event->modifiers());
}

void ClusterTimeline::mouseMoveEvent(QMouseEvent* event) {
    const int member = memberNear(event->position());
    m_selection->setHovered(member);
    if (member >= 0) {
        QToolTip::showText(event->globalPosition().toPoint(), m_selection->name(member), this);
    }
}

void ClusterTimeline::leaveEvent(QEvent* /*event*/) { m_selection->setHovered(-1); }

}  // namespace ensil::ui

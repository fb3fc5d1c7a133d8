#include "widgets/member_table_steps.h"

#include "gl/palette.h"

namespace ensil::ui {
namespace {
QColor colourOf(int identity) {
    const glm::vec3 c = gl::clusterColor(identity);
    return QColor::fromRgbF(c.r, c.g, c.b);
}
}  // namespace

void MemberTableSteps::setSteps(QStringList labels) {
    m_labels = std::move(labels);
    m_identities.assign(static_cast<std::size_t>(m_labels.size()), {});
    m_current = -1;
}

bool MemberTableSteps::setStepClusters(int step, std::vector<int> identities) {
    if (step < 0 || step >= stepCount()) return false;
    m_identities[static_cast<std::size_t>(step)] = std::move(identities);
    return true;
}

int MemberTableSteps::identityAt(int step, int member) const {
    if (step < 0 || step >= stepCount() || member < 0) return -1;
    const std::vector<int>& ids = m_identities[static_cast<std::size_t>(step)];
    return static_cast<std::size_t>(member) < ids.size() ? ids[static_cast<std::size_t>(member)]
                                                         : -1;
}

bool MemberTableSteps::movedAt(int step, int member) const {
    const int now = identityAt(step, member);
    if (now < 0) return false;
    for (int before = step - 1; before >= 0; --before) {
        if (m_identities[static_cast<std::size_t>(before)].empty()) continue;
        const int then = identityAt(before, member);
        return then >= 0 && then != now;
    }
    return false;
}

QString MemberTableSteps::shortLabel(int step) const {
    // As the strip labels its columns: without the year when every step shares it.
    const QString& label = m_labels[step];
    bool oneYear = true;
    for (const QString& l : m_labels) oneYear = oneYear && l.left(5) == m_labels.front().left(5);
    QString text =
        oneYear && label.size() > 5 && label[4] == QLatin1Char('-') ? label.mid(5) : label;
    return text.replace(QLatin1Char('T'), QLatin1Char(' '));
}

QVariant MemberTableSteps::data(int step, int member, const QString& memberName, int role,
                                int sortRole) const {
    const int identity = identityAt(step, member);
    if (role == sortRole) return identity < 0 ? QVariant() : QVariant(identity + 1);
    if (role == Qt::DisplayRole) return identity < 0 ? QVariant() : QVariant(identity + 1);
    if (role == Qt::DecorationRole && identity >= 0) return colourOf(identity);
    if (role == Qt::FontRole && movedAt(step, member)) {
        QFont bold;
        bold.setBold(true);
        return bold;
    }
    if (role == Qt::TextAlignmentRole) {
        return QVariant::fromValue(Qt::Alignment(Qt::AlignRight | Qt::AlignVCenter));
    }
    if (role == Qt::ToolTipRole) {
        if (m_identities[static_cast<std::size_t>(step)].empty()) {
            return QObject::tr("%1: not clustered yet").arg(m_labels[step]);
        }
        if (identity < 0)
            return QObject::tr("%1 at %2: no cluster").arg(memberName, m_labels[step]);
        QString tip =
            QObject::tr("%1 at %2: cluster %3").arg(memberName, m_labels[step]).arg(identity + 1);
        if (movedAt(step, member)) tip += QObject::tr(" (moved here from another cluster)");
        return tip;
    }
    return {};
}

QVariant MemberTableSteps::headerData(int step, int role) const {
    if (step < 0 || step >= stepCount()) return {};
    if (role == Qt::DisplayRole) return shortLabel(step);
    if (role == Qt::ToolTipRole) {
        return QObject::tr(
                   "Each member's cluster at %1, numbered and coloured as in the "
                   "Clusters over Time strip; bold: it moved there from another "
                   "cluster; empty: this step is not clustered yet")
            .arg(m_labels[step]);
    }
    if (role == Qt::FontRole && step == m_current) {
        // The step on screen.
        QFont bold;
        bold.setBold(true);
        return bold;
    }
    return {};
}

}  // namespace ensil::ui

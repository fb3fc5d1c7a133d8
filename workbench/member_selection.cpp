#include "workbench/member_selection.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>

#include "engine/session_scene.h"
#include "gl/palette.h"
#include "preprocessing/cluster_identity.h"
#include "session/member_appearance.h"

namespace ensil::workbench {
namespace {
constexpr double kUnknown = std::numeric_limits<double>::quiet_NaN();

double entry(const std::vector<double>& values, int member) {
    return member >= 0 && static_cast<std::size_t>(member) < values.size()
               ? values[static_cast<std::size_t>(member)]
               : kUnknown;
}

void requireLength(const std::vector<double>& values, qsizetype names, const char* what) {
    if (!values.empty() && static_cast<qsizetype>(values.size()) != names) {
        throw std::invalid_argument(std::string(what) + " has " + std::to_string(values.size()) +
                                    " values for " + std::to_string(names) + " members");
    }
}
void requireMember(int member, qsizetype names, const char* what) {
    if (member < 0 || member >= names) {
        throw std::invalid_argument(std::string(what) + " " + std::to_string(member) +
                                    " is not one of the " + std::to_string(names) + " members");
    }
}
}  // namespace

QString depthText(double depth) {
    if (std::isnan(depth)) return QStringLiteral("-");
    // C's %#.3g: QString::asprintf's own formatting drops a significant zero ("0.050").
    std::array<char, 32> text{};
    std::snprintf(text.data(), text.size(), "%#.3g", depth);
    return QString::fromLatin1(text.data());
}

MemberSelection::MemberSelection(session::SessionModel* session, QObject* parent)
    : QObject(parent), m_session(session) {
    connect(m_session, &session::SessionModel::changed, this, &MemberSelection::showSessionMembers);
}

MemberSelection::MemberSelection(QObject* parent)
    : MemberSelection(new session::SessionModel, parent) {
    m_session->setParent(this);
}

session::MemberFlags MemberSelection::flagsOfSession() const {
    return session::memberFlags(m_session->state(), m_labels, memberCount());
}

void MemberSelection::showSessionMembers(session::SessionParts parts) {
    using session::SessionPart;
    if (!(parts & (SessionPart::Visibility | SessionPart::Selection))) return;
    session::MemberFlags flags = flagsOfSession();
    const bool visibility = flags.visible != m_visible;
    const bool selection = flags.selected != m_selected;
    m_visible = std::move(flags.visible);
    m_selected = std::move(flags.selected);
    if (visibility) emit visibilityChanged();
    if (selection) emit selectionChanged();
}

void MemberSelection::writeVisible(const std::vector<bool>& visible) {
    std::vector<int> hidden;
    for (std::size_t m = 0; m < visible.size(); ++m) {
        if (!visible[m]) hidden.push_back(static_cast<int>(m));
    }
    m_session->update([&hidden](session::SessionState& s) {
        s.hiddenMembers = hidden;
        s.hiddenClusters.clear();  // resolved into their members
    });
}

void MemberSelection::writeSelected(const std::vector<bool>& selected) {
    std::vector<int> members;
    for (std::size_t m = 0; m < selected.size(); ++m) {
        if (selected[m]) members.push_back(static_cast<int>(m));
    }
    m_session->update([&members](session::SessionState& s) { s.selection = members; });
}

void MemberSelection::setMembers(MemberFigures figures) {
    requireLength(figures.distanceToMean, figures.names.size(), "the distance to the mean");
    requireLength(figures.meanOutlyingness, figures.names.size(), "the mean outlyingness");
    requireLength(figures.depth, figures.names.size(), "the depth");
    if (figures.median != -1) requireMember(figures.median, figures.names.size(), "the median");
    for (const int m : figures.outliers) requireMember(m, figures.names.size(), "the outlier");
    const bool sameMembers = figures.names == m_figures.names;
    // Other members: nothing of the last ones' stays hidden or selected.
    if (!sameMembers) {
        m_session->update([](session::SessionState& s) {
            s.hiddenMembers.clear();
            s.hiddenClusters.clear();
            s.selection.clear();
        });
    }
    emit membersAboutToBeReset();
    emit clustersAboutToChange();
    m_figures = std::move(figures);
    if (!sameMembers) {
        m_hovered = -1;
        m_tree = {};
        m_identities.clear();  // other members: colours start afresh
    }
    relabel(/*newTree=*/false, m_clusters);
    session::MemberFlags flags = flagsOfSession();
    m_visible = std::move(flags.visible);
    m_selected = std::move(flags.selected);
    emit clustersChanged();
    emit membersReset();
    if (!sameMembers) {
        emit visibilityChanged();
        emit selectionChanged();
        emit hoverChanged(m_hovered);
    }
}

void MemberSelection::setTree(prep::MergeTree tree) {
    if (tree.memberCount != 0 && tree.memberCount != memberCount()) {
        throw std::invalid_argument("the merge tree clusters " + std::to_string(tree.memberCount) +
                                    " members but there are " + std::to_string(memberCount()));
    }
    emit clustersAboutToChange();
    m_tree = std::move(tree);
    relabel(/*newTree=*/true, m_clusters);
    emit clustersChanged();
    // Hidden clusters (a project's, until resolved) hide other members under other clusters.
    showSessionMembers(session::SessionPart::Visibility);
}

void MemberSelection::setClusterCount(int k) {
    if (k < 1 || k == m_clusters) return;
    emit clustersAboutToChange();
    const int previous = std::clamp(m_clusters, 1, std::max(1, m_tree.memberCount));
    m_clusters = k;
    relabel(/*newTree=*/false, previous);
    emit clustersChanged();
    showSessionMembers(session::SessionPart::Visibility);
}

void MemberSelection::relabel(bool newTree, int previousK) {
    if (!isClustered()) {
        m_labels.clear();
        return;  // identities stay for the next tree of the same members
    }
    const std::vector<int> previous = prep::memberIdentities(m_labels, m_identities);
    m_clusters = std::clamp(m_clusters, 1, m_tree.memberCount);
    const std::vector<int> labels = prep::clusterLabels(m_tree, m_clusters);
    const bool known = !m_identities.empty() && previous.size() == labels.size();
    if (!known) {
        m_identities = prep::identitiesFromTree(m_tree, m_clusters);
    } else if (newTree) {
        m_identities = prep::matchIdentities(labels, m_clusters, previous);
    } else if (previousK != m_clusters) {
        m_identities = prep::followTree(m_tree, previousK, m_identities, m_clusters);
    }
    m_labels = labels;
}

std::vector<int> MemberSelection::memberClusterNumbers() const {
    if (!isClustered()) return {};
    std::vector<int> numbers;
    for (const int identity : prep::memberIdentities(m_labels, m_identities)) {
        numbers.push_back(identity + 1);
    }
    return numbers;
}

void MemberSelection::numberClustersAs(const std::vector<int>& numbers) {
    if (!isClustered() || numbers.size() != m_labels.size()) return;
    std::vector<int> identities;
    for (const int number : numbers) identities.push_back(number - 1);
    emit clustersAboutToChange();
    m_identities = prep::matchIdentities(m_labels, m_clusters, identities);
    emit clustersChanged();
}

double MemberSelection::distanceToMean(int member) const {
    return entry(m_figures.distanceToMean, member);
}

double MemberSelection::meanOutlyingness(int member) const {
    return entry(m_figures.meanOutlyingness, member);
}

double MemberSelection::depth(int member) const { return entry(m_figures.depth, member); }

bool MemberSelection::isMedian(int member) const {
    return valid(member) && member == m_figures.median;
}

bool MemberSelection::isOutlier(int member) const {
    return valid(member) && std::find(m_figures.outliers.begin(), m_figures.outliers.end(),
                                      member) != m_figures.outliers.end();
}

int MemberSelection::clusterOf(int member) const {
    return valid(member) && !m_labels.empty() ? m_labels[static_cast<std::size_t>(member)] : -1;
}

QList<int> MemberSelection::membersOfCluster(int cluster) const {
    QList<int> members;
    for (int m = 0; m < static_cast<int>(m_labels.size()); ++m) {
        if (m_labels[static_cast<std::size_t>(m)] == cluster) members << m;
    }
    return members;
}

int MemberSelection::identityOf(int cluster) const {
    return cluster >= 0 && static_cast<std::size_t>(cluster) < m_identities.size() &&
                   !m_labels.empty()
               ? m_identities[static_cast<std::size_t>(cluster)]
               : -1;
}

QColor MemberSelection::clusterColor(int cluster) const {
    const glm::vec3 c = gl::clusterColor(identityOf(cluster));
    return QColor::fromRgbF(c.r, c.g, c.b);
}

bool MemberSelection::isMemberVisible(int member) const {
    return valid(member) && m_visible[static_cast<std::size_t>(member)];
}

Qt::CheckState MemberSelection::clusterVisibility(int cluster) const {
    int shown = 0;
    int total = 0;
    for (std::size_t m = 0; m < m_labels.size(); ++m) {
        if (m_labels[m] != cluster) continue;
        ++total;
        if (m_visible[m]) ++shown;
    }
    if (total > 0 && shown == total) return Qt::Checked;
    return shown > 0 ? Qt::PartiallyChecked : Qt::Unchecked;
}

void MemberSelection::setMemberVisible(int member, bool visible) {
    if (!valid(member) || m_visible[static_cast<std::size_t>(member)] == visible) return;
    std::vector<bool> next = m_visible;
    next[static_cast<std::size_t>(member)] = visible;
    writeVisible(next);
}

void MemberSelection::setClusterVisible(int cluster, bool visible) {
    std::vector<bool> next = m_visible;
    for (std::size_t m = 0; m < m_labels.size(); ++m) {
        if (m_labels[m] == cluster) next[m] = visible;
    }
    if (next != m_visible) writeVisible(next);
}

void MemberSelection::soloCluster(int cluster) {
    if (cluster < 0 || cluster >= clusterCount()) return;
    std::vector<bool> visible(m_visible.size());
    for (std::size_t m = 0; m < m_labels.size(); ++m) visible[m] = m_labels[m] == cluster;
    if (visible != m_visible) writeVisible(visible);
}

void MemberSelection::showAll() {
    if (std::all_of(m_visible.begin(), m_visible.end(), [](bool v) { return v; })) return;
    writeVisible(std::vector<bool>(m_visible.size(), true));
}

bool MemberSelection::isSelected(int member) const {
    return valid(member) && m_selected[static_cast<std::size_t>(member)];
}

QList<int> MemberSelection::selectedMembers() const {
    QList<int> members;
    for (int m = 0; m < memberCount(); ++m) {
        if (m_selected[static_cast<std::size_t>(m)]) members << m;
    }
    return members;
}

int MemberSelection::selectedCount() const {
    return static_cast<int>(std::count(m_selected.begin(), m_selected.end(), true));
}

void MemberSelection::setSelection(const QList<int>& members) {
    std::vector<bool> selected(m_selected.size(), false);
    for (int m : members) {
        if (valid(m)) selected[static_cast<std::size_t>(m)] = true;
    }
    if (selected != m_selected) writeSelected(selected);
}

void MemberSelection::click(const QList<int>& members, Qt::KeyboardModifiers modifiers) {
    if (modifiers.testFlag(Qt::ControlModifier)) {
        QList<int> next = selectedMembers();
        for (int m : members) {
            if (!valid(m)) continue;
            if (isSelected(m)) {
                next.removeAll(m);
            } else {
                next << m;
            }
        }
        setSelection(next);
    } else if (modifiers.testFlag(Qt::ShiftModifier)) {
        setSelection(selectedMembers() + members);
    } else {
        setSelection(members);
    }
}

void MemberSelection::setHovered(int member) {
    const int next = valid(member) ? member : -1;
    if (next == m_hovered) return;
    m_hovered = next;
    emit hoverChanged(m_hovered);
}

std::vector<gl::MemberAppearance> MemberSelection::appearance() const {
    // As every picture of the session is coloured (ensil render's too).
    return engine::sceneAppearance(m_session->state(), m_labels, m_identities, memberCount());
}

}  // namespace ensil::workbench

// The one shared selection model of the workbench: which members there are (names and per-member
// figures), how they are clustered (the merge tree and the number of clusters), which are
// visible, which are selected and which one the pointer is over. Every panel and the 3D view
// observe it and change it through it; no view calls another. GUI thread only; owned by the
// main window (or a test), panels keep a pointer.
//
// Which members are hidden and selected is the session's (session::SessionState's
// hiddenMembers, hiddenClusters and selection): this model reads them from the session model it
// is given, writes its edits there, and says so when they change, whoever changed them (a panel,
// undo, a project). It keeps only what is derived from them (each member's flags under the
// current clusters) or transient (the hover). Visibility is per member; a cluster's is derived
// from its members' (all, some or none visible), so hiding a cluster hides its members.
#pragma once

#include <QColor>
#include <QList>
#include <QObject>
#include <QStringList>
#include <vector>

#include "gl/render_settings.h"
#include "preprocessing/clustering.h"
#include "session/member_appearance.h"
#include "session/session_model.h"

namespace ensil::workbench {

// What the member table shows besides the cluster; one entry per member. Empty vectors mean
// "not known yet" (the figures come with each isovalue).
struct MemberFigures {
    QStringList names;
    std::vector<double> distanceToMean;    // NaN when not known
    std::vector<double> meanOutlyingness;  // NaN when not known (or no isosurface)
    // The contour boxplot (preprocessing/inclusion_depth.h): each member's inclusion depth in
    // [0, 1] (1 = most central, 0 = no surface), the median (the deepest member; -1 when not
    // known) and the outliers (depth below the lower fence), as member indices.
    std::vector<double> depth;
    int median = -1;
    std::vector<int> outliers;
};

// A depth in [0, 1] as the panels show it: 3 significant digits, trailing zeros kept so a
// column reads evenly ("0.100", "1.00"); "-" when not known (NaN).
[[nodiscard]] QString depthText(double depth);

class MemberSelection : public QObject {
    Q_OBJECT
public:
    // Shows and edits the visibility and selection of `session`, which outlives it.
    explicit MemberSelection(session::SessionModel* session, QObject* parent = nullptr);
    // With a session of its own (a panel tested alone).
    explicit MemberSelection(QObject* parent = nullptr);

    // New members. Selection, visibility and hover survive when the names are the same (a new
    // isovalue of the same ensemble); otherwise everything starts afresh. The merge tree is
    // dropped unless its member count still fits. Throws std::invalid_argument when the
    // figures' lengths differ from the names', or a median or outlier is not a member.
    void setMembers(MemberFigures figures);
    // The merge tree of the current members (memberCount == memberCount(), or 0 for "not
    // clustered"). Keeps the number of clusters, clamped to 1..N. Throws std::invalid_argument
    // for a tree of another size.
    void setTree(prep::MergeTree tree);
    void setClusterCount(int k);

    [[nodiscard]] int memberCount() const { return static_cast<int>(m_figures.names.size()); }
    [[nodiscard]] QString name(int member) const { return m_figures.names.value(member); }
    [[nodiscard]] double distanceToMean(int member) const;
    [[nodiscard]] double meanOutlyingness(int member) const;
    // The contour boxplot's figures: the inclusion depth (NaN when not known), whether the member
    // is its median (the deepest) or one of its outliers, and the median (-1 when not known).
    [[nodiscard]] double depth(int member) const;
    [[nodiscard]] int medianMember() const { return m_figures.median; }
    [[nodiscard]] bool isMedian(int member) const;
    [[nodiscard]] bool isOutlier(int member) const;
    // Whether any contour boxplot is known (a median or depths), so panels can say what marks
    // mean only when there are any.
    [[nodiscard]] bool hasBoxplot() const {
        return m_figures.median >= 0 || !m_figures.depth.empty();
    }

    [[nodiscard]] const prep::MergeTree& tree() const { return m_tree; }
    [[nodiscard]] bool isClustered() const { return m_tree.memberCount > 0; }
    // The number of clusters shown (0 when not clustered).
    [[nodiscard]] int clusterCount() const { return isClustered() ? m_clusters : 0; }
    // The number the user asked for, kept while there is no tree.
    [[nodiscard]] int requestedClusterCount() const { return m_clusters; }
    // Cluster label per member (0..k-1, in dendrogram order); empty when not clustered.
    [[nodiscard]] const std::vector<int>& labels() const { return m_labels; }
    [[nodiscard]] int clusterOf(int member) const;  // -1 when not clustered
    [[nodiscard]] QList<int> membersOfCluster(int cluster) const;
    // A cluster's stable identity (preprocessing/cluster_identity.h): its colour, and its
    // number (identity + 1) in the legend, the cluster list and tooltips. -1 for -1.
    [[nodiscard]] int identityOf(int cluster) const;
    [[nodiscard]] int clusterNumber(int cluster) const { return identityOf(cluster) + 1; }
    [[nodiscard]] QColor clusterColor(int cluster) const;  // gray for -1
    // Each member's cluster number (clusterNumber), empty when not clustered: what a project
    // keeps. Numbering the clusters as `numbers` did (a project's, per member) matches the
    // current clusters to them by shared members, as after a new tree; ignored unless clustered
    // and one number per member.
    [[nodiscard]] std::vector<int> memberClusterNumbers() const;
    void numberClustersAs(const std::vector<int>& numbers);
    [[nodiscard]] QColor memberColor(int member) const { return clusterColor(clusterOf(member)); }

    [[nodiscard]] bool isMemberVisible(int member) const;
    // Qt::Checked when all its members are visible, PartiallyChecked when some, else Unchecked.
    [[nodiscard]] Qt::CheckState clusterVisibility(int cluster) const;
    void setMemberVisible(int member, bool visible);
    void setClusterVisible(int cluster, bool visible);
    void soloCluster(int cluster);  // only this cluster's members visible
    void showAll();

    [[nodiscard]] bool isSelected(int member) const;
    [[nodiscard]] QList<int> selectedMembers() const;  // ascending
    [[nodiscard]] int selectedCount() const;
    void setSelection(const QList<int>& members);
    void clearSelection() { setSelection({}); }
    // A click on members (one, a branch, a cluster, a brushed set): plain replaces the
    // selection, Shift adds to it, Ctrl toggles each member. A plain click on nothing clears.
    void click(const QList<int>& members, Qt::KeyboardModifiers modifiers);

    [[nodiscard]] int hovered() const { return m_hovered; }
    void setHovered(int member);  // -1 for none

    // What the renderer needs per member: cluster colour, visibility, selection, cluster.
    [[nodiscard]] std::vector<gl::MemberAppearance> appearance() const;

signals:
    void membersAboutToBeReset();
    void membersReset();
    void clustersAboutToChange();
    void clustersChanged();
    void visibilityChanged();
    void selectionChanged();
    void hoverChanged(int member);

private:
    [[nodiscard]] bool valid(int member) const { return member >= 0 && member < memberCount(); }
    // The members' flags from the session under the current clusters; emits what changed.
    void showSessionMembers(session::SessionParts parts);
    [[nodiscard]] session::MemberFlags flagsOfSession() const;
    // Writes these flags into the session: hidden members by index (hidden clusters resolved
    // into their members), the selection ascending.
    void writeVisible(const std::vector<bool>& visible);
    void writeSelected(const std::vector<bool>& selected);
    // Recomputes the labels of the cut, and the identities: matched to the previous ones
    // after a new tree, followed along the tree after a new k, from the tree when new.
    void relabel(bool newTree, int previousK);

    MemberFigures m_figures;
    prep::MergeTree m_tree;
    int m_clusters = 5;
    std::vector<int> m_labels;
    std::vector<int> m_identities;  // per label
    session::SessionModel* m_session;
    // Derived from the session: per member, for the current members and clusters.
    std::vector<bool> m_visible;
    std::vector<bool> m_selected;
    int m_hovered = -1;  // transient: not part of the session
};

}  // namespace ensil::workbench

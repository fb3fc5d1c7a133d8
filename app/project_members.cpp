#include "app/project_members.h"

namespace ensil::app {

void applyProjectMembers(const Project& project, ui::MemberSelection& selection) {
    for (const int m : project.hiddenMembers) selection.setMemberVisible(m, false);
    for (const int c : project.hiddenClusters) {
        if (c < selection.clusterCount()) selection.setClusterVisible(c, false);
    }
    selection.setSelection(QList<int>(project.selection.begin(), project.selection.end()));
}

}  // namespace ensil::app

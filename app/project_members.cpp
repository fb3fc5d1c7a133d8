#include "app/project_members.h"

#include "widgets/session/member_appearance.h"

namespace ensil::app {

void applyProjectMembers(const session::SessionState& state, ui::MemberSelection& selection) {
    const session::MemberFlags flags =
        session::memberFlags(state, selection.labels(), selection.memberCount());
    QList<int> selected;
    for (int m = 0; m < selection.memberCount(); ++m) {
        selection.setMemberVisible(m, flags.visible[static_cast<std::size_t>(m)]);
        if (flags.selected[static_cast<std::size_t>(m)]) selected << m;
    }
    selection.setSelection(selected);
}

}  // namespace ensil::app

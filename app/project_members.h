// A session's hidden members, hidden clusters and selection, applied to the workbench's shared
// selection model. It resolves them with session::memberFlags, as headless rendering does, so a
// project looks the same in both. GUI thread.
#pragma once

#include "widgets/member_selection.h"
#include "widgets/session/session_state.h"

namespace ensil::app {

// `selection` must already hold the session's members and merge tree (clusters are hidden by
// their members).
void applyProjectMembers(const session::SessionState& state, ui::MemberSelection& selection);

}  // namespace ensil::app

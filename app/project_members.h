// A project's hidden members, hidden clusters and selection, applied to the shared selection
// model. The workbench and `ensil render PROJECT.ensil` both go through this and then draw
// ui::MemberSelection::appearance(), so a project looks the same in both. GUI thread.
#pragma once

#include "app/project.h"
#include "widgets/member_selection.h"

namespace ensil::app {

// `selection` must already hold the project's members and merge tree (clusters are hidden by
// their members).
void applyProjectMembers(const Project& project, ui::MemberSelection& selection);

}  // namespace ensil::app

// How each member is drawn in a project: coloured by its cluster, hidden when the project hides
// it or its cluster, solid when selected. The workbench and `ensil render` both draw projects
// through this, so a project looks the same in both. Any thread.
#pragma once

#include <vector>

#include "app/project.h"
#include "gl/render_settings.h"

namespace ensil::app {

std::vector<gl::MemberAppearance> memberAppearance(const std::vector<int>& labels,
                                                   const Project& project);

}  // namespace ensil::app

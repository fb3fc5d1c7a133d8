// How each member is drawn, from the session alone: its cluster colour, whether it is visible
// and whether it is selected. The workbench's shared selection (workbench::MemberSelection) and
// headless rendering both go through these functions, so a project looks the same in both.
// Pure functions; any thread.
#pragma once

#include <vector>

#include "gl/render_settings.h"
#include "session/session_state.h"

namespace ensil::session {

// Per member: visible and selected.
struct MemberFlags {
    std::vector<bool> visible;
    std::vector<bool> selected;
};

// The session's hidden members, hidden clusters (by `labels`, one cluster label per member or
// empty when not clustered) and selection, for `memberCount` members. Indices out of range are
// ignored: a project may name members of a larger ensemble.
MemberFlags memberFlags(const SessionState& state, const std::vector<int>& labels, int memberCount);

// What the renderer needs per member; `labels` as above (-1 or empty: gray, not clustered),
// `identities` the stable identity of each label (preprocessing/cluster_identity.h): its
// colour, and the cluster number picking and the legend report.
std::vector<gl::MemberAppearance> memberAppearance(const std::vector<int>& labels,
                                                   const std::vector<int>& identities,
                                                   const MemberFlags& flags);

}  // namespace ensil::session

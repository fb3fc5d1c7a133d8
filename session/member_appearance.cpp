#include "session/member_appearance.h"

#include <algorithm>

#include "gl/palette.h"

namespace ensil::session {

MemberFlags memberFlags(const SessionState& state, const std::vector<int>& labels,
                        int memberCount) {
    const auto n = static_cast<std::size_t>(std::max(memberCount, 0));
    MemberFlags flags{std::vector<bool>(n, true), std::vector<bool>(n, false)};
    const auto valid = [n](int m) { return m >= 0 && static_cast<std::size_t>(m) < n; };
    for (const int m : state.hiddenMembers) {
        if (valid(m)) flags.visible[static_cast<std::size_t>(m)] = false;
    }
    for (const int c : state.hiddenClusters) {
        for (std::size_t m = 0; m < labels.size() && m < n; ++m) {
            if (labels[m] == c) flags.visible[m] = false;
        }
    }
    for (const int m : state.selection) {
        if (valid(m)) flags.selected[static_cast<std::size_t>(m)] = true;
    }
    return flags;
}

std::vector<gl::MemberAppearance> memberAppearance(const std::vector<int>& labels,
                                                   const std::vector<int>& identities,
                                                   const MemberFlags& flags) {
    std::vector<gl::MemberAppearance> look(flags.visible.size());
    for (std::size_t m = 0; m < look.size(); ++m) {
        gl::MemberAppearance& a = look[m];
        const int label = m < labels.size() ? labels[m] : -1;
        const int identity = label >= 0 && static_cast<std::size_t>(label) < identities.size()
                                 ? identities[static_cast<std::size_t>(label)]
                                 : -1;
        a.color = gl::clusterColor(identity);
        a.cluster = identity;
        a.visible = flags.visible[m];
        a.selected = m < flags.selected.size() && flags.selected[m];
    }
    return look;
}

}  // namespace ensil::session

#include "app/member_appearance.h"

#include <algorithm>

#include "gl/palette.h"

namespace ensil::app {

std::vector<gl::MemberAppearance> memberAppearance(const std::vector<int>& labels,
                                                   const Project& project) {
    std::vector<gl::MemberAppearance> look = gl::clusterAppearance(labels);
    const auto contains = [](const std::vector<int>& list, int value) {
        return std::find(list.begin(), list.end(), value) != list.end();
    };
    for (std::size_t m = 0; m < look.size(); ++m) {
        const int member = static_cast<int>(m);
        look[m].visible = !contains(project.hiddenMembers, member) &&
                          !contains(project.hiddenClusters, look[m].cluster);
        look[m].selected = contains(project.selection, member);
    }
    return look;
}

}  // namespace ensil::app

// A qualitative palette for clusters, safe for colour-blind viewers (Okabe & Ito 2008), with
// black replaced by light gray because the view's background is dark.
#pragma once

#include <array>
#include <glm/vec3.hpp>
#include <vector>

#include "gl/render_settings.h"

namespace ensil::gl {

inline constexpr std::array<glm::vec3, 8> kClusterPalette{{
    {0.902F, 0.624F, 0.000F},  // orange
    {0.337F, 0.706F, 0.914F},  // sky blue
    {0.000F, 0.620F, 0.451F},  // bluish green
    {0.941F, 0.894F, 0.259F},  // yellow
    {0.000F, 0.447F, 0.698F},  // blue
    {0.835F, 0.369F, 0.000F},  // vermillion
    {0.800F, 0.475F, 0.655F},  // reddish purple
    {0.733F, 0.733F, 0.733F},  // light gray
}};

inline glm::vec3 clusterColor(int cluster) {
    return kClusterPalette[static_cast<std::size_t>(cluster) % kClusterPalette.size()];
}

// Every member visible, coloured by its cluster label.
inline std::vector<MemberAppearance> clusterAppearance(const std::vector<int>& labels) {
    std::vector<MemberAppearance> look(labels.size());
    for (std::size_t m = 0; m < labels.size(); ++m) {
        look[m].color = clusterColor(labels[m]);
        look[m].cluster = labels[m];
    }
    return look;
}

inline constexpr glm::vec3 kMeanSurfaceColor{0.62F, 0.62F, 0.62F};

}  // namespace ensil::gl

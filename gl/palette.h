// A qualitative palette of 12 colours for clusters: the seven colours of Okabe & Ito (2008),
// safe for colour-blind viewers, then five light ones of Paul Tol's schemes that stay apart
// from them as thin lines on a dark background. None is near the mean's gray or the gray of
// members that are not clustered. Colour i belongs to the cluster whose stable identity is i
// (preprocessing/cluster_identity.h); beyond 12 clusters, one "other" colour.
#pragma once

#include <array>
#include <glm/common.hpp>
#include <glm/vec3.hpp>
#include <vector>

#include "gl/render_settings.h"

namespace ensil::gl {

inline constexpr std::array<glm::vec3, 12> kClusterPalette{{
    {0.902F, 0.624F, 0.000F},  // orange
    {0.337F, 0.706F, 0.914F},  // sky blue
    {0.000F, 0.620F, 0.451F},  // bluish green
    {0.941F, 0.894F, 0.259F},  // yellow
    {0.000F, 0.447F, 0.698F},  // blue
    {0.835F, 0.369F, 0.000F},  // vermillion
    {0.800F, 0.475F, 0.655F},  // reddish purple
    {1.000F, 0.667F, 0.733F},  // pink (Tol light)
    {0.267F, 0.733F, 0.600F},  // mint (Tol light)
    {0.733F, 0.800F, 0.200F},  // pear (Tol light)
    {0.600F, 0.867F, 1.000F},  // light cyan (Tol light)
    {0.667F, 0.267F, 0.600F},  // purple (Tol muted)
}};

// The floor map's colour scale: a polynomial fit of matplotlib's 'viridis' (perceptually
// uniform, colour-blind safe), c0 + t (c1 + t (c2 + ...)). The floor shader takes these as
// uniforms and the colour bar uses viridis() below, so both show the same colours.
inline constexpr std::array<glm::vec3, 7> kViridisCoefficients{{
    {0.2777F, 0.0054F, 0.3341F},
    {0.1051F, 1.4046F, 1.3846F},
    {-0.3309F, 0.2148F, 0.0951F},
    {-4.6342F, -5.7991F, -19.3324F},
    {6.2283F, 14.1799F, 56.6906F},
    {4.7764F, -13.7451F, -65.3530F},
    {-5.4355F, 4.6459F, 26.3124F},
}};

inline glm::vec3 viridis(float t) {
    glm::vec3 c = kViridisCoefficients.back();
    for (std::size_t i = kViridisCoefficients.size() - 1; i-- > 0;) {
        c = kViridisCoefficients[i] + t * c;
    }
    return c;
}

// Members that are not clustered (before the first clustering).
inline constexpr glm::vec3 kUnclusteredColor{0.733F, 0.733F, 0.733F};

// Clusters beyond the palette's 12 colours (the later, smaller splits, since a split leaves
// its colour on the larger part) share this one, and the legend lists them as one entry
// ("Other clusters"), rather than repeating colours that would then mean two clusters. A
// muted violet-gray, apart from the palette, the mean's gray and the unclustered gray.
inline constexpr glm::vec3 kOtherClustersColor{0.42F, 0.40F, 0.52F};

// The colour of a cluster identity; kUnclusteredColor for -1, kOtherClustersColor beyond the
// palette.
inline glm::vec3 clusterColor(int identity) {
    if (identity < 0) return kUnclusteredColor;
    if (static_cast<std::size_t>(identity) >= kClusterPalette.size()) return kOtherClustersColor;
    return kClusterPalette[static_cast<std::size_t>(identity)];
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

// A member that steps back (the others selected, or the contour boxplot's band shown): its
// colour most of the way to the background. The renderer draws it so and the legend shows it so.
inline constexpr float kSteppedBack = 0.6F;
inline glm::vec3 steppedBack(const glm::vec3& colour, const glm::vec3& background) {
    return glm::mix(colour, background, kSteppedBack);
}

}  // namespace ensil::gl

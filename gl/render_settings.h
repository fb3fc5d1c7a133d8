// How the ensemble is drawn: the mode, silhouette thickness, density-based removal, the mean
// surface, and each member's colour, visibility and selection. A value type; GUI thread.
#pragma once

#include <glm/vec3.hpp>
#include <vector>

namespace ensil::gl {

// OpaqueSurfaces draws every member as a solid lit isosurface (a reference; occludes).
enum class RenderMode { ShadedSilhouettes, Spaghetti, Surfaces, OpaqueSurfaces };

struct RenderSettings {
    RenderMode mode = RenderMode::ShadedSilhouettes;
    float thickness = 0.006F;   // tau, in display units (the data box is about 1 wide)
    float surfaceAlpha = 0.2F;  // for RenderMode::Surfaces
    bool showMean = true;       // the mean member as a solid gray surface
    bool removal = false;       // density-based silhouette removal (algorithms.md section 7)
    float removalMin = 0.0F;    // o*_min, in the variable's units squared
    float removalMax = 1.0F;    // o*_max
    int groupSize = 4;          // s_G
};

struct MemberAppearance {
    glm::vec3 color{0.8F};
    bool visible = true;
    bool selected = false;  // drawn as a solid lit isosurface
};

}  // namespace ensil::gl

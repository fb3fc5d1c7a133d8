// The context surfaces (preprocessing/context_surfaces.h) of three concentric spheres: their
// places follow from the definitions by hand, so a surface built from the wrong field (or at
// the wrong level) lands on another radius.
#include "preprocessing/context_surfaces.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "fixtures.h"
#include "preprocessing/column_maximum.h"
#include "preprocessing/ensemble_statistics.h"

using namespace ensil;

namespace {
// Member i is |x - c| - o_i on a 32^3 grid, c = (15.5, 15.5, 15.5), o = (-2, -1, 4): at c = 8
// its surface is the sphere of radius 6, 7 or 12, and its inside set {f > 8} the points
// outside that sphere. The sets nest (radius 12's inside the others'), so:
// - member 1 (radius 7) is the deepest: it contains member 2's set and lies in member 0's;
// - the band is members 1 and 0 (member 0 loses only the thin shell 6..7 in member 1, member 2
//   the thick shell 7..12), so its inner surface is radius 7 and its outer one radius 6;
// - P(f > 8) is 1/3 between radii 6 and 7 and 2/3 between 7 and 12: its 0.5 surface is
//   radius 7, where the members' median (member 1's value everywhere) crosses 8.
constexpr float kOffsets[] = {-2.0F, -1.0F, 4.0F};
const glm::vec3 kCentre(15.5F);

data::Ensemble nestedSpheres() {
    return test::analyticEnsemble(3, 32, 32, 32, [](auto m, auto i, auto j, auto k) {
        return glm::length(glm::vec3(i, j, k) - kCentre) - kOffsets[m];
    });
}

// The smallest and largest distance of a mesh's vertices from the centre, in grid cells.
std::pair<float, float> radii(const data::PackedMesh& mesh) {
    float lo = 1e9F, hi = 0.0F;
    for (const data::PackedVertex& v : mesh.vertices) {
        const glm::vec3 q(v.position[0], v.position[1], v.position[2]);
        const glm::vec3 p = mesh.boundsMin + q / 65535.0F * (mesh.boundsMax - mesh.boundsMin);
        const float r = glm::length(p - kCentre);
        lo = std::min(lo, r);
        hi = std::max(hi, r);
    }
    return {lo, hi};
}
}  // namespace

TEST(ContextSurfaces, LieWhereTheDefinitionsPutThemOnNestedSpheres) {
    const data::Ensemble e = nestedSpheres();
    prep::PipelineOptions options;
    options.isovalue = 8.0F;
    const prep::ContextSurfaces s =
        prep::buildContextSurfaces(e, data::DisplayFrame(e.grid, 1.0F), options);
    EXPECT_EQ(s.boxplot.median, 1u);
    EXPECT_EQ(s.boxplot.bandMembers, (std::vector<std::size_t>{1, 0}));
    // Each surface is that of a field interpolated as the members' own surfaces are (the
    // members' median; the band members' lowest and highest values): on the sphere, to within
    // the interpolation's error. The 0.5 surface of P(f > c), a step field, or of an inside /
    // outside indicator would be off by up to three quarters of a cell.
    constexpr float kInterpolated = 0.1F;
    for (const auto& [name, mesh, radius] : {std::tuple{"probability", &s.probability, 7.0F},
                                             std::tuple{"band inner", &s.bandInner, 7.0F},
                                             std::tuple{"band outer", &s.bandOuter, 6.0F}}) {
        SCOPED_TRACE(name);
        ASSERT_FALSE(mesh->vertices.empty());
        const auto [lo, hi] = radii(*mesh);
        EXPECT_GT(lo, radius - kInterpolated);
        EXPECT_LT(hi, radius + kInterpolated);
    }

    // The floor's column maximum of P(f > 8): of the exceedance the statistics give.
    const prep::EnsembleStatistics statistics = prep::computeEnsembleStatistics(e, 8.0F);
    EXPECT_EQ(s.exceedanceColumnMaximum,
              prep::computeColumnMaximum(e.grid, {"P", statistics.exceedance}));
    ASSERT_EQ(s.exceedanceColumnMaximum.size(), 32u * 32u);

    data::MeshSet set;
    prep::addContextSurfaces(set, s);
    EXPECT_EQ(set.median, 1);
    EXPECT_EQ(set.probability.vertices.size(), s.probability.vertices.size());
    EXPECT_EQ(set.bandOuter.indices, s.bandOuter.indices);
}

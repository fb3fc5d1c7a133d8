#include "preprocessing/preview_meshes.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "fixtures.h"
#include "preprocessing/marching_cubes.h"
#include "preprocessing/mesh_packing.h"

using namespace ensil;

namespace {
// A sphere of radius 12 + m (member m, at isovalue 12) whose centre lies near the box's bottom and
// its x = 99 face, so the box cuts it on both.
const glm::vec3 kSphereCentre{92.0F, 50.2F, 3.0F};
data::Ensemble cutSpheres(std::size_t members) {
    return test::analyticEnsemble(members, 100, 100, 20, [](auto m, auto i, auto j, auto k) {
        return glm::length(glm::vec3(i, j, k) - kSphereCentre) - static_cast<float>(m);
    });
}
}  // namespace

TEST(PreviewSampling, KeepsEachAxisEndsAndShortAxesWholeWithinTheBudget) {
    const data::Grid grid = cutSpheres(1).grid;
    const prep::PreviewSampling s = prep::previewSampling(grid, 65536);
    EXPECT_EQ(s.stride, 2);  // 100 x 100 x 20 is 200,000 points; 51 x 51 x 20 fits
    EXPECT_LE(s.pointCount(), 65536u);
    for (int a = 0; a < 2; ++a) {
        const auto& idx = s.indices[static_cast<std::size_t>(a)];
        EXPECT_EQ(idx.front(), 0u);
        EXPECT_EQ(idx.back(), 99u) << "the last point of axis " << a << " is kept";
        EXPECT_EQ(idx[idx.size() - 2], 98u);
    }
    EXPECT_EQ(s.indices[2].size(), 20u) << "20 levels are kept whole";
    EXPECT_EQ(prep::previewSampling(grid, 1u << 20).stride, 1) << "small grids are not sampled";
}

TEST(PreviewMeshes, LieOnTheSurfaceMeetTheBoxFacesAndHaveFewerTriangles) {
    const data::Ensemble e = cutSpheres(2);
    const prep::EnsembleMoments moments = prep::computeEnsembleMoments(e);
    const prep::IsovalueMeshes preview =
        prep::buildPreviewMeshes(e, moments, data::DisplayFrame(e.grid, 1.0F), 12.0F);
    ASSERT_EQ(preview.members.size(), 2u);
    EXPECT_FALSE(preview.mean.vertices.empty());
    const std::size_t full =
        prep::extractIsosurface(e.grid, e.members[0].values, 12.0F).triangleCount();
    for (std::size_t m = 0; m < 2; ++m) {
        const data::PackedMesh& mesh = preview.members[m];
        ASSERT_FALSE(mesh.vertices.empty());
        EXPECT_LT(mesh.indices.size() / 3, full / 4) << "member " << m;
        const float radius = 12.0F + static_cast<float>(m);
        int onFarFace = 0;
        for (const data::PackedVertex& v : mesh.vertices) {
            const glm::vec3 p = prep::unpackPosition(mesh, v);
            // In the full grid's cells: within the preview's decimation bound (1 cell) and the
            // packing's rounding.
            ASSERT_NEAR(glm::length(p - kSphereCentre), radius, 1.05F) << "member " << m;
            if (std::abs(p.x - 99.0F) < 1e-2F) ++onFarFace;
        }
        EXPECT_GT(onFarFace, 4) << "member " << m << " meets the x = 99 face, as in full";
    }
}

TEST(PreviewMeshes, AtFullSamplingWithoutDecimationTheyAreTheFullSurfaces) {
    const data::Ensemble e = cutSpheres(1);
    const prep::EnsembleMoments moments = prep::computeEnsembleMoments(e);
    const prep::IsovalueMeshes preview =
        prep::buildPreviewMeshes(e, moments, data::DisplayFrame(e.grid, 1.0F), 12.0F,
                                 {.pointBudget = e.grid.pointCount(), .maxErrorCells = 0.0F});
    const data::TriangleMesh full = prep::extractIsosurface(e.grid, e.members[0].values, 12.0F);
    EXPECT_EQ(preview.members[0].indices.size(), full.indices.size());
    EXPECT_EQ(preview.members[0].vertices.size(), full.positions.size());
}

TEST(PreviewMeshes, CancelStopsThem) {
    const data::Ensemble e = cutSpheres(3);
    const prep::EnsembleMoments moments = prep::computeEnsembleMoments(e);
    std::stop_source stop;
    stop.request_stop();
    EXPECT_THROW(prep::buildPreviewMeshes(e, moments, data::DisplayFrame(e.grid, 1.0F), 12.0F, {},
                                          stop.get_token()),
                 data::Cancelled);
}

#include "preprocessing/isosurface_pipeline.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "fixtures.h"
#include "mesh_checks.h"
#include "preprocessing/decimation.h"
#include "preprocessing/marching_cubes.h"
#include "tests/benchmarks/hausdorff.h"

using namespace ensil;

namespace {
// Spheres of radius 8 + m around a fixed centre: member m's surface is known exactly.
data::Ensemble spheres(std::size_t members) {
    return test::analyticEnsemble(members, 40, 40, 40, [](auto m, auto i, auto j, auto k) {
        return glm::length(glm::vec3(i, j, k) - glm::vec3(19.6F, 20.2F, 19.8F)) -
               static_cast<float>(m);
    });
}
}  // namespace

TEST(Decimation, StaysWithinItsErrorBoundAndKeepsTheSphereClosed) {
    const auto e = spheres(1);
    const data::TriangleMesh full = prep::extractIsosurface(e.grid, e.members[0].values, 12.0F);
    const prep::DecimationResult d = prep::decimateMesh(full, 0.25F);
    EXPECT_LT(d.mesh.triangleCount(), full.triangleCount() / 4) << "a smooth sphere decimates well";
    EXPECT_LE(d.errorCells, 0.25F + 1e-4F);
    for (const glm::vec3& p : d.mesh.positions) {
        // Kept vertices are original vertices: on the sphere within marching cubes' own error.
        ASSERT_NEAR(glm::length(p - glm::vec3(19.6F, 20.2F, 19.8F)), 12.0F, 0.05F);
    }
    const test::Topology topo = test::topologyOf(d.mesh);
    EXPECT_EQ(topo.boundaryEdges, 0u);
    EXPECT_EQ(topo.inconsistentEdges, 0u);
    EXPECT_EQ(topo.euler, 2);
    // Area within 3 % of the sphere's: the surface did not collapse.
    EXPECT_NEAR(test::areaOf(d.mesh), 4 * 3.14159265 * 144, 0.03 * 4 * 3.14159265 * 144);
}

TEST(Decimation, TheFullSurfaceStaysWithinTwiceTheBoundOfTheDecimatedOne) {
    // The bound holds meshoptimizer's own estimate, a root-mean-square distance to the planes
    // merged into a vertex, not the largest distance between the surfaces: on this sphere the
    // farthest full-resolution vertex lies about 1.8 times the bound from the decimated surface
    // (0.46 cells at 0.25, 0.08 at 0.05; METHODS.md section 2), the mean one within it.
    const auto e = spheres(1);
    const data::TriangleMesh full = prep::extractIsosurface(e.grid, e.members[0].values, 12.0F);
    for (const float bound : {0.25F, 0.05F}) {
        const SurfaceDistance d = distanceToSurface(full, prep::decimateMesh(full, bound).mesh);
        EXPECT_LE(d.maximum, 2.0 * bound) << "bound " << bound;
        EXPECT_LE(d.mean, bound) << "bound " << bound;
    }
}

TEST(Decimation, ZeroErrorKeepsEveryTriangle) {
    const auto e = spheres(1);
    const data::TriangleMesh full = prep::extractIsosurface(e.grid, e.members[0].values, 12.0F);
    const prep::DecimationResult d = prep::decimateMesh(full, 0.0F);
    EXPECT_EQ(d.mesh.triangleCount(), full.triangleCount());
    EXPECT_EQ(d.mesh.vertexCount(), full.vertexCount());
}

TEST(IsosurfacePipeline, MeshesEveryMemberAndTheMean) {
    const auto e = spheres(4);  // spheres of radius 12, 13, 14, 15 at isovalue 12
    const prep::EnsembleMoments moments = prep::computeEnsembleMoments(e);
    const data::DisplayFrame frame(e.grid, 1.0F);
    prep::PipelineOptions options;
    options.isovalue = 12.0F;
    const prep::IsovalueMeshes out = prep::buildIsovalueMeshes(e, moments, frame, options);
    ASSERT_EQ(out.members.size(), 4u);
    for (std::size_t m = 0; m < 4; ++m) {
        ASSERT_FALSE(out.members[m].vertices.empty());
        // Radius 12 + m in cells: the packed bounds span the sphere's diameter.
        const float extent = out.members[m].boundsMax.x - out.members[m].boundsMin.x;
        EXPECT_NEAR(extent, 2.0F * (12.0F + static_cast<float>(m)), 1.0F) << "member " << m;
    }
    // The mean of radii 12..15 is a sphere of radius 13.5.
    EXPECT_NEAR(out.mean.boundsMax.x - out.mean.boundsMin.x, 27.0F, 1.0F);
    EXPECT_LT(out.triangles, out.trianglesExtracted);
    EXPECT_EQ(out.gpuBytes(), [&] {
        std::size_t b = out.mean.gpuBytes();
        for (const auto& m : out.members) b += m.gpuBytes();
        return b;
    }());
    // Members farther from the others are more outlying: member 0 (radius 12) vs member 1.
    const auto meanOutlyingness = [](const data::PackedMesh& m) {
        double s = 0;
        for (const auto& v : m.vertices)
            s += prep::unpackHalf(v.outlyingness) * m.outlyingnessScale;
        return s / static_cast<double>(m.vertices.size());
    };
    EXPECT_GT(meanOutlyingness(out.members[0]), meanOutlyingness(out.members[1]));
}

TEST(IsosurfacePipeline, CancelStopsIt) {
    const auto e = spheres(3);
    const prep::EnsembleMoments moments = prep::computeEnsembleMoments(e);
    prep::PipelineOptions options;
    options.isovalue = 12.0F;
    std::stop_source stop;
    EXPECT_THROW(prep::buildIsovalueMeshes(e, moments, data::DisplayFrame(e.grid, 1.0F), options,
                                           stop.get_token(), [&](double) { stop.request_stop(); }),
                 data::Cancelled);
}

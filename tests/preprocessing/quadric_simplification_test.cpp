#include "preprocessing/quadric_simplification.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <map>
#include <set>
#include <utility>

#include "data/demo_ensemble.h"
#include "fixtures.h"
#include "mesh_checks.h"
#include "preprocessing/marching_cubes.h"

using namespace ensil;

namespace {
const glm::vec3 kBallCentre(19.6F, 20.2F, 19.8F);

data::TriangleMesh sphere(float radius, std::size_t n = 40) {
    const auto e = test::analyticEnsemble(1, n, n, n, [](auto, auto i, auto j, auto k) {
        return glm::length(glm::vec3(i, j, k) - kBallCentre);
    });
    return prep::extractIsosurface(e.grid, e.members[0].values, radius);
}

// The directed edges used by exactly one triangle: the open border.
std::set<std::pair<std::uint32_t, std::uint32_t>> borderEdges(const data::TriangleMesh& m) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> count;
    for (std::size_t t = 0; t < m.indices.size(); t += 3)
        for (std::size_t e = 0; e < 3; ++e) {
            const auto a = m.indices[t + e], b = m.indices[t + (e + 1) % 3];
            ++count[{std::min(a, b), std::max(a, b)}];
        }
    std::set<std::pair<std::uint32_t, std::uint32_t>> border;
    for (const auto& [edge, n] : count)
        if (n == 1) border.insert(edge);
    return border;
}
}  // namespace

TEST(QuadricSimplification, AClosedSurfaceStaysClosedAndOneSheetHoweverFarItGoes) {
    // An error bound far larger than the sphere lets every collapse through but the ones the
    // link condition and the tetrahedron rule refuse: without them the surface pinches into
    // edges used by three or more triangles, or flattens into a sheet used twice.
    const data::TriangleMesh full = sphere(6.0F);
    const prep::SimplifiedMesh s = prep::simplifyMesh(full, 1000.0F);
    ASSERT_FALSE(s.mesh.empty());
    EXPECT_LT(s.mesh.triangleCount(), 40u) << "it did simplify";
    const test::Topology topo = test::topologyOf(s.mesh);
    EXPECT_EQ(topo.boundaryEdges, 0u);
    EXPECT_EQ(topo.nonManifoldEdges, 0u);
    EXPECT_EQ(topo.inconsistentEdges, 0u);
    EXPECT_EQ(topo.euler, 2);
}

TEST(QuadricSimplification, WeatherLikeSurfacesKeepTheirTopologyUnderEveryBound) {
    // Demo members: jets of many pieces, open where they leave the box. A vertex takes in any
    // number of neighbours in a pass, so the link condition of a collapse onto it must see the
    // triangles of those moved onto it before: with its own triangles only, these surfaces
    // pinch (edges used by three triangles, or windings that disagree).
    const auto demo = data::makeDemoEnsemble({.members = 6, .nx = 64, .ny = 48, .nz = 16});
    for (const float bound : {1.0F, 4.0F, 1000.0F}) {
        for (std::size_t m = 0; m < demo.ensemble.memberCount(); ++m) {
            const data::TriangleMesh full =
                prep::extractIsosurface(demo.ensemble.grid, demo.ensemble.members[m].values, 30.0F);
            const test::Topology before = test::topologyOf(full);
            ASSERT_EQ(before.nonManifoldEdges + before.inconsistentEdges, 0u);
            const prep::SimplifiedMesh s = prep::simplifyMesh(full, bound);
            EXPECT_LT(s.mesh.triangleCount(), full.triangleCount() / 4) << "it did simplify";
            const test::Topology after = test::topologyOf(s.mesh);
            EXPECT_EQ(after.nonManifoldEdges, 0u) << "bound " << bound << ", member " << m;
            EXPECT_EQ(after.inconsistentEdges, 0u) << "bound " << bound << ", member " << m;
            EXPECT_EQ(after.euler, before.euler) << "bound " << bound << ", member " << m;
            EXPECT_EQ(after.boundaryEdges, before.boundaryEdges) << "the open border stays";
        }
    }
}

TEST(QuadricSimplification, OpenBorderVerticesStayWhereTheyWere) {
    // A sphere of radius 12 centred near the corner of a 24-point box leaves the box: its
    // surface has an open border on three faces.
    const auto e = test::analyticEnsemble(1, 24, 24, 24, [](auto, auto i, auto j, auto k) {
        return glm::length(glm::vec3(i, j, k) - glm::vec3(4.3F, 3.7F, 4.1F));
    });
    const data::TriangleMesh full = prep::extractIsosurface(e.grid, e.members[0].values, 12.0F);
    std::set<std::uint32_t> borderVertices;
    for (const auto& [a, b] : borderEdges(full)) borderVertices.insert({a, b});
    ASSERT_GT(borderVertices.size(), 20u);
    const prep::SimplifiedMesh s = prep::simplifyMesh(full, 0.5F);
    EXPECT_LT(s.mesh.triangleCount(), full.triangleCount() / 3);
    // Kept vertices keep their input order and positions; every border vertex is still used.
    std::set<std::uint32_t> used(s.mesh.indices.begin(), s.mesh.indices.end());
    std::set<std::pair<float, float>> keptAt;
    for (const std::uint32_t v : used)
        keptAt.insert({s.mesh.positions[v].x, s.mesh.positions[v].y});
    for (const std::uint32_t v : borderVertices)
        EXPECT_TRUE(keptAt.contains({full.positions[v].x, full.positions[v].y}))
            << "border vertex " << v << " moved or went";
    // And the border is the same length: no border edge was collapsed.
    EXPECT_EQ(borderEdges(s.mesh).size(), borderEdges(full).size());
}

TEST(QuadricSimplification, NoTriangleTurnsOverAndTheErrorStaysWithinTheBound) {
    // A flat ellipsoid (semi-axes 2.5, 12 and 12 cells): around its thin rim a collapse can fold
    // a triangle over, which the turn limit refuses.
    const glm::vec3 axes(2.5F, 12.0F, 12.0F);
    const auto e = test::analyticEnsemble(1, 40, 40, 40, [&](auto, auto i, auto j, auto k) {
        return glm::length((glm::vec3(i, j, k) - kBallCentre) / axes);
    });
    const data::TriangleMesh full = prep::extractIsosurface(e.grid, e.members[0].values, 1.0F);
    for (const float bound : {0.05F, 0.25F, 0.5F}) {
        const prep::SimplifiedMesh s = prep::simplifyMesh(full, bound);
        EXPECT_LE(s.error, bound) << "bound " << bound;
        EXPECT_GT(s.error, 0.0F) << "bound " << bound;
        for (std::size_t t = 0; t < s.mesh.indices.size(); t += 3) {
            const glm::vec3 a = s.mesh.positions[s.mesh.indices[t]];
            const glm::vec3 b = s.mesh.positions[s.mesh.indices[t + 1]];
            const glm::vec3 c = s.mesh.positions[s.mesh.indices[t + 2]];
            // Marching cubes winds towards the lower values: against the field's gradient.
            const glm::vec3 normal = glm::normalize(glm::cross(b - a, c - a));
            const glm::vec3 gradient =
                glm::normalize(((a + b + c) / 3.0F - kBallCentre) / (axes * axes));
            ASSERT_LT(glm::dot(normal, gradient), 0.0F)
                << "bound " << bound << ", triangle " << t / 3;
        }
    }
}

TEST(QuadricSimplification, DropsTrianglesThatNameNoVertexOrOneTwiceAndKeepsAZeroBoundMesh) {
    data::TriangleMesh m = sphere(6.0F);
    const data::TriangleMesh clean = m;
    const auto n = static_cast<std::uint32_t>(m.vertexCount());
    m.indices.insert(m.indices.end(), {0, 1, n + 5, 2, 2, 3, n, n, n});
    const prep::SimplifiedMesh s = prep::simplifyMesh(m, 0.25F);
    for (const std::uint32_t i : s.mesh.indices) ASSERT_LT(i, s.mesh.vertexCount());
    EXPECT_EQ(test::topologyOf(s.mesh).boundaryEdges, 0u);
    EXPECT_EQ(s.mesh.triangleCount(), prep::simplifyMesh(clean, 0.25F).mesh.triangleCount());
    const prep::SimplifiedMesh unchanged = prep::simplifyMesh(clean, 0.0F);
    EXPECT_EQ(unchanged.mesh.indices, clean.indices);
    EXPECT_EQ(unchanged.error, 0.0F);
}

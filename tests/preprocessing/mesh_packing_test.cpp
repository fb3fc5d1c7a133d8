#include "preprocessing/mesh_packing.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <random>

#include "fixtures.h"
#include "preprocessing/marching_cubes.h"

using namespace ensil;

namespace {
// The angle between two vectors, in double and through atan2: acos of a float dot product
// cannot resolve angles below ~3e-4 rad.
double angle(const glm::vec3& a, const glm::vec3& b) {
    const glm::dvec3 x(a), y(b);
    return std::atan2(glm::length(glm::cross(x, y)), glm::dot(x, y));
}

glm::vec3 roundTrip(const glm::vec3& n) {
    prep::VertexAttributes a;
    a.normals = {n};
    a.principalDirections = {n};
    a.kappa1 = a.kappa2 = a.outlyingness = {0.0F};
    const auto packed = prep::packMesh({{glm::vec3(0)}, {}}, a);
    return prep::unpackUnitVector(packed.vertices[0].normal);
}
}  // namespace

TEST(PackedMesh, VertexIsTwentyBytes) { EXPECT_EQ(sizeof(data::PackedVertex), 20u); }

TEST(PackedMesh, UnitVectorsSurviveWithinTwoTenThousandthsOfARadian) {
    std::mt19937 rng(3);
    std::normal_distribution<float> g;
    double worst = 0;
    for (int i = 0; i < 200000; ++i) {
        const glm::vec3 n = glm::normalize(glm::vec3(g(rng), g(rng), g(rng)));
        worst = std::max(worst, angle(roundTrip(n), n));
    }
    // The axes and the octahedron's folds are the hardest cases.
    for (glm::vec3 n :
         {glm::vec3(0, 0, 1), glm::vec3(0, 0, -1), glm::vec3(1, 0, 0), glm::vec3(0, -1, 0),
          glm::normalize(glm::vec3(1, 1, -1e-6F)), glm::normalize(glm::vec3(-1, 0, -1))}) {
        worst = std::max(worst, angle(roundTrip(n), n));
    }
    EXPECT_LT(worst, 2e-4);
    RecordProperty("worst_angle_rad", std::to_string(worst));
}

TEST(PackedMesh, HalvesKeepElevenBitsAndClampAtTheirRange) {
    for (float x : {1.0F, -0.1234F, 3.3e-3F, 123.456F, -65000.0F, 1e-3F}) {
        EXPECT_NEAR(prep::unpackHalf(prep::packHalf(x)), x, std::abs(x) * 0x1p-11F) << x;
    }
    EXPECT_EQ(prep::unpackHalf(prep::packHalf(1e9F)), 65504.0F);
    EXPECT_EQ(prep::unpackHalf(prep::packHalf(std::nanf(""))), 0.0F);
}

TEST(PackedMesh, PositionsAndAttributesRoundTripWithinTheStatedErrors) {
    const glm::vec3 c{15.3F, 14.8F, 10.1F};
    const auto e = test::analyticEnsemble(1, 32, 32, 22, [&](auto, auto i, auto j, auto k) {
        return glm::length(glm::vec3(i, j, k) - c);
    });
    const data::TriangleMesh mesh = prep::extractIsosurface(e.grid, e.members[0].values, 9.0F);
    prep::AxisTables axes;
    for (std::size_t a = 0; a < 3; ++a) {
        const std::size_t n = e.grid.axis(static_cast<int>(a)).size();
        for (std::size_t i = 0; i < n; ++i) axes[a].push_back(static_cast<double>(i));
    }
    prep::VertexAttributes attr =
        prep::computeVertexAttributes(e.grid, e.members[0].values, mesh, axes, 9.0F);
    for (std::size_t v = 0; v < attr.outlyingness.size(); ++v)
        attr.outlyingness[v] = 5000.0F * static_cast<float>(v % 7);
    const data::PackedMesh packed = prep::packMesh(mesh, attr);
    ASSERT_EQ(packed.vertices.size(), mesh.vertexCount());
    EXPECT_EQ(packed.indices, mesh.indices);
    EXPECT_EQ(packed.gpuBytes(), mesh.vertexCount() * 20 + mesh.indices.size() * 4);
    const glm::vec3 step = (packed.boundsMax - packed.boundsMin) / 65535.0F;
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
        const data::PackedVertex& p = packed.vertices[v];
        const glm::vec3 d = glm::abs(prep::unpackPosition(packed, p) - mesh.positions[v]);
        for (int a = 0; a < 3; ++a) ASSERT_LE(d[a], 0.5F * step[a] + 1e-5F);
        ASSERT_NEAR(prep::unpackHalf(p.kappa1), attr.kappa1[v],
                    std::abs(attr.kappa1[v]) * 0x1p-11F + 1e-7F);
        ASSERT_NEAR(prep::unpackHalf(p.outlyingness) * packed.outlyingnessScale,
                    attr.outlyingness[v], attr.outlyingness[v] * 0x1p-11F + 1e-3F);
        ASSERT_LT(angle(prep::unpackUnitVector(p.normal), attr.normals[v]), 2e-4);
        ASSERT_LT(angle(prep::unpackUnitVector(p.direction), attr.principalDirections[v]), 2e-4);
    }
}

TEST(PackedMesh, MaximumOutlyingnessIsTheLargestFiniteValueOverAllMembersScaled) {
    data::MeshSet set;
    EXPECT_EQ(prep::maximumOutlyingness(set), 0.0F);
    set.members.resize(2);
    for (const float o : {0.5F, 3.0F, 1.25F}) {
        data::PackedVertex v{};
        v.outlyingness = prep::packHalf(o);
        set.members[0].vertices.push_back(v);
    }
    data::PackedVertex infinite{};
    infinite.outlyingness = 0x7C00;  // +inf: not a value the removal range should reach
    set.members[1].vertices.push_back(infinite);
    data::PackedVertex two{};
    two.outlyingness = prep::packHalf(2.0F);
    set.members[1].vertices.push_back(two);
    set.members[1].outlyingnessScale = 4.0F;  // 2 x 4 = 8 beats member 0's 3
    EXPECT_FLOAT_EQ(prep::maximumOutlyingness(set), 8.0F);
}

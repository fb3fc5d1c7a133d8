#include "preprocessing/vertex_attributes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "fixtures.h"
#include "preprocessing/ensemble_moments.h"
#include "preprocessing/marching_cubes.h"

using namespace ensil;

namespace {
// Display coordinates = index * spacing along each axis.
prep::AxisTables scaled(const data::Grid& g, glm::dvec3 spacing) {
    prep::AxisTables t;
    const std::array<std::size_t, 3> n{g.nx(), g.ny(), g.nz()};
    for (int a = 0; a < 3; ++a) {
        t[static_cast<std::size_t>(a)].resize(n[static_cast<std::size_t>(a)]);
        for (std::size_t i = 0; i < n[static_cast<std::size_t>(a)]; ++i)
            t[static_cast<std::size_t>(a)][i] = static_cast<double>(i) * spacing[a];
    }
    return t;
}

struct Surface {
    data::Ensemble ensemble;
    data::TriangleMesh mesh;
    prep::VertexAttributes attributes;
};

Surface surfaceOf(data::Ensemble e, float iso, glm::dvec3 spacing) {
    Surface s{std::move(e), {}, {}};
    s.mesh = prep::extractIsosurface(s.ensemble.grid, s.ensemble.members[0].values, iso);
    s.attributes = prep::computeVertexAttributes(s.ensemble.grid, s.ensemble.members[0].values,
                                                 s.mesh, scaled(s.ensemble.grid, spacing), iso);
    return s;
}

// Vertices away from the volume's border, where one-sided differences are less accurate.
bool interior(const glm::vec3& p, float n) {
    return p.x > 2 && p.y > 2 && p.z > 2 && p.x < n - 3 && p.y < n - 3 && p.z < n - 3;
}
}  // namespace

TEST(VertexAttributes, SphereNormalsPointInwardAndBothCurvaturesAreMinusOneOverR) {
    // f = |x - c| in display units with spacing 0.5: radius 6 display units = 12 cells.
    const glm::vec3 c{20.3F, 19.6F, 20.2F};
    auto e = test::analyticEnsemble(1, 41, 41, 41, [&](auto, auto i, auto j, auto k) {
        return 0.5F * glm::length(glm::vec3(i, j, k) - c);
    });
    const Surface s = surfaceOf(std::move(e), 6.0F, {0.5, 0.5, 0.5});
    ASSERT_GT(s.mesh.vertexCount(), 1000u);
    double worstK = 0, worstN = 0;
    for (std::size_t v = 0; v < s.mesh.vertexCount(); ++v) {
        const glm::vec3 p = s.mesh.positions[v];
        const glm::vec3 inward = glm::normalize(c - p);
        worstN = std::max(worstN, 1.0 - glm::dot(s.attributes.normals[v], inward));
        worstK = std::max({worstK, std::abs(s.attributes.kappa1[v] + 1.0 / 6.0),
                           std::abs(s.attributes.kappa2[v] + 1.0 / 6.0)});
        ASSERT_NEAR(glm::dot(s.attributes.principalDirections[v], s.attributes.normals[v]), 0.0F,
                    1e-4);
    }
    EXPECT_LT(std::acos(1.0 - worstN), 1.0 * 3.14159265 / 180.0)
        << "normals radial within 1 degree";
    EXPECT_LT(worstK, 0.03 / 6.0) << "curvature error within 3 %";
}

TEST(VertexAttributes, CylinderHasOneFlatDirectionAlongItsAxis) {
    // Distance to the line x = 15.4, y = 15.7 (parallel to z): kappa = 0 along z, -1/r around.
    auto e = test::analyticEnsemble(1, 32, 32, 24, [](auto, auto i, auto j, auto) {
        return glm::length(glm::vec2(static_cast<float>(i) - 15.4F, static_cast<float>(j) - 15.7F));
    });
    const Surface s = surfaceOf(std::move(e), 8.0F, {1, 1, 1});
    for (std::size_t v = 0; v < s.mesh.vertexCount(); ++v) {
        if (!interior(s.mesh.positions[v], 24)) continue;
        ASSERT_NEAR(s.attributes.kappa1[v], 0.0F, 0.004F);
        ASSERT_NEAR(s.attributes.kappa2[v], -1.0F / 8.0F, 0.004F);
        ASSERT_GT(std::abs(s.attributes.principalDirections[v].z), 0.99F) << "kappa1 runs along z";
    }
}

TEST(VertexAttributes, TorusCurvaturesDifferInSignOnTheInnerSide) {
    const float R = 10.0F, r = 4.0F;
    auto e = test::analyticEnsemble(1, 36, 36, 18, [&](auto, auto i, auto j, auto k) {
        const float x = static_cast<float>(i) - 17.6F, y = static_cast<float>(j) - 17.3F;
        const float z = static_cast<float>(k) - 8.4F;
        const float q = std::sqrt(x * x + y * y) - R;
        return std::sqrt(q * q + z * z);
    });
    const Surface s = surfaceOf(std::move(e), r, {1, 1, 1});
    // Exact: -1/r across the tube; -cos(theta) / (R + r cos(theta)) around the hole, with
    // cos(theta) = (rho - R) / r: positive on the inner side (a saddle), negative outside.
    int inner = 0, outer = 0;
    for (std::size_t v = 0; v < s.mesh.vertexCount(); ++v) {
        const glm::vec3 p = s.mesh.positions[v];
        const float rho = glm::length(glm::vec2(p.x - 17.6F, p.y - 17.3F));
        const float cosTheta = std::clamp((rho - R) / r, -1.0F, 1.0F);
        const float around = -cosTheta / (R + r * cosTheta), tube = -1.0F / r;
        ASSERT_NEAR(s.attributes.kappa1[v], std::max(around, tube), 0.02F) << "vertex " << v;
        ASSERT_NEAR(s.attributes.kappa2[v], std::min(around, tube), 0.02F) << "vertex " << v;
        // kappa1 is the curvature around the hole everywhere (-1/(R + r) > -1/r), so its
        // direction is the toroidal one, perpendicular to the radius and to the axis.
        const glm::vec3 toroidal = glm::normalize(glm::vec3(-(p.y - 17.3F), p.x - 17.6F, 0.0F));
        ASSERT_GT(std::abs(glm::dot(s.attributes.principalDirections[v], toroidal)), 0.99F)
            << "vertex " << v;
        if (cosTheta < -0.9F) {
            ++inner;
            ASSERT_GT(s.attributes.kappa1[v], 0.0F);
            ASSERT_LT(s.attributes.kappa2[v], 0.0F);
        }
        if (cosTheta > 0.9F) {
            ++outer;
            ASSERT_LT(s.attributes.kappa1[v], 0.0F);
        }
    }
    EXPECT_GT(inner, 10);
    EXPECT_GT(outer, 10);
}

TEST(VertexAttributes, OutlyingnessIsTheMeanSquaredDistanceToAllMembers) {
    // Members are linear ramps shifted by constants c_m: f_m = x + c_m. At the isovalue mu the
    // other members' values differ from mu by (c_j - c_i), so o_i = sum_j (c_j - c_i)^2 / N.
    const std::array<float, 4> shift{0.0F, 1.0F, 3.0F, -2.0F};
    const auto e = test::analyticEnsemble(
        4, 20, 6, 6, [&](auto m, auto i, auto, auto) { return static_cast<float>(i) + shift[m]; });
    const prep::EnsembleMoments moments = prep::computeEnsembleMoments(e);
    for (std::size_t i = 0; i < 4; ++i) {
        const float mu = 9.5F;
        const data::TriangleMesh mesh = prep::extractIsosurface(e.grid, e.members[i].values, mu);
        const auto attributes = prep::computeVertexAttributes(
            e.grid, e.members[i].values, mesh, scaled(e.grid, {1, 1, 1}), mu, &moments);
        double expected = 0;
        for (float c : shift) expected += (c - shift[i]) * (c - shift[i]) / 4.0;
        ASSERT_FALSE(attributes.outlyingness.empty());
        for (float o : attributes.outlyingness) ASSERT_NEAR(o, expected, 1e-4 * (1 + expected));
    }
}

TEST(VertexAttributes, UnevenSpacingGivesTheSameSurfaceAsAUniformGrid) {
    // A sphere sampled on levels z_k = k + 0.3 sin(k) (uneven, as pressure levels are): mapped
    // through the axis tables, the surface must be the same sphere, with the same normals and
    // curvatures, as on a uniform grid.
    const glm::vec3 c{16.2F, 15.7F, 15.9F};
    const auto level = [](std::size_t k) {
        return static_cast<double>(k) + 0.3 * std::sin(static_cast<double>(k));
    };
    auto e = test::analyticEnsemble(1, 33, 33, 33, [&](auto, auto i, auto j, auto k) {
        return glm::length(glm::vec3(i, j, static_cast<float>(level(k))) - c);
    });
    prep::AxisTables axes = scaled(e.grid, {1, 1, 1});
    for (std::size_t k = 0; k < axes[2].size(); ++k) axes[2][k] = level(k);
    const data::TriangleMesh mesh = prep::extractIsosurface(e.grid, e.members[0].values, 10.0F);
    const auto a = prep::computeVertexAttributes(e.grid, e.members[0].values, mesh, axes, 10.0F);
    ASSERT_GT(mesh.vertexCount(), 500u);
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
        const glm::vec3 idx = mesh.positions[v];
        const auto k0 = static_cast<std::size_t>(idx.z);
        const double z = level(k0) + (idx.z - static_cast<float>(k0)) * (level(k0 + 1) - level(k0));
        const glm::vec3 p{idx.x, idx.y, static_cast<float>(z)};
        ASSERT_NEAR(glm::length(p - c), 10.0F, 0.07F) << "vertex " << v;
        ASSERT_GT(glm::dot(a.normals[v], glm::normalize(c - p)),
                  std::cos(2.0F * 3.14159265F / 180.0F));
        ASSERT_NEAR(a.kappa1[v], -0.1F, 0.005F);
        ASSERT_NEAR(a.kappa2[v], -0.1F, 0.005F);
    }
}

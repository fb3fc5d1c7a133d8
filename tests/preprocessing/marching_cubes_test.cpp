#include "preprocessing/marching_cubes.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <tuple>

#include "fixtures.h"
#include "mesh_checks.h"
#include "reference_marching_cubes.h"

using namespace ensil;

namespace {
constexpr std::size_t kN = 40;
const glm::vec3 kCentre{19.3F, 20.1F, 18.7F};  // off the grid points, so no value equals r

data::Ensemble sphereField() {
    return test::analyticEnsemble(1, kN, kN, kN, [](auto, auto i, auto j, auto k) {
        return glm::length(glm::vec3(i, j, k) - kCentre);
    });
}

data::TriangleMesh mesh(const data::Ensemble& e, float iso) {
    return prep::extractIsosurface(e.grid, e.members[0].values, iso);
}
}  // namespace

TEST(MarchingCubes, SphereVerticesLieOnTheSphere) {
    const auto e = sphereField();
    const data::TriangleMesh m = mesh(e, 12.0F);
    ASSERT_GT(m.triangleCount(), 1000u);
    for (const glm::vec3& p : m.positions) {
        // |x - c| is not linear along an edge; linear interpolation errs by at most h^2 / (2r).
        ASSERT_NEAR(glm::length(p - kCentre), 12.0F, 1.0F / 24.0F + 1e-4F);
    }
}

TEST(MarchingCubes, SphereIsClosedOrientedGenusZeroWithTheRightArea) {
    const auto e = sphereField();
    const data::TriangleMesh m = mesh(e, 12.0F);
    const test::Topology topo = test::topologyOf(m);
    EXPECT_EQ(topo.boundaryEdges, 0u);
    EXPECT_EQ(topo.nonManifoldEdges, 0u);
    EXPECT_EQ(topo.inconsistentEdges, 0u);
    EXPECT_EQ(topo.euler, 2) << "a sphere";
    const double exact = 4.0 * std::numbers::pi * 12.0 * 12.0;
    EXPECT_NEAR(test::areaOf(m), exact, 0.01 * exact);
    // Winding: counter-clockwise seen from lower values, so the geometric normal is -grad f,
    // which for the distance field points to the centre.
    for (std::size_t t = 0; t < m.indices.size(); t += 3) {
        const glm::vec3 a = m.positions[m.indices[t]], b = m.positions[m.indices[t + 1]],
                        c = m.positions[m.indices[t + 2]];
        const glm::vec3 normal = glm::cross(b - a, c - a);
        const glm::vec3 inward = kCentre - (a + b + c) / 3.0F;
        ASSERT_GT(glm::dot(normal, inward), 0.0F) << "triangle " << t / 3;
    }
}

TEST(MarchingCubes, TorusHasGenusOne) {
    // (sqrt(x^2 + y^2) - R)^2 + z^2 = r^2 with R = 10, r = 4.
    const auto e = test::analyticEnsemble(1, 36, 36, 16, [](auto, auto i, auto j, auto k) {
        const float x = static_cast<float>(i) - 17.6F, y = static_cast<float>(j) - 17.3F;
        const float z = static_cast<float>(k) - 7.4F;
        const float q = std::sqrt(x * x + y * y) - 10.0F;
        return std::sqrt(q * q + z * z);
    });
    const data::TriangleMesh m = mesh(e, 4.0F);
    const test::Topology topo = test::topologyOf(m);
    EXPECT_EQ(topo.boundaryEdges, 0u);
    EXPECT_EQ(topo.inconsistentEdges, 0u);
    EXPECT_EQ(topo.euler, 0) << "a torus";
    const double exact = 4.0 * std::numbers::pi * std::numbers::pi * 10.0 * 4.0;
    EXPECT_NEAR(test::areaOf(m), exact, 0.03 * exact);
}

TEST(MarchingCubes, RandomFieldsAreWatertightInsideTheVolume) {
    // Noise exercises every case, ambiguous faces included: the mesh may only end where it
    // leaves the volume, and neighbouring cells must agree on each shared face.
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> value(-1.0F, 1.0F);
    for (int trial = 0; trial < 20; ++trial) {
        const auto e =
            test::analyticEnsemble(1, 9, 8, 7, [&](auto, auto, auto, auto) { return value(rng); });
        const data::TriangleMesh m = mesh(e, 0.05F);
        const test::Topology topo = test::topologyOf(m);
        EXPECT_EQ(topo.nonManifoldEdges, 0u) << "trial " << trial;
        EXPECT_EQ(topo.inconsistentEdges, 0u) << "trial " << trial;
        // Boundary edges lie on the faces of the volume.
        std::map<std::pair<std::uint32_t, std::uint32_t>, int> count;
        for (std::size_t t = 0; t < m.indices.size(); t += 3)
            for (int k = 0; k < 3; ++k) {
                auto a = m.indices[t + k], b = m.indices[t + (k + 1) % 3];
                ++count[{std::min(a, b), std::max(a, b)}];
            }
        const auto onFace = [](const glm::vec3& p) {
            return p.x == 0 || p.x == 8 || p.y == 0 || p.y == 7 || p.z == 0 || p.z == 6;
        };
        for (const auto& [edge, n] : count) {
            if (n == 1) {
                ASSERT_TRUE(onFace(m.positions[edge.first]) && onFace(m.positions[edge.second]))
                    << "a crack inside the volume, trial " << trial;
            }
        }
    }
}

TEST(MarchingCubes, CellsTouchingMissingValuesMakeNoTriangles) {
    auto e = sphereField();
    // Punch a missing block through the top of the sphere.
    for (std::size_t k = 28; k < 36; ++k)
        for (std::size_t j = 16; j < 24; ++j)
            for (std::size_t i = 16; i < 24; ++i)
                e.members[0].values[e.grid.index(i, j, k)] =
                    std::numeric_limits<float>::quiet_NaN();
    const data::TriangleMesh m = mesh(e, 12.0F);
    for (const glm::vec3& p : m.positions) {
        const bool insideHole = p.x > 16 && p.x < 23 && p.y > 16 && p.y < 23 && p.z > 28;
        ASSERT_FALSE(insideHole) << "vertex in the missing block";
    }
    const test::Topology topo = test::topologyOf(m);
    EXPECT_GT(topo.boundaryEdges, 0u) << "the hole has a rim";
    EXPECT_EQ(topo.inconsistentEdges, 0u);
}

TEST(MarchingCubes, NoSurfaceWhenTheIsovalueIsOutsideTheRange) {
    const auto e = sphereField();
    EXPECT_TRUE(mesh(e, 1000.0F).empty());
    EXPECT_TRUE(mesh(e, -1.0F).empty());
}

TEST(MarchingCubes, StopsWhenCancelled) {
    const auto e = sphereField();
    std::stop_source stop;
    stop.request_stop();
    EXPECT_THROW(prep::extractIsosurface(e.grid, e.members[0].values, 12.0F, stop.get_token()),
                 data::Cancelled);
}

namespace {
// A triangle's corners rotated to start at the smallest, keeping its winding.
test::Triangle canonical(test::Triangle t) {
    const auto less = [](const glm::vec3& a, const glm::vec3& b) {
        return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
    };
    while (less(t[1], t[0]) || less(t[2], t[0])) t = {t[1], t[2], t[0]};
    return t;
}
bool lessTriangle(const test::Triangle& a, const test::Triangle& b) {
    return std::lexicographical_compare(&a[0].x, &a[0].x + 9, &b[0].x, &b[0].x + 9);
}

// Noise in [-1, 1] with about 3 % of the points missing and a missing block.
data::Ensemble holedNoise(std::size_t nx, std::size_t ny, std::size_t nz, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> value(-1.0F, 1.0F);
    std::uniform_real_distribution<float> chance(0.0F, 1.0F);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    return test::analyticEnsemble(1, nx, ny, nz, [&](auto, auto i, auto j, auto k) {
        const bool block = i >= nx / 3 && i < nx / 2 && j >= ny / 2 && k + 1 >= nz / 2;
        return chance(rng) < 0.03F || block ? nan : value(rng);
    });
}
}  // namespace

TEST(MarchingCubes, MatchesAPlainCellByCellExtraction) {
    // Row lengths below, at and across the 64-point words the extraction works in.
    const std::vector<std::array<std::size_t, 3>> shapes{{3, 2, 2},  {9, 8, 7},   {64, 5, 4},
                                                         {65, 6, 5}, {130, 7, 3}, {200, 3, 9}};
    unsigned seed = 1;
    for (const auto& [nx, ny, nz] : shapes) {
        const auto e = holedNoise(nx, ny, nz, seed++);
        const data::TriangleMesh m = mesh(e, 0.05F);
        const test::ReferenceSurface ref =
            test::referenceMarchingCubes(e.grid, e.members[0].values, 0.05F);
        const std::string shape =
            std::to_string(nx) + "x" + std::to_string(ny) + "x" + std::to_string(nz);
        ASSERT_GT(ref.triangles.size(), 0u) << shape;
        // One vertex per crossing edge, shared: no two vertices at one place.
        EXPECT_EQ(m.vertexCount(), ref.crossingEdges) << shape;
        std::vector<glm::vec3> sorted = m.positions;
        const auto lessPoint = [](const glm::vec3& a, const glm::vec3& b) {
            return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
        };
        std::sort(sorted.begin(), sorted.end(), lessPoint);
        EXPECT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end()) << shape;
        // The same triangles, with the same winding, bit for bit.
        std::vector<test::Triangle> fast;
        for (std::size_t t = 0; t < m.indices.size(); t += 3) {
            ASSERT_LT(std::max({m.indices[t], m.indices[t + 1], m.indices[t + 2]}),
                      m.vertexCount());
            fast.push_back(canonical({m.positions[m.indices[t]], m.positions[m.indices[t + 1]],
                                      m.positions[m.indices[t + 2]]}));
        }
        std::vector<test::Triangle> expected;
        for (const auto& t : ref.triangles) expected.push_back(canonical(t));
        std::sort(fast.begin(), fast.end(), lessTriangle);
        std::sort(expected.begin(), expected.end(), lessTriangle);
        ASSERT_EQ(fast.size(), expected.size()) << shape;
        EXPECT_TRUE(fast == expected) << shape;
    }
}

TEST(MarchingCubes, SameMeshWhateverTheThreadCount) {
    const auto e = holedNoise(150, 40, 30, 7);
    const data::TriangleMesh many = mesh(e, 0.05F);
    data::TriangleMesh one;
    tbb::task_arena single(1);
    single.execute([&] { one = mesh(e, 0.05F); });
    ASSERT_GT(many.triangleCount(), 1000u);
    EXPECT_TRUE(one.positions == many.positions);
    EXPECT_TRUE(one.indices == many.indices);
}

// The rims where isosurfaces meet the data box (gl/mesh_rims.h): which edges are rims, that a
// cut sphere's rim is its cut circle, and that a two-level sheet, which has no silhouette seen
// from above, shows (and picks) every member by its rim.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "gl/mesh_rims.h"
#include "tests/gl/sphere_scene.h"

using namespace ensil;

namespace {
data::PackedVertex vertex(std::uint16_t x, std::uint16_t y, std::uint16_t z) {
    data::PackedVertex v{};
    v.position[0] = x;
    v.position[1] = y;
    v.position[2] = z;
    return v;
}

std::vector<std::pair<std::uint32_t, std::uint32_t>> pairsOf(const std::vector<std::uint32_t>& s) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
    for (std::size_t i = 0; i + 1 < s.size(); i += 2) {
        pairs.emplace_back(std::min(s[i], s[i + 1]), std::max(s[i], s[i + 1]));
    }
    std::sort(pairs.begin(), pairs.end());
    return pairs;
}

// Member m's field is zero on level 0 and 10 - r on level 1, r the distance from (cx_m, 15.5)
// on a 32 x 32 x 2 grid: its isosurface at 2 is a sheet between the levels over the disc
// r < 8, with no part turned edge-on to a viewer above. Its rim on the top face is the circle
// r = 8, the member's contour line there.
data::Ensemble twoLevelSheets(const std::vector<float>& centresX) {
    data::Ensemble e;
    e.grid = data::Grid(data::makeUniformAxis("x", "m", 0, 31, 32),
                        data::makeUniformAxis("y", "m", 0, 31, 32),
                        data::makeUniformAxis("z", "m", 0, 3, 2));
    for (const float cx : centresX) {
        data::Member m;
        m.values.resize(e.grid.pointCount());
        for (std::size_t j = 0; j < 32; ++j) {
            for (std::size_t i = 0; i < 32; ++i) {
                const float r = glm::length(glm::vec2(i, j) - glm::vec2(cx, 15.5F));
                m.values[e.grid.index(i, j, 0)] = 0.0F;
                m.values[e.grid.index(i, j, 1)] = 10.0F - r;
            }
        }
        e.members.push_back(std::move(m));
    }
    return e;
}
}  // namespace

TEST(MeshRims, OnlyEdgesOfOneTriangleWithBothEndsOnOneFaceAreRims) {
    // The box [0, 2] x [0, 1] x [0, 1]; the mesh's bounds reach x = 0 and 2, y = 0 and 1, and
    // lie inside along z (0.5). A quad A B C D over the whole x-y extent, split along A C, and a
    // second triangle B A E below A B, so A B has a triangle on either side.
    data::PackedMesh mesh;
    mesh.boundsMin = {0.0F, 0.0F, 0.4F};
    mesh.boundsMax = {2.0F, 1.0F, 0.6F};
    mesh.vertices = {vertex(0, 0, 30000), vertex(65535, 0, 30000), vertex(65535, 65535, 30000),
                     vertex(0, 65535, 30000), vertex(30000, 0, 0)};
    const std::uint32_t a = 0, b = 1, c = 2, d = 3, e = 4;
    mesh.indices = {a, b, c, a, c, d, b, a, e};
    const auto rims = pairsOf(gl::rimSegments(mesh, {2.0F, 1.0F, 1.0F}));
    // B C (x = 2), C D (y = 1), D A (x = 0) are rims; A C joins no common face; A B (y = 0) has
    // two triangles; B E and E A lie on y = 0 too and belong to one triangle each. z = 0 is not
    // reached by the mesh's bounds, so E's z code 0 means nothing.
    using Pair = std::pair<std::uint32_t, std::uint32_t>;
    EXPECT_EQ(rims, (std::vector<Pair>{{0, 3}, {0, 4}, {1, 2}, {1, 4}, {2, 3}}));
    // No box without two points along every axis.
    EXPECT_TRUE(gl::rimSegments(mesh, {2.0F, 1.0F, 0.0F}).empty());
}

TEST(MeshRims, ASphereCutByTheBoxHasItsCutCircleAsItsRimAndAWholeOneHasNone) {
    // Centred on the bottom face: the box cuts the sphere of radius 8 along a circle at z = 0.
    const auto set = test::meshesOf(test::spheres({{15.5F, 15.5F, 0.0F}, {15.5F, 15.5F, 15.5F}}));
    const data::PackedMesh& cut = set->members[0];
    const std::vector<std::uint32_t> rims = gl::rimSegments(cut, glm::vec3(31.0F));
    ASSERT_GT(rims.size(), 40u) << "a circle of radius 8 crosses at least 40 cells";
    for (const std::uint32_t v : rims) {
        const data::PackedVertex& p = cut.vertices[v];
        const glm::vec3 q(p.position[0], p.position[1], p.position[2]);
        const glm::vec3 index = cut.boundsMin + q / 65535.0F * (cut.boundsMax - cut.boundsMin);
        EXPECT_EQ(index.z, 0.0F);
        EXPECT_NEAR(glm::length(glm::vec2(index) - glm::vec2(15.5F)), 8.0F, 0.2F);
    }
    EXPECT_TRUE(gl::rimSegments(set->members[1], glm::vec3(31.0F)).empty());
}

using RimsTest = test::SphereSceneTest;

TEST_F(RimsTest, ATwoLevelSheetShowsAndPicksEveryMemberByItsRimFromAbove) {
    const std::vector<float> centres{10.0F, 15.5F, 21.0F};
    const data::Ensemble e = twoLevelSheets(centres);
    m_renderer.setGrid(e.grid);
    m_renderer.setMeshes(test::meshesOf(e, 2.0F));
    m_renderer.setAppearance({{gl::clusterColor(0), true, false},
                              {gl::clusterColor(1), true, false},
                              {gl::clusterColor(2), true, false}});
    m_renderer.settings().showMean = false;
    m_renderer.lookFrom(-90.0F, 90.0F);  // straight down, north up
    m_renderer.camera().setProjection(gl::Camera::Projection::Orthographic);

    m_renderer.settings().showRims = false;
    (void)draw();
    EXPECT_TRUE(m_renderer.membersIn(0, 0, kWidth - 1, kHeight - 1).empty())
        << "seen from above the sheets have no silhouette";

    m_renderer.settings().showRims = true;
    const QImage image = draw();
    EXPECT_EQ(m_renderer.membersIn(0, 0, kWidth - 1, kHeight - 1), (std::vector<int>{0, 1, 2}));
    // Each member is drawn, in its colour, and picked where its contour circle lies: west of
    // its centre, away from the other circles.
    for (std::size_t m = 0; m < centres.size(); ++m) {
        SCOPED_TRACE(m);
        const QPoint west = project(display({centres[m] - 7.9F, 15.5F, 1.0F}));
        EXPECT_EQ(m_renderer.pick(west.x(), west.y()).member, static_cast<int>(m));
        int near = 0;
        for (int dy = -2; dy <= 2; ++dy) {
            for (int dx = -2; dx <= 2; ++dx) {
                const QColor c = image.pixelColor(west + QPoint(dx, dy));
                if (test::channelDistance(c, gl::clusterColor(static_cast<int>(m))) < 40) ++near;
            }
        }
        EXPECT_GT(near, 0) << "no pixel in the member's colour on its rim";
    }
}

// Another vertical axis for a pressure grid moves only the axis tables: what is drawn after the
// change, with the meshes and rims uploaded before it, is what the same meshes uploaded again
// draw, and not what was drawn through log-pressure.
TEST_F(RimsTest, AnotherVerticalAxisMovesTheSurfacesWithoutUploadingThemAgain) {
    data::Ensemble e = test::spheres({{16.0F, 16.0F, 12.0F}});
    data::Axis pressure;
    pressure.name = "plev";
    pressure.units = "Pa";
    pressure.positiveUp = false;
    for (int k = 0; k < 32; ++k) pressure.values.push_back(100000.0 - 2800.0 * k);
    e.grid = data::Grid(e.grid.x(), e.grid.y(), pressure);
    const std::shared_ptr<data::MeshSet> meshes = test::meshesOf(e);
    m_renderer.setGrid(e.grid);
    m_renderer.setMeshes(meshes);
    m_renderer.setAppearance({{gl::clusterColor(0), true, false}});
    m_renderer.lookFrom(-90.0F, 0.0F);  // from the south, level
    const QImage logPressure = draw();
    m_renderer.setVerticalAxis(data::VerticalAxis::Pressure);
    const QImage switched = draw();
    m_renderer.setMeshes(meshes);  // uploaded again
    const QImage uploaded = draw();
    EXPECT_EQ(switched, uploaded);
    EXPECT_NE(switched, logPressure);
}

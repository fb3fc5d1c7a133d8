// The cutting plane (METHODS.md section 11) and density-based removal (section 10) on spheres,
// whose geometry says exactly which pixels must change.
#include <QImage>
#include <algorithm>
#include <cstdlib>

#include "tests/gl/sphere_scene.h"

using namespace ensil;
using test::channelDistance;
using test::spheres;
using CuttingPlaneTest = test::SphereSceneTest;
using RemovalTest = test::SphereSceneTest;

namespace {
constexpr glm::vec3 kOrange{1.0F, 0.5F, 0.0F};

// The best match to `colour` within `radius` pixels along the row through p.
int nearestMatch(const QImage& image, QPoint p, const glm::vec3& colour, int radius = 3) {
    int best = 255;
    for (int dx = -radius; dx <= radius; ++dx)
        best = std::min(best, channelDistance(image.pixelColor(p + QPoint(dx, 0)), colour));
    return best;
}
}  // namespace

TEST_F(CuttingPlaneTest, TheViewersSideIsCutAwayAndTheCurveDrawnWhereTheSurfaceCrossesThePlane) {
    // A sphere of radius 8 at the centre; the plane x = 12 (3.5 cells left of the centre).
    // Looking along +y from x = 15.5, the viewer is on the side x > 12, which is cut away.
    const glm::vec3 centre{15.5F, 15.5F, 15.5F};
    show(spheres({centre}), {kOrange});
    m_renderer.settings().showMean = false;
    m_renderer.settings().thickness = 0.05F;
    const QPoint rightRim = project(display(centre + glm::vec3(7.9F, 0, 0)));
    const QPoint leftRim = project(display(centre - glm::vec3(7.9F, 0, 0)));
    const QImage whole = draw();
    ASSERT_LE(nearestMatch(whole, rightRim, kOrange), 40) << "the right rim is drawn uncut";

    m_renderer.settings().plane = gl::CuttingPlane::through({1, 0, 0}, display({12, 15.5F, 15.5F}));
    m_renderer.settings().plane.thickness = 0.5F / 31.0F;  // half a cell
    const QImage cut = draw();
    EXPECT_LE(channelDistance(cut.pixelColor(rightRim), {0, 0, 0}), 3) << "cut away";
    EXPECT_LE(nearestMatch(cut, leftRim, kOrange), 40) << "the far side of the plane stays";
    // The sphere meets the plane x = 12 in a circle of radius sqrt(64 - 3.5^2) = 7.19 cells;
    // seen edge-on, a vertical line. Its front point (12, 15.5 - 7.19, 15.5) is on screen.
    const QPoint curve = project(display({11.9F, 15.5F - 7.19F, 15.5F}));
    EXPECT_LE(nearestMatch(cut, curve, kOrange, 2), 40) << "the intersection curve";
    // The same plane facing the other way cuts the same side: the viewer decides, not the sign.
    m_renderer.settings().plane =
        gl::CuttingPlane::through({-1, 0, 0}, display({12, 15.5F, 15.5F}));
    m_renderer.settings().plane.thickness = 0.5F / 31.0F;
    EXPECT_EQ(test::differingFraction(cut, draw(), 0), 0.0);
}

TEST_F(CuttingPlaneTest, ThePlaneCutsTheMeanAndTheCurveThicknessGrowsWithEpsilonUpToThreePixels) {
    const glm::vec3 centre{15.5F, 15.5F, 15.5F};
    show(spheres({centre}), {kOrange});
    m_renderer.settings().showMean = false;
    m_renderer.settings().thickness = 0.001F;  // no silhouettes to speak of: the curve alone
    m_renderer.settings().plane = gl::CuttingPlane::through({1, 0, 0}, display(centre));
    const auto litPixels = [&](float epsilonCells) {
        m_renderer.settings().plane.thickness = epsilonCells / 31.0F;
        const QImage image = draw();
        const QImage empty = [&] {
            m_renderer.settings().plane.enabled = false;
            m_renderer.setAppearance({{kOrange, false, false}});
            QImage e = draw();
            m_renderer.settings().plane.enabled = true;
            m_renderer.setAppearance({{kOrange, true, false}});
            return e;
        }();
        return test::differingFraction(image, empty, 8);
    };
    // A cell is about 6 pixels here, and the plane, seen edge-on, meets the sphere's front face
    // square-on: eps of 0.1 and 0.4 cells are 0.6 and 2.4 pixels on screen, 3 and 6 cells both
    // more than the curve's 3-pixel limit.
    const double thin = litPixels(0.1F);
    const double thick = litPixels(0.4F);
    EXPECT_GT(thin, 0.0);
    EXPECT_GT(thick, 1.5 * thin);
    const double limited = litPixels(3.0F);
    EXPECT_NEAR(litPixels(6.0F) / limited, 1.0, 0.05) << "never wider than three pixels";
}

TEST_F(CuttingPlaneTest, WhereASurfaceGrazesThePlaneTheCurveStaysAFewPixelsWide) {
    // The sheet z = 15.5 - 0.05 (x - 15.5), tilted 2.9 degrees, seen from straight above and
    // cut by the horizontal plane z = 15.5: they meet along x = 15.5. Half a cell behind the
    // plane is 10 cells of the sheet (x from 15.5 to 25.5): with the curve eps deep alone that
    // is a wide band (issue 39's zebra stripes); it must stay a curve, a few pixels wide.
    data::Ensemble sheet = spheres({{0, 0, 0}});
    for (std::size_t k = 0; k < 32; ++k) {
        for (std::size_t j = 0; j < 32; ++j) {
            for (std::size_t i = 0; i < 32; ++i) {
                sheet.members[0].values[sheet.grid.index(i, j, k)] =
                    float(k) + 0.05F * (float(i) - 15.5F);
            }
        }
    }
    m_renderer.setGrid(sheet.grid);
    m_renderer.setMeshes(test::meshesOf(sheet, 15.5F));
    m_renderer.setAppearance({{kOrange, true, false}});
    m_renderer.camera().setProjection(gl::Camera::Projection::Orthographic);
    m_renderer.camera().setAngles(-90.0F, 90.0F);
    m_renderer.camera().fit(m_renderer.frame().center(), 0.45F);
    m_renderer.settings().showMean = false;
    m_renderer.settings().thickness = 0.001F;  // a sheet seen face-on: no silhouette
    m_renderer.settings().plane =
        gl::CuttingPlane::through({0, 0, 1}, display({15.5F, 15.5F, 15.5F}));
    m_renderer.settings().plane.thickness = 0.5F / 31.0F;
    const QImage cut = draw();
    m_renderer.setAppearance({{kOrange, false, false}});
    const QImage empty = draw();
    // The middle row, inside the box's outline: every pixel that the sheet changes is the curve.
    const int row = project(display({15.5F, 15.5F, 15.5F})).y();
    const int from = project(display({2, 15.5F, 15.5F})).x();
    const int to = project(display({29, 15.5F, 15.5F})).x();
    const int curveX = project(display({15.5F, 15.5F, 15.5F})).x();
    const int cellPixels = project(display({25.5F, 15.5F, 15.5F})).x() - curveX;
    ASSERT_GT(std::abs(cellPixels), 40) << "ten cells span a wide band on screen";
    int lit = 0, farthest = 0;
    for (int x = std::min(from, to); x <= std::max(from, to); ++x) {
        const QColor c = empty.pixelColor(x, row);
        if (channelDistance(cut.pixelColor(x, row), {c.redF(), c.greenF(), c.blueF()}) <= 8)
            continue;
        ++lit;
        farthest = std::max(farthest, std::abs(x - curveX));
    }
    EXPECT_GE(lit, 2) << "the curve is drawn";
    EXPECT_LE(lit, 6) << "a few pixels wide, not an area";
    EXPECT_LE(farthest, 6) << "where the sheet meets the plane";
}

TEST_F(RemovalTest, ChangingTheThresholdsChangesOnlyMembersInTheBand) {
    // Four concentric spheres of radius 8, 7, 6, 5 (offsets 0, -1, -2, -3): the fields differ by
    // constants, so each member's outlyingness is constant: sum_j (d_j - d_i)^2 / 4 = 3.5, 1.5,
    // 1.5, 3.5 for offsets 0, -1, -2, -3.
    const glm::vec3 centre{15.5F, 15.5F, 15.5F};
    show(spheres({centre, centre, centre, centre}, {0, -1, -2, -3}),
         {kOrange, kOrange, kOrange, kOrange});
    m_renderer.settings().showMean = false;
    // A silhouette is about tau display units wide (0.4 cells): the rings do not overlap.
    m_renderer.settings().thickness = 0.013F;
    m_renderer.settings().removal = true;
    m_renderer.settings().groupSize = 1;
    m_renderer.settings().removalMin = 0.0F;
    m_renderer.settings().removalMax = 1.0F;
    const QImage base = draw();
    m_renderer.settings().removalMax = 1.4F;  // every member still above the band
    EXPECT_EQ(test::differingFraction(base, draw(), 0), 0.0);

    m_renderer.settings().removalMax = 2.0F;  // the band now holds 1.5: radii 7 and 6 fade
    const QImage changed = draw();
    const QPoint middle = project(display(centre));
    const auto ringRadius = [&](float cells) {
        const QPoint rim = project(display(centre + glm::vec3(cells, 0, 0)));
        return static_cast<double>(rim.x() - middle.x());
    };
    // A silhouette lies on and just inside its sphere's outline: the middle of each ring is
    // taken a quarter cell inside the outline.
    const double cell = ringRadius(8) - ringRadius(7);
    const std::array<double, 4> rings{ringRadius(8) - 0.25 * cell, ringRadius(7) - 0.25 * cell,
                                      ringRadius(6) - 0.25 * cell, ringRadius(5) - 0.25 * cell};
    std::array<int, 4> changedNear{0, 0, 0, 0};
    for (int y = 0; y < base.height(); ++y) {
        for (int x = 0; x < base.width(); ++x) {
            // A pixel counts as changed when a channel moved by more than a tenth: the
            // antialiased fringe of a fading ring may tint its neighbour ring's pixels faintly.
            const QRgb a = base.pixel(x, y), b = changed.pixel(x, y);
            if (std::max({std::abs(qRed(a) - qRed(b)), std::abs(qGreen(a) - qGreen(b)),
                          std::abs(qBlue(a) - qBlue(b))}) <= 25) {
                continue;
            }
            const double r = std::hypot(x - middle.x(), y - middle.y());
            std::size_t nearest = 0;
            for (std::size_t i = 1; i < rings.size(); ++i)
                if (std::abs(r - rings[i]) < std::abs(r - rings[nearest])) nearest = i;
            ++changedNear[nearest];
        }
    }
    EXPECT_EQ(changedNear[0], 0) << "radius 8 has outlyingness 3.5, outside the band";
    EXPECT_GT(changedNear[1], 20) << "radius 7 has outlyingness 1.5";
    EXPECT_GT(changedNear[2], 20) << "radius 6 has outlyingness 1.5";
    EXPECT_EQ(changedNear[3], 0) << "radius 5 has outlyingness 3.5";
}

// The plane's cut through the box: a square for a horizontal plane, a hexagon for the plane
// through the centre across the main diagonal, nothing for one outside; corners in order.
TEST(PlaneBoxPolygon, IsTheCutThroughTheBoxInOrder) {
    const glm::vec3 lo{0.0F}, hi{1.0F, 1.0F, 0.2F};
    const auto square =
        gl::planeBoxPolygon(gl::CuttingPlane::through({0, 0, 1}, {0, 0, 0.1F}), lo, hi);
    ASSERT_EQ(square.size(), 4U);
    for (const glm::vec3& p : square) EXPECT_NEAR(p.z, 0.1F, 1e-6F);
    const auto hexagon =
        gl::planeBoxPolygon(gl::CuttingPlane::through({1, 1, 5}, 0.5F * (lo + hi)), lo, hi);
    EXPECT_EQ(hexagon.size(), 6U);
    // In order: consecutive corners share a face of the box (one coordinate at a bound).
    for (std::size_t i = 0; i < hexagon.size(); ++i) {
        const glm::vec3 a = hexagon[i], b = hexagon[(i + 1) % hexagon.size()];
        bool shared = false;
        for (int k = 0; k < 3; ++k) {
            shared = shared || (std::abs(a[k] - lo[k]) < 1e-5F && std::abs(b[k] - lo[k]) < 1e-5F) ||
                     (std::abs(a[k] - hi[k]) < 1e-5F && std::abs(b[k] - hi[k]) < 1e-5F);
        }
        EXPECT_TRUE(shared) << i;
    }
    EXPECT_TRUE(
        gl::planeBoxPolygon(gl::CuttingPlane::through({0, 0, 1}, {0, 0, 2}), lo, hi).empty());
}

// The cutting plane's filled cut face (METHODS.md section 18): a field whose value at every
// grid point is known by hand, cut by a plane that faces the camera, so each pixel of the face
// must show the colour of the value there, the members' curves stay on top of it, what lies
// behind it is hidden and not picked, and its colour bar is listed.
#include <QImage>
#include <cmath>
#include <limits>

#include "tests/gl/sphere_scene.h"

using namespace ensil;
using test::channelDistance;
using test::spheres;
using SectionTest = test::SphereSceneTest;

namespace {
constexpr glm::vec3 kOrange{1.0F, 0.5F, 0.0F};
// The field on the 32^3 grid: f = i + 2k (x and z grid indices), from 0 to 93; missing
// (NaN) where i < 4.
constexpr float kLargest = 31.0F + 2.0F * 31.0F;
float fieldAt(float i, float k) { return i + 2.0F * k; }

gl::SectionVolume handMadeVolume(const data::Grid& grid) {
    gl::SectionVolume volume;
    volume.values.resize(grid.pointCount());
    for (std::size_t k = 0; k < grid.nz(); ++k) {
        for (std::size_t j = 0; j < grid.ny(); ++j) {
            for (std::size_t i = 0; i < grid.nx(); ++i) {
                volume.values[grid.index(i, j, k)] =
                    i < 4 ? std::numeric_limits<float>::quiet_NaN()
                          : fieldAt(static_cast<float>(i), static_cast<float>(k));
            }
        }
    }
    volume.minimum = 0.0F;
    volume.maximum = kLargest;
    volume.quantity = QStringLiteral("mean f");
    volume.units = QStringLiteral("K");
    return volume;
}
}  // namespace

TEST_F(SectionTest, EachPixelOfTheFaceShowsTheColourOfTheFieldThere) {
    // A sphere wholly behind the plane y = 10 (its centre at y = 22, radius 8).
    const data::Ensemble e = spheres({{15.5F, 22.0F, 15.5F}});
    show(e, {kOrange});
    m_renderer.settings().showMean = false;
    m_renderer.setSectionVolume(handMadeVolume(e.grid));
    m_renderer.settings().plane = gl::CuttingPlane::through({0, 1, 0}, display({0, 10, 0}));
    m_renderer.settings().plane.fill = gl::SectionField::Mean;
    ASSERT_TRUE(m_renderer.sectionShown());
    const QImage image = draw();
    int checked = 0;
    for (const float i : {6.0F, 11.5F, 17.0F, 25.25F, 29.0F}) {
        for (const float k : {3.0F, 12.5F, 20.0F, 28.0F}) {
            const QPoint pixel = project(display({i, 10, k}));
            const glm::vec3 expected = gl::viridis(fieldAt(i, k) / kLargest);
            EXPECT_LE(channelDistance(image.pixelColor(pixel), expected), 6)
                << "at grid (" << i << ", 10, " << k << ")";
            ++checked;
        }
    }
    EXPECT_EQ(checked, 20);
    // Where the field is missing the face is gray, not a colour of the scale.
    const QColor missing = image.pixelColor(project(display({1.5F, 10, 15})));
    EXPECT_LE(channelDistance(missing, glm::vec3(0.5F)), 6);
    // The sphere behind the face is hidden by it: its centre shows the field, not orange.
    const QPoint centre = project(display({15.5F, 10, 15.5F}));
    EXPECT_LE(
        channelDistance(image.pixelColor(centre), gl::viridis(fieldAt(15.5F, 15.5F) / kLargest)),
        6);

    // Without a fill the same plane leaves the sphere in view.
    m_renderer.settings().plane.fill = gl::SectionField::None;
    EXPECT_FALSE(m_renderer.sectionShown());
    const QImage unfilled = draw();
    EXPECT_GT(channelDistance(unfilled.pixelColor(project(display({6, 10, 3}))),
                              gl::viridis(fieldAt(6, 3) / kLargest)),
              40);
}

TEST_F(SectionTest, TheCurvesOfMembersCrossingThePlaneAreDrawnOverTheFace) {
    // A sphere centred on the plane y = 10: it crosses the face in a circle of radius 8.
    const data::Ensemble e = spheres({{15.5F, 10.0F, 15.5F}});
    show(e, {kOrange});
    m_renderer.settings().showMean = false;
    m_renderer.setSectionVolume(handMadeVolume(e.grid));
    m_renderer.settings().plane = gl::CuttingPlane::through({0, 1, 0}, display({0, 10, 0}));
    m_renderer.settings().plane.thickness = 0.6F / 31.0F;
    // Points of the circle where the member's curve changes the picture (within 2 pixels,
    // by more than 30 in a channel): drawn with the member and without it.
    const auto pointsOnTheCurve = [&] {
        m_renderer.setAppearance({{kOrange, true, false}});
        const QImage with = draw();
        m_renderer.setAppearance({{kOrange, false, false}});
        const QImage without = draw();
        int found = 0;
        for (int a = 0; a < 32; ++a) {
            const float angle = static_cast<float>(a) * 6.2831853F / 32.0F;
            const glm::vec3 p{15.5F + 8.0F * std::cos(angle), 10.0F,
                              15.5F + 8.0F * std::sin(angle)};
            const QPoint pixel = project(display(p));
            int largest = 0;
            for (int dx = -2; dx <= 2; ++dx) {
                for (int dy = -2; dy <= 2; ++dy) {
                    const QColor c = with.pixelColor(pixel + QPoint(dx, dy));
                    const QColor d = without.pixelColor(pixel + QPoint(dx, dy));
                    largest =
                        std::max({largest, std::abs(c.red() - d.red()),
                                  std::abs(c.green() - d.green()), std::abs(c.blue() - d.blue())});
                }
            }
            found += largest > 30;
        }
        return found;
    };
    const int unfilled = pointsOnTheCurve();
    m_renderer.settings().plane.fill = gl::SectionField::Mean;
    const int filled = pointsOnTheCurve();
    EXPECT_GE(unfilled, 30);
    EXPECT_GE(filled, unfilled) << "the face hides none of the member's curve";
}

TEST_F(SectionTest, PickingTheFaceGivesItsPointAndValueAndNotTheMemberBehindIt) {
    const data::Ensemble e = spheres({{15.5F, 22.0F, 15.5F}});
    show(e, {kOrange});
    m_renderer.settings().showMean = false;
    m_renderer.settings().mode = gl::RenderMode::OpaqueSurfaces;  // the sphere's face is drawn
    m_renderer.setSectionVolume(handMadeVolume(e.grid));
    m_renderer.settings().plane = gl::CuttingPlane::through({0, 1, 0}, display({0, 10, 0}));
    (void)draw();
    const QPoint centre = project(display({15.5F, 10, 15.5F}));
    const gl::PickResult unfilled = m_renderer.pick(centre.x(), centre.y(), 0);
    EXPECT_EQ(unfilled.member, 0) << "without a fill the sphere is seen through the plane";
    EXPECT_FALSE(unfilled.section);

    m_renderer.settings().plane.fill = gl::SectionField::Mean;
    (void)draw();
    const QPoint at = project(display({20.0F, 10, 7.0F}));
    const gl::PickResult hit = m_renderer.pick(at.x(), at.y(), 0);
    ASSERT_TRUE(hit.section);
    const glm::dvec3 index = m_renderer.frame().displayToIndex(*hit.section);
    EXPECT_NEAR(index.y, 10.0, 0.05);
    EXPECT_NEAR(m_renderer.sectionValueAt(*hit.section),
                fieldAt(static_cast<float>(index.x), static_cast<float>(index.z)), 1e-3);
    EXPECT_NEAR(index.x, 20.0, 0.6);
    EXPECT_NEAR(index.z, 7.0, 0.6);
    const gl::PickResult behind = m_renderer.pick(centre.x(), centre.y(), 0);
    EXPECT_EQ(behind.member, -1) << "the sphere lies behind the face";
    EXPECT_TRUE(behind.section);
}

TEST_F(SectionTest, TheSectionsColourBarIsListedAfterTheFloors) {
    const data::Ensemble e = spheres({{15.5F, 22.0F, 15.5F}});
    show(e, {kOrange});
    m_renderer.setFloorMap(gl::FloorMap::spanning(std::vector<float>(32 * 32, 1.0F),
                                                  QStringLiteral("floor: column maximum")));
    m_renderer.setSectionVolume(handMadeVolume(e.grid));
    m_renderer.settings().plane = gl::CuttingPlane::through({0, 1, 0}, display({0, 10, 0}));
    EXPECT_EQ(m_renderer.overlay(kWidth, kHeight).colourScales.size(), 1u)
        << "no fill: the floor's";
    m_renderer.settings().plane.fill = gl::SectionField::StandardDeviation;
    const gl::ViewOverlay overlay = m_renderer.overlay(kWidth, kHeight);
    ASSERT_EQ(overlay.colourScales.size(), 2u);
    EXPECT_EQ(overlay.colourScales[1].caption, QStringLiteral("section: mean f [K]"));
    EXPECT_EQ(overlay.colourScales[1].maximum, kLargest);
}

TEST_F(SectionTest, TheContextSurfaceTakesTheColourOfTheSpreadWhereItLies) {
    // One sphere; its mean (itself) drawn solid as the context, the member hidden. The spread
    // rises with height: 0 at the bottom of the box, 31 at its top.
    const data::Ensemble e = spheres({{15.5F, 15.5F, 15.5F}});
    show(e, {kOrange});
    m_renderer.setAppearance({{kOrange, false, false}});
    m_renderer.settings().showMean = true;
    m_renderer.settings().meanOpacity = 1.0F;
    gl::SectionVolume spread;
    spread.values.resize(e.grid.pointCount());
    for (std::size_t k = 0; k < 32; ++k) {
        for (std::size_t j = 0; j < 32; ++j) {
            for (std::size_t i = 0; i < 32; ++i) {
                spread.values[e.grid.index(i, j, k)] = static_cast<float>(k);
            }
        }
    }
    spread.maximum = 31.0F;
    spread.quantity = QStringLiteral("standard deviation of f");
    spread.units = QStringLiteral("K");
    m_renderer.setSpreadVolume(spread);
    // Points on the sphere's side facing the camera, high and low.
    const float side = std::sqrt(64.0F - 36.0F);
    const QPoint high = project(display({15.5F, 15.5F - side, 21.5F}));
    const QPoint low = project(display({15.5F, 15.5F - side, 9.5F}));
    const QImage gray = draw();
    const QColor g = gray.pixelColor(high);
    EXPECT_LE(std::max({std::abs(g.red() - g.green()), std::abs(g.green() - g.blue())}), 8)
        << "without it, gray";
    EXPECT_EQ(m_renderer.overlay(kWidth, kHeight).colourScales.size(), 0u);

    m_renderer.settings().contextBySpread = true;
    const QImage coloured = draw();
    // High up the spread is large (viridis' yellow-green end: more green than blue), low down
    // it is small (its purple-blue end: more blue than green; compared as a ratio, since the
    // low point lies where the surface turns away from the light and shading darkens both).
    const QColor top = coloured.pixelColor(high), bottom = coloured.pixelColor(low);
    EXPECT_GT(top.green(), top.blue() + 30) << top.name().toStdString();
    EXPECT_GT(bottom.blue(), 1.3 * bottom.green()) << bottom.name().toStdString();
    const gl::ViewOverlay overlay = m_renderer.overlay(kWidth, kHeight);
    ASSERT_EQ(overlay.colourScales.size(), 1u);
    EXPECT_EQ(overlay.colourScales[0].caption,
              QStringLiteral("context: standard deviation of f [K]"));
}

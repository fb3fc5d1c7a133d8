#include "gl/renderer.h"

#include <gtest/gtest.h>

#include <QColor>
#include <cmath>
#include <glm/vec4.hpp>
#include <limits>

#include "data/demo_ensemble.h"
#include "tests/gl/renderer_fixture.h"
#include "tests/support/image_compare.h"
#include "tests/support/offscreen_gl.h"

using namespace ensil;

namespace {
constexpr int kTolerance = 12;  // per channel, out of 255

bool near(const QColor& c, const glm::vec4& expected, int tolerance = kTolerance) {
    return std::abs(c.red() - static_cast<int>(std::lround(expected.r * 255))) <= tolerance &&
           std::abs(c.green() - static_cast<int>(std::lround(expected.g * 255))) <= tolerance &&
           std::abs(c.blue() - static_cast<int>(std::lround(expected.b * 255))) <= tolerance;
}

// Any pixel in the (2r+1)^2 neighbourhood has the colour.
bool colourNear(const QImage& image, QPoint p, const glm::vec4& colour, int r = 2) {
    for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; ++dx) {
            const QPoint q = p + QPoint(dx, dy);
            if (image.rect().contains(q) && near(image.pixelColor(q), colour)) return true;
        }
    return false;
}
}  // namespace

class RendererTest : public test::RendererFixture {
protected:
    data::DemoEnsemble demo() const {
        return data::makeDemoEnsemble({.members = 3, .nx = 48, .ny = 24, .nz = 8, .seed = 5});
    }
};

TEST_F(RendererTest, WithoutDataEveryPixelIsBackground) {
    const QImage image = draw();
    for (QPoint p :
         {QPoint(0, 0), QPoint(kWidth / 2, kHeight / 2), QPoint(kWidth - 1, kHeight - 1)}) {
        EXPECT_TRUE(near(image.pixelColor(p), gl::Renderer::kDefaultBackground, 1))
            << p.x() << "," << p.y();
    }
}

TEST_F(RendererTest, BoxCornersAppearWhereTheCameraProjectsThem) {
    const auto d = demo();
    m_renderer.setGrid(d.ensemble.grid);
    const QImage image = draw();
    const glm::vec3 lo = m_renderer.frame().boxMin(), hi = m_renderer.frame().boxMax();
    int found = 0;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p{corner & 1 ? hi.x : lo.x, corner & 2 ? hi.y : lo.y,
                          corner & 4 ? hi.z : lo.z};
        const QPoint px = project(p);
        ASSERT_TRUE(image.rect().contains(px)) << "corner " << corner << " is off screen";
        found += colourNear(image, px, gl::Renderer::kBoxColor) ? 1 : 0;
    }
    EXPECT_EQ(found, 8) << "every box corner is an endpoint of visible edges";
    // The image corner is outside the box: background.
    EXPECT_TRUE(near(image.pixelColor(1, 1), gl::Renderer::kDefaultBackground, 1));
}

TEST_F(RendererTest, FloorShowsTheMapAndMissingValuesInGray) {
    const auto d = demo();
    const data::Grid& grid = d.ensemble.grid;
    m_renderer.setGrid(grid);
    m_renderer.setBackground({0, 0, 0, 1});
    // Left half of the map at the minimum (viridis dark purple), right half missing (gray).
    std::vector<float> values(grid.nx() * grid.ny());
    for (std::size_t j = 0; j < grid.ny(); ++j)
        for (std::size_t i = 0; i < grid.nx(); ++i)
            values[i + grid.nx() * j] =
                i < grid.nx() / 2 ? 0.0F : std::numeric_limits<float>::quiet_NaN();
    m_renderer.setFloorMap({values, 0.0F, 1.0F, {}});
    const QImage image = draw();
    const glm::vec3 hi = m_renderer.frame().boxMax();
    const QPoint left = project({0.2F * hi.x, 0.5F * hi.y, 0.0F});
    const QPoint right = project({0.8F * hi.x, 0.5F * hi.y, 0.0F});
    EXPECT_TRUE(near(image.pixelColor(left), {0.267F, 0.005F, 0.329F, 1.0F}, 16))
        << image.pixelColor(left).name().toStdString();
    EXPECT_TRUE(near(image.pixelColor(right), {0.5F, 0.5F, 0.5F, 1.0F}, 4))
        << image.pixelColor(right).name().toStdString();
}

TEST_F(RendererTest, FloorMapFollowsAxisDirectionNorthStaysNorth) {
    // Latitude stored from north to south, as ERA5 does; the map marks the northern half.
    data::Axis lat = data::makeUniformAxis("lat", "degrees_north", 60.0, 30.0, 16);
    const data::Grid grid(data::makeUniformAxis("lon", "degrees_east", 0.0, 60.0, 16), lat,
                          data::makeUniformAxis("z", "km", 0.0, 10.0, 3));
    m_renderer.setGrid(grid);
    std::vector<float> values(16 * 16);
    for (std::size_t j = 0; j < 16; ++j)
        for (std::size_t i = 0; i < 16; ++i)
            values[i + 16 * j] = grid.y().values[j] > 45.0 ? 1.0F : 0.0F;
    m_renderer.setFloorMap({values, 0.0F, 1.0F, {}});
    const QImage image = draw();
    const glm::vec3 hi = m_renderer.frame().boxMax();
    const QPoint north = project({0.5F * hi.x, 0.85F * hi.y, 0.0F});
    const QPoint south = project({0.5F * hi.x, 0.15F * hi.y, 0.0F});
    const glm::vec4 yellow{0.993F, 0.906F, 0.144F, 1.0F}, purple{0.267F, 0.005F, 0.329F, 1.0F};
    EXPECT_TRUE(near(image.pixelColor(north), yellow, 20))
        << image.pixelColor(north).name().toStdString();
    EXPECT_TRUE(near(image.pixelColor(south), purple, 20))
        << image.pixelColor(south).name().toStdString();
}

TEST_F(RendererTest, VerticalExaggerationRaisesTheTopOfTheBox) {
    const auto d = demo();
    m_renderer.setGrid(d.ensemble.grid);
    const float flat = m_renderer.frame().boxMax().z;
    m_renderer.setVerticalExaggeration(4.0F);
    EXPECT_FLOAT_EQ(m_renderer.frame().boxMax().z, 4.0F * flat);
}

TEST_F(RendererTest, DemoSceneMatchesBaseline) {
    const auto d = demo();
    const data::Grid& grid = d.ensemble.grid;
    m_renderer.setGrid(grid);
    // Column maximum of member 1 as the floor map, computed here to keep gl free of
    // preprocessing.
    std::vector<float> map(grid.nx() * grid.ny(), 0.0F);
    for (std::size_t k = 0; k < grid.nz(); ++k)
        for (std::size_t p = 0; p < map.size(); ++p)
            map[p] = std::max(map[p], d.ensemble.members[0].values[k * map.size() + p]);
    m_renderer.setFloorMap({map, 0.0F, 80.0F, {}});
    const QImage image = draw();
    const test::ImageComparison result = test::compareWithBaseline(image, "renderer_demo_scene");
    EXPECT_TRUE(result.passed) << result.message.toStdString();
}

TEST(RendererSelection, AFewSelectedAreSolidAndACrowdIsNot) {
    // Brushing once selected ~40 of 50 members and drew 40 solid, z-fighting surfaces.
    gl::Renderer renderer;
    std::vector<gl::MemberAppearance> look(6);
    EXPECT_FALSE(renderer.selectionShown().any);
    renderer.setAppearance(look);
    EXPECT_FALSE(renderer.selectionShown().any) << "nothing selected: nothing dimmed";
    for (int m = 0; m < gl::Renderer::kMaxSolidSelection; ++m)
        look[static_cast<std::size_t>(m)].selected = true;
    renderer.setAppearance(look);
    EXPECT_TRUE(renderer.selectionShown().any);
    EXPECT_TRUE(renderer.selectionShown().solid) << "a few: solid surfaces, as in the paper";
    look[4].selected = true;
    renderer.setAppearance(look);
    EXPECT_FALSE(renderer.selectionShown().solid) << "more: semi-transparent surfaces";
    look[5].selected = true;
    look[5].visible = false;  // hidden members do not count
    look[4].selected = false;
    renderer.setAppearance(look);
    EXPECT_TRUE(renderer.selectionShown().solid);
    renderer.settings().mode = gl::RenderMode::OpaqueSurfaces;
    for (auto& a : look) a.selected = true;
    renderer.setAppearance(look);
    EXPECT_TRUE(renderer.selectionShown().solid) << "opaque surfaces stay opaque";
    renderer.settings().mode = gl::RenderMode::ShadedSilhouettes;
    renderer.setAnimatedMember(2);
    EXPECT_TRUE(renderer.selectionShown().solid) << "the animated member is one solid surface";
}

namespace {
// The largest |x| or |y| in normalised device coordinates of the box's corners.
float boxReach(const gl::Renderer& renderer, float aspect) {
    const glm::vec3 lo = renderer.frame().boxMin(), hi = renderer.frame().boxMax();
    float reach = 0.0F;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec4 c = renderer.camera().viewProjection(aspect) *
                            glm::vec4(corner & 1 ? hi.x : lo.x, corner & 2 ? hi.y : lo.y,
                                      corner & 4 ? hi.z : lo.z, 1.0F);
        reach = std::max({reach, std::abs(c.x / c.w), std::abs(c.y / c.w)});
    }
    return reach;
}
}  // namespace

TEST(RendererCamera, AResetViewIsFramedAgainWhenTheViewChangesShapeAndAMovedOneIsNot) {
    gl::Renderer renderer;  // no GL needed: the camera and the frame only
    const auto d = data::makeDemoEnsemble({.members = 2, .nx = 48, .ny = 24, .nz = 8, .seed = 5});
    renderer.setViewSize(1600, 1000);
    renderer.setGrid(d.ensemble.grid);  // framed for 1.6:1
    ASSERT_LE(boxReach(renderer, 1.6F), 0.81F);
    // The window becomes tall and narrow: the reset view is framed again, whole.
    renderer.setViewSize(500, 1000);
    EXPECT_LE(boxReach(renderer, 0.5F), 0.81F) << "the box sticks out of the narrow view";
    EXPECT_GE(boxReach(renderer, 0.5F), 0.7F) << "and still fills it";
    // A camera the user turned stays where it is.
    renderer.camera().orbit(40.0F, 0.0F);
    const float distance = renderer.camera().distance();
    renderer.setViewSize(1600, 1000);
    EXPECT_EQ(renderer.camera().distance(), distance);
}

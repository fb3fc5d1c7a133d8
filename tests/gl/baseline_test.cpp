// Image baselines (llvmpipe, 320 x 240, tolerance of tests/support/image_compare.h: a pixel
// differs beyond 24/255 in a channel, at most 0.5 % of pixels may differ) for every mode, and
// for removal, the cutting plane and a selection each on and off. The scene: three spheres of
// radii 7, 8 and 9.5 at different centres, overlapping, with the mean, seen from the
// south-west above.
// Regenerate with ENSIL_UPDATE_BASELINES=1 after a deliberate change, and look at them.
#include "preprocessing/mesh_packing.h"
#include "tests/gl/sphere_scene.h"

using namespace ensil;
using test::spheres;

namespace {
struct Variant {
    const char* name;
    gl::RenderMode mode = gl::RenderMode::ShadedSilhouettes;
    bool removal = false;
    bool plane = false;
    bool selection = false;
};

class BaselineTest : public test::SphereSceneTest, public ::testing::WithParamInterface<Variant> {};
}  // namespace

TEST_P(BaselineTest, MatchesItsBaseline) {
    const Variant v = GetParam();
    show(spheres({{12, 15.5F, 15.5F}, {17, 15, 17}, {19, 17.5F, 13}}, {-1.0F, 0.0F, 1.5F}),
         {gl::clusterColor(0), gl::clusterColor(1), gl::clusterColor(2)});
    m_renderer.camera().setAngles(-60.0F, 25.0F);
    m_renderer.camera().fit(m_renderer.frame().center(), 0.5F);
    gl::RenderSettings& s = m_renderer.settings();
    s.mode = v.mode;
    s.thickness = 0.02F;
    s.surfaceAlpha = 0.3F;
    if (v.removal) {
        // Over the lower 60 % of the outlyingness found on the surfaces, two groups: where
        // the spheres lie near the mean their silhouettes fade.
        s.removal = true;
        s.removalMin = 0.0F;
        s.removalMax = 0.6F * prep::maximumOutlyingness(*m_renderer.meshes());
        s.groupSize = 2;
    }
    if (v.plane) {
        s.plane = gl::CuttingPlane::acrossBox({1.0F, 0.0F, 0.3F}, 0.1F, m_renderer.frame().boxMin(),
                                              m_renderer.frame().boxMax());
        s.plane.thickness = 0.008F;
    }
    if (v.selection) {
        m_renderer.setAppearance({{gl::clusterColor(0), true, false, 0},
                                  {gl::clusterColor(1), true, true, 1},
                                  {gl::clusterColor(2), true, false, 2}});
    }
    const test::ImageComparison result =
        test::compareWithBaseline(draw(), QStringLiteral("baseline_%1").arg(v.name));
    EXPECT_TRUE(result.passed) << result.message.toStdString();
}

INSTANTIATE_TEST_SUITE_P(
    EveryModeAndOption, BaselineTest,
    ::testing::Values(Variant{"shaded"}, Variant{"spaghetti", gl::RenderMode::Spaghetti},
                      Variant{"surfaces", gl::RenderMode::Surfaces},
                      Variant{"opaque", gl::RenderMode::OpaqueSurfaces},
                      Variant{"shaded_removal", gl::RenderMode::ShadedSilhouettes, true},
                      Variant{"shaded_plane", gl::RenderMode::ShadedSilhouettes, false, true},
                      Variant{"surfaces_plane", gl::RenderMode::Surfaces, false, true},
                      Variant{"shaded_selection", gl::RenderMode::ShadedSilhouettes, false, false,
                              true}),
    [](const ::testing::TestParamInfo<Variant>& variant) {
        return std::string(variant.param.name);
    });

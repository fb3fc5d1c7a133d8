// The geometry shader that drops triangles, and clips the rest to the parts that can hold a
// silhouette, a plane curve or a fragment density-based removal keeps, must not change the
// picture: real meshes of varied curvature (the demo ensemble), every silhouette mode, thin and
// thick tau, with and without a cutting plane or removal, from afar and close up in perspective
// (where the view vector turns most across a triangle), drawn with culling on and off.
#include <gtest/gtest.h>

#include "data/demo_ensemble.h"
#include "gl/palette.h"
#include "gl/renderer.h"
#include "preprocessing/clustering.h"
#include "preprocessing/mesh_packing.h"
#include "tests/gl/sphere_scene.h"

using namespace ensil;

namespace {
// The share of pixels allowed to differ. Since the picture is multisampled, a pixel on a band's
// edge is drawn from its centre's values into the samples the (clipped or whole) triangle
// covers, and a few such pixels differ by a sample; without the antialiasing margins in the
// culling shader 0.5 to 5 % of the pixels differ.
constexpr double kTolerance = 1.5e-3;

class SilhouetteCullingTest : public test::OffscreenGlTest {
protected:
    void SetUp() override {
        test::OffscreenGlTest::SetUp();
        if (IsSkipped() || HasFatalFailure()) return;
        m_renderer.initialize();
        const auto demo =
            data::makeDemoEnsemble({.members = 8, .nx = 96, .ny = 48, .nz = 12, .seed = 2});
        const data::Ensemble& e = demo.ensemble;
        m_renderer.setGrid(e.grid);
        m_renderer.setVerticalExaggeration(3.0F);
        m_meshes = test::meshesOf(e, 30.0F, 3.0F);
        m_renderer.setMeshes(m_meshes);
        std::vector<int> labels(e.memberCount());
        for (std::size_t m = 0; m < labels.size(); ++m) labels[m] = static_cast<int>(m % 4);
        m_renderer.setAppearance(gl::clusterAppearance(labels));
        m_renderer.settings().showMean = false;
    }
    void TearDown() override {
        if (m_renderer.isInitialized()) m_renderer.releaseGpuResources();
        test::OffscreenGlTest::TearDown();
    }
    // Fraction of pixels that differ by more than 2/255 between culling on and off.
    double cullingDifference() {
        m_renderer.settings().silhouetteCulling = false;
        m_renderer.render(framebuffer(), kWidth, kHeight);
        const QImage all = grab();
        m_renderer.settings().silhouetteCulling = true;
        m_renderer.render(framebuffer(), kWidth, kHeight);
        const QImage culled = grab();
        QImage empty(all.size(), all.format());
        const glm::vec4 bg = gl::Renderer::kDefaultBackground;
        empty.fill(QColor::fromRgbF(bg.r, bg.g, bg.b));
        EXPECT_GT(test::differingFraction(all, empty, 8), 0.02) << "silhouettes should be drawn";
        return test::differingFraction(all, culled, 2);
    }
    gl::Renderer m_renderer;
    std::shared_ptr<const data::MeshSet> m_meshes;
};
}  // namespace

TEST_F(SilhouetteCullingTest, ShadedAndSpaghettiLookTheSameWithAndWithoutCulling) {
    for (const gl::RenderMode mode :
         {gl::RenderMode::ShadedSilhouettes, gl::RenderMode::Spaghetti}) {
        for (const float tau : {0.003F, 0.02F, 0.1F}) {
            m_renderer.settings().mode = mode;
            m_renderer.settings().thickness = tau;
            EXPECT_LE(cullingDifference(), kTolerance) << "mode " << int(mode) << " tau " << tau;
        }
    }
}

TEST_F(SilhouetteCullingTest, PlaneCurvesSurviveCulling) {
    const data::DisplayFrame& frame = m_renderer.frame();
    m_renderer.settings().plane =
        gl::CuttingPlane::acrossBox({0.3F, 1.0F, 0.2F}, 0.1F, frame.boxMin(), frame.boxMax());
    m_renderer.settings().plane.thickness = 0.01F;
    m_renderer.camera().setAngles(-60.0F, 40.0F);
    EXPECT_LE(cullingDifference(), kTolerance);
    m_renderer.camera().setProjection(gl::Camera::Projection::Orthographic);
    EXPECT_LE(cullingDifference(), kTolerance);
}

TEST_F(SilhouetteCullingTest, CloseUpPerspectiveLooksTheSame) {
    m_renderer.camera().setAngles(-35.0F, 20.0F);
    m_renderer.camera().zoom(3.0F);
    for (const gl::RenderMode mode :
         {gl::RenderMode::ShadedSilhouettes, gl::RenderMode::Spaghetti}) {
        for (const float tau : {0.003F, 0.05F}) {
            m_renderer.settings().mode = mode;
            m_renderer.settings().thickness = tau;
            EXPECT_LE(cullingDifference(), kTolerance) << "mode " << int(mode) << " tau " << tau;
        }
    }
}

TEST_F(SilhouetteCullingTest, DensityBasedRemovalLooksTheSame) {
    const float top = prep::maximumOutlyingness(*m_meshes);
    ASSERT_GT(top, 0.0F);
    m_renderer.settings().removal = true;
    m_renderer.settings().groupSize = 3;
    m_renderer.settings().removalMin = 0.05F * top;
    m_renderer.settings().removalMax = 0.6F * top;
    m_renderer.settings().thickness = 0.05F;
    m_renderer.settings().showMean = true;
    for (const gl::RenderMode mode :
         {gl::RenderMode::ShadedSilhouettes, gl::RenderMode::Spaghetti}) {
        m_renderer.settings().mode = mode;
        EXPECT_LE(cullingDifference(), kTolerance) << "mode " << int(mode);
    }
    // With a plane, the curves are kept whatever the removal says.
    const data::DisplayFrame& frame = m_renderer.frame();
    m_renderer.settings().plane =
        gl::CuttingPlane::acrossBox({0.0F, 1.0F, 0.0F}, 0.0F, frame.boxMin(), frame.boxMax());
    EXPECT_LE(cullingDifference(), kTolerance);
}

// The renderer's scene targets kept across the view's switches between motion frames (a reduced
// resolution) and still frames, and a larger set left behind released.
#include "gl/render_targets.h"

#include <gtest/gtest.h>

#include <QOpenGLContext>
#include <QOpenGLVersionFunctionsFactory>

#include "tests/support/offscreen_gl.h"

using namespace ensil;

namespace {
class Targets : public test::OffscreenGlTest {
protected:
    void SetUp() override {
        OffscreenGlTest::SetUp();
        if (IsSkipped() || HasFatalFailure()) return;
        f = QOpenGLVersionFunctionsFactory::get<gl::GlFunctions>(QOpenGLContext::currentContext());
        ASSERT_NE(f, nullptr);
    }
    void TearDown() override {
        if (f != nullptr) targets.release(*f);
        OffscreenGlTest::TearDown();
    }
    gl::GlFunctions* f = nullptr;
    gl::RenderTargets targets;
};
constexpr int kSamples = 4;
}  // namespace

TEST_F(Targets, StillAndMotionFramesInTurnMakeEachSizeOnce) {
    targets.ensure(*f, 400, 300, kSamples);
    const GLuint still = targets.sceneFramebuffer();
    for (int turn = 0; turn < 3; ++turn) {
        targets.ensure(*f, 100, 75, kSamples, /*reduced=*/true);  // motion
        EXPECT_NE(targets.sceneFramebuffer(), still);
        targets.ensure(*f, 400, 300, kSamples);  // still
        EXPECT_EQ(targets.sceneFramebuffer(), still);
    }
    EXPECT_EQ(targets.setsMade(), 2u) << "one set a size, however often the view switches";
    EXPECT_EQ(targets.pixelsHeld(), 400LL * 300 + 100LL * 75);
}

TEST_F(Targets, ALargerSetLeftByAFullResolutionFrameIsReleased) {
    targets.ensure(*f, 400, 300, kSamples);
    targets.ensure(*f, 1600, 1200, kSamples);  // a picture exported larger than the view
    EXPECT_EQ(targets.pixelsHeld(), 400LL * 300 + 1600LL * 1200)
        << "the view's set stays for the view's next frame";
    targets.ensure(*f, 400, 300, kSamples);
    EXPECT_EQ(targets.pixelsHeld(), 400LL * 300) << "the export's set goes";
    EXPECT_EQ(targets.setsMade(), 2u);
    // A third size replaces the set not in use.
    targets.ensure(*f, 200, 150, kSamples, /*reduced=*/true);
    targets.ensure(*f, 300, 200, kSamples, /*reduced=*/true);
    EXPECT_EQ(targets.pixelsHeld(), 200LL * 150 + 300LL * 200);
    EXPECT_EQ(targets.setsMade(), 4u);
}

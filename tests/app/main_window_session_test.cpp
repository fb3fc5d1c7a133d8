// The workbench's session model: every control writes into the session and the bindings show
// it everywhere, so the view, the panels, a saved project and undo never disagree.
#include <gtest/gtest.h>

#include <QAction>
#include <QDoubleSpinBox>
#include <QSignalSpy>
#include <QTest>

#include "app/main_window.h"
#include "session/session_history.h"
#include "tests/app/workbench_helpers.h"
#include "tests/support/scoped_cache_home.h"
#include "widgets/cutting_plane_panel.h"
#include "widgets/render_panel.h"
#include "widgets/render_toolbar.h"
#include "widgets/silhouette_view.h"
#include "workbench/isovalue_session.h"
#include "workbench/member_selection.h"

using namespace ensil;

namespace {
using SessionBindings = test::SmallDemoWorkbench;
}  // namespace

TEST_F(SessionBindings, EveryControlWritesIntoTheSessionThatIsSaved) {
    window.renderPanel()->findChild<QDoubleSpinBox*>("surface_opacity")->setValue(0.55);
    window.renderPanel()->setMode(gl::RenderMode::Surfaces);
    window.memberSelection()->setClusterCount(3);  // as the dendrogram's cut line does
    window.memberSelection()->setMemberVisible(1, false);
    const session::SessionState saved = window.captureSession();
    EXPECT_FLOAT_EQ(saved.render.surfaceAlpha, 0.55F);
    EXPECT_EQ(saved.render.mode, gl::RenderMode::Surfaces);
    EXPECT_EQ(saved.clusters, 3);
    EXPECT_EQ(window.renderToolbar()->clusterCount(), 3) << "the toolbar follows the session";
    EXPECT_EQ(saved.hiddenMembers, std::vector<int>{1});
    // The view draws exactly what the session holds.
    EXPECT_FLOAT_EQ(window.view()->renderer().settings().surfaceAlpha, 0.55F);
    EXPECT_EQ(window.view()->renderer().settings().mode, gl::RenderMode::Surfaces);
}

TEST_F(SessionBindings, AnExaggerationKeepsThePlaneAcrossTheBoxAndUndoPutsBothBack) {
    ui::CuttingPlanePanel* plane = window.cuttingPlanePanel();
    plane->setOrientation(ui::CuttingPlanePanel::AlongZ);
    plane->setPosition(0.3);
    plane->setCutting(true);
    QCoreApplication::processEvents();  // the plane's own undo step is recorded (queued)
    const float offsetBefore = window.view()->renderer().settings().plane.offset;
    QSignalSpy built(window.isovalueSession(), &workbench::IsovalueSession::finished);
    window.renderPanel()->control("vertical_exaggeration")->showValue(1.0);
    window.renderPanel()->findChild<QDoubleSpinBox*>("vertical_exaggeration")->setValue(3.0);
    ASSERT_TRUE(built.wait(60000)) << "a new exaggeration rebuilds the attributes";
    EXPECT_FLOAT_EQ(window.view()->renderer().frame().verticalExaggeration(), 3.0F);
    EXPECT_NEAR(plane->position(), 0.3, 1e-3) << "the plane keeps its place across the box";
    EXPECT_NE(window.view()->renderer().settings().plane.offset, offsetBefore);
    EXPECT_FLOAT_EQ(window.captureSession().render.plane.offset,
                    window.view()->renderer().settings().plane.offset);
    ASSERT_TRUE(QTest::qWaitFor(
        [&] { return window.history()->stack()->undoText().startsWith("Vertical exaggeration"); },
        10000))
        << window.history()->stack()->undoText().toStdString();
    window.history()->stack()->undo();
    ASSERT_TRUE(built.wait(60000));
    EXPECT_FLOAT_EQ(window.view()->renderer().frame().verticalExaggeration(), 1.0F);
    EXPECT_NEAR(window.view()->renderer().settings().plane.offset, offsetBefore, 1e-5F);
}

// Undo and redo in the workbench: Edit > Undo names the step, undoing an isovalue shows the
// earlier surfaces again, a rendering setting and visibility come back, and the camera's own
// motion is left alone.
#include <gtest/gtest.h>

#include <QAction>
#include <QDoubleSpinBox>
#include <QSignalSpy>
#include <QTest>

#include "app/main_window.h"
#include "session/session_history.h"
#include "tests/app/workbench_helpers.h"
#include "tests/support/scoped_cache_home.h"
#include "widgets/render_panel.h"
#include "widgets/render_toolbar.h"
#include "widgets/silhouette_view.h"
#include "workbench/isovalue_session.h"
#include "workbench/member_selection.h"

using namespace ensil;

namespace {
class History : public test::SmallDemoWorkbench {
protected:
    void SetUp() override {
        test::SmallDemoWorkbench::SetUp();
        if (HasFatalFailure()) return;
        // The first surfaces start the history; let the queued records of loading pass.
        QCoreApplication::processEvents();
        ASSERT_EQ(stack()->count(), 0);
    }
    QUndoStack* stack() { return window.history()->stack(); }
    QAction* action(const char* name) { return window.findChild<QAction*>(name); }
    // Waits until the queued record of an edit has run.
    bool recorded(int count) {
        return QTest::qWaitFor([&] { return stack()->count() == count; }, 10000);
    }
};
}  // namespace

TEST_F(History, UndoingARenderingSettingPutsItBackAndTheMenuNamesTheStep) {
    auto* thickness = window.renderPanel()->findChild<QDoubleSpinBox*>("thickness");
    ASSERT_NE(thickness, nullptr);
    const float before = window.view()->renderer().settings().thickness;
    thickness->setValue(0.02);
    ASSERT_TRUE(recorded(1));
    EXPECT_EQ(action("undoAction")->text(),
              QString::fromUtf8("&Undo Thickness \u03c4 %1 -> 0.02").arg(double(before)));
    // The camera moves between the edit and the undo: that is no step, and it stays.
    window.view()->renderer().camera().orbit(60.0F, 0.0F);
    const float azimuth = window.view()->renderer().camera().azimuth();
    action("undoAction")->trigger();
    EXPECT_FLOAT_EQ(window.view()->renderer().settings().thickness, before);
    EXPECT_NEAR(thickness->value(), double(before), 1e-6) << "the panel shows it too";
    EXPECT_FLOAT_EQ(window.view()->renderer().camera().azimuth(), azimuth);
    action("redoAction")->trigger();
    EXPECT_FLOAT_EQ(window.view()->renderer().settings().thickness, 0.02F);
}

TEST_F(History, UndoingAnIsovalueShowsTheEarlierSurfacesAgain) {
    const double first = window.renderToolbar()->isovalue();
    QSignalSpy built(window.isovalueSession(), &workbench::IsovalueSession::finished);
    window.renderToolbar()->isovalueBox()->setValue(first - 3.0);
    ASSERT_TRUE(built.wait(60000));
    ASSERT_TRUE(recorded(1));
    EXPECT_TRUE(action("undoAction")->text().startsWith("&Undo Isovalue"))
        << action("undoAction")->text().toStdString();
    const float second = window.view()->renderer().meshes()->isovalue;
    action("undoAction")->trigger();
    ASSERT_TRUE(built.wait(60000));
    EXPECT_NEAR(window.renderToolbar()->isovalue(), first, 1e-6);
    EXPECT_NEAR(window.view()->renderer().meshes()->isovalue, first, 1e-4);
    EXPECT_NE(window.view()->renderer().meshes()->isovalue, second);
    EXPECT_EQ(window.renderToolbar()->isovalueBox()->suffix(), QStringLiteral(" m s\u207b\u00b9"))
        << "the demo's m s-1, as people read it, also after an undo";
    EXPECT_EQ(stack()->count(), 1) << "undoing records nothing new";
}

TEST_F(History, VisibilityAndClustersAreStepsOfTheirOwn) {
    window.memberSelection()->setMemberVisible(2, false);
    ASSERT_TRUE(recorded(1));
    window.memberSelection()->setClusterCount(2);
    ASSERT_TRUE(recorded(2));
    action("undoAction")->trigger();
    // The six members opened with three clusters, about half of them.
    EXPECT_EQ(window.memberSelection()->requestedClusterCount(), 3);
    EXPECT_FALSE(window.memberSelection()->isMemberVisible(2));
    action("undoAction")->trigger();
    EXPECT_TRUE(window.memberSelection()->isMemberVisible(2));
    EXPECT_FALSE(action("undoAction")->isEnabled());
}

TEST_F(History, AViewPresetIsACameraStepThatUndoTakesBack) {
    QAction* map = nullptr;
    for (QAction* a : window.findChildren<QAction*>()) {
        if (a->text() == "&Map View (North Up)") map = a;
    }
    ASSERT_NE(map, nullptr);
    const float elevation = window.view()->renderer().camera().elevation();
    map->trigger();
    ASSERT_TRUE(recorded(1));
    EXPECT_EQ(action("undoAction")->text(), "&Undo Map View (North Up)");
    EXPECT_FLOAT_EQ(window.view()->renderer().camera().elevation(), 89.0F) << "straight down";
    EXPECT_FLOAT_EQ(window.view()->renderer().camera().azimuth(), -90.0F) << "north up";
    EXPECT_EQ(window.view()->renderer().camera().projection(), gl::Camera::Projection::Orthographic)
        << "a map has no perspective";
    action("undoAction")->trigger();
    EXPECT_FLOAT_EQ(window.view()->renderer().camera().elevation(), elevation);
    EXPECT_EQ(window.view()->renderer().camera().projection(), gl::Camera::Projection::Perspective);
}

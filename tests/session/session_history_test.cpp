// Undo steps of a session: named from what changed, a drag is one step, and undoing leaves the
// camera's own motion and the selection alone.
#include "session/session_history.h"

#include <gtest/gtest.h>

using namespace ensil;

TEST(SessionChange, NamesTheStepFromWhatChanged) {
    session::SessionState before;
    before.isovalue = 35.6F;
    session::SessionState after = before;
    after.isovalue = 30.0F;
    EXPECT_EQ(session::describeChange(before, after, false)->name, "Isovalue 35.6 -> 30");
    after = before;
    after.render.thickness = 0.01F;
    const auto thickness = session::describeChange(before, after, false);
    ASSERT_TRUE(thickness);
    EXPECT_EQ(thickness->name, QString::fromUtf8("Thickness \u03c4 0.006 -> 0.01"));
    EXPECT_GE(thickness->mergeKey, 0) << "a dragged number merges";
    after = before;
    after.linkage = prep::Linkage::Ward;
    EXPECT_EQ(session::describeChange(before, after, false)->name, "Linkage average -> ward");
    EXPECT_LT(session::describeChange(before, after, false)->mergeKey, 0);
    after = before;
    after.hiddenMembers = {3};
    EXPECT_EQ(session::describeChange(before, after, false)->name, "Visibility");
    after = before;
    after.render.plane.offset = 0.2F;
    EXPECT_EQ(session::describeChange(before, after, false)->name, "Cutting Plane");
    after = before;
    after.sections.level = "500 hPa";
    EXPECT_EQ(session::describeChange(before, after, false)->name, "Map Level default -> 500 hPa");
    after = before;
    after.sections.cross = "45N";
    EXPECT_EQ(session::describeChange(before, after, false)->name, "Cross-Section default -> 45N");
    after = before;
    after.sectionsFill = session::SectionsFill::Spread;
    EXPECT_EQ(session::describeChange(before, after, false)->name, "Sections Fill mean -> spread");
}

TEST(SessionChange, TheCamerasOwnMotionAndTheSelectionAreNoSteps) {
    session::SessionState before;
    session::SessionState after = before;
    after.camera.azimuth = 10.0F;
    after.camera.placement = session::CameraState::Placement{2.0F, {0.5F, 0.5F, 0.1F}};
    after.selection = {1, 2};
    EXPECT_FALSE(session::describeChange(before, after, false));
    EXPECT_EQ(session::describeChange(before, after, true)->name, "Reset Camera");
}

namespace {
// A session owner as simple as can be: the state itself.
struct Owner {
    session::SessionState state;
    int shown = 0;
    session::SessionHistory history{[this] { return state; },
                                    [this](const session::SessionState& s) {
                                        state = s;
                                        ++shown;
                                    }};
};
}  // namespace

TEST(SessionHistory, UndoAndRedoShowTheSessionBeforeAndAfterEachStep) {
    Owner o;
    o.history.reset();
    o.state.clusters = 3;
    o.history.record();
    o.state.linkage = prep::Linkage::Single;
    o.history.record();
    ASSERT_EQ(o.history.stack()->count(), 2);
    EXPECT_EQ(o.history.stack()->undoText(), "Linkage average -> single");
    EXPECT_EQ(o.shown, 0) << "recording a step done by the user shows nothing again";
    o.history.stack()->undo();
    EXPECT_EQ(o.state.linkage, prep::Linkage::Average);
    EXPECT_EQ(o.state.clusters, 3);
    o.history.stack()->undo();
    EXPECT_EQ(o.state.clusters, 5);
    o.history.stack()->redo();
    EXPECT_EQ(o.state.clusters, 3);
    EXPECT_EQ(o.state.linkage, prep::Linkage::Average);
}

TEST(SessionHistory, ADragIsOneStepAndUndoKeepsTheCameraWhereTheUserMovedIt) {
    Owner o;
    o.history.reset();
    for (const float tau : {0.008F, 0.01F, 0.012F}) {
        o.state.render.thickness = tau;
        o.history.record();
    }
    EXPECT_EQ(o.history.stack()->count(), 1);
    EXPECT_EQ(o.history.stack()->undoText(), QString::fromUtf8("Thickness \u03c4 0.006 -> 0.012"));
    o.state.camera.azimuth = 40.0F;  // orbiting: no step
    o.state.selection = {4};
    o.history.record();
    EXPECT_EQ(o.history.stack()->count(), 1);
    o.history.stack()->undo();
    EXPECT_FLOAT_EQ(o.state.render.thickness, 0.006F);
    EXPECT_FLOAT_EQ(o.state.camera.azimuth, 40.0F);
    EXPECT_EQ(o.state.selection, std::vector<int>{4});
    // Another kind of change after the drag is a step of its own.
    o.history.stack()->redo();
    o.state.render.groupSize = 8;
    o.history.record();
    EXPECT_EQ(o.history.stack()->count(), 2);
}

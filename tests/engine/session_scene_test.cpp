// How a session becomes the renderer's state (engine/session_scene.h), which the workbench's view
// and `ensil render` share: the parts given and only those, the floor of the isovalue drawn, the
// member a section shows, and each member's look from the session. The renderer keeps its state
// on the CPU until it draws, so no display is needed.
#include "engine/session_scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "data/demo_ensemble.h"
#include "preprocessing/ensemble_moments.h"

using namespace ensil;
using session::SessionPart;

namespace {
struct SmallScene {
    data::Ensemble ensemble;
    prep::EnsembleMoments moments;
    engine::ColumnMaxima maxima;
};

SmallScene smallScene() {
    SmallScene s;
    s.ensemble =
        data::makeDemoEnsemble({.members = 4, .nx = 12, .ny = 8, .nz = 5, .seed = 2}).ensemble;
    s.moments = prep::computeEnsembleMoments(s.ensemble);
    s.maxima = engine::computeColumnMaxima(s.ensemble, s.moments.mean);
    return s;
}

engine::SceneData dataOf(const SmallScene& s) {
    engine::SceneData d;
    d.ensemble = &s.ensemble;
    d.mean = &s.moments.mean;
    d.columnMaxima = &s.maxima;
    return d;
}
}  // namespace

TEST(SessionScene, TheRendererTakesTheSessionsPartsGivenAndOnlyThose) {
    const SmallScene scene = smallScene();
    gl::Renderer renderer;
    renderer.setGrid(scene.ensemble.grid);
    session::SessionState state;
    state.verticalExaggeration = 3.0F;
    state.camera.orthographic = true;
    state.render.thickness = 0.01F;
    state.render.plane.enabled = true;
    state.render.verticalAxis = data::VerticalAxis::StandardHeight;

    // Only the background: the exaggeration, settings and projection stay as they were.
    engine::showSession(renderer, state, dataOf(scene), SessionPart::Background);
    EXPECT_FLOAT_EQ(renderer.frame().verticalExaggeration(), 1.0F);
    EXPECT_NE(renderer.settings().thickness, 0.01F);
    EXPECT_EQ(renderer.camera().projection(), gl::Camera::Projection::Perspective);

    engine::showSession(
        renderer, state, dataOf(scene),
        SessionPart::Exaggeration | SessionPart::Rendering | SessionPart::Projection);
    EXPECT_FLOAT_EQ(renderer.frame().verticalExaggeration(), 3.0F);
    EXPECT_FLOAT_EQ(renderer.settings().thickness, 0.01F);
    EXPECT_TRUE(renderer.settings().plane.enabled);
    EXPECT_EQ(renderer.camera().projection(), gl::Camera::Projection::Orthographic);
    // The box's frame follows the vertical axis chosen, keeping the exaggeration.
    EXPECT_EQ(renderer.frame().verticalAxis(), data::VerticalAxis::StandardHeight);
    EXPECT_FLOAT_EQ(renderer.frame().verticalExaggeration(), 3.0F);
}

TEST(SessionScene, TheProbabilityFloorIsTheIsovalueDrawnsAndAGivenRangeReplacesItsOwn) {
    const SmallScene scene = smallScene();
    gl::RenderSettings settings;
    settings.floor = gl::FloorContent::ProbabilityMaximum;
    engine::SceneData data = dataOf(scene);
    // Before an isovalue is drawn there is no probability to show.
    EXPECT_TRUE(engine::sceneFloor(data, settings).values.empty());
    const std::vector<float> probability(scene.ensemble.grid.nx() * scene.ensemble.grid.ny(),
                                         0.25F);
    data.isovalue = 30.0F;
    data.exceedanceColumnMaximum = &probability;
    const gl::FloorMap floor = engine::sceneFloor(data, settings);
    ASSERT_EQ(floor.values.size(), probability.size());
    EXPECT_FLOAT_EQ(floor.values.front(), 0.25F);

    settings.floor = gl::FloorContent::ColumnMaximum;
    const gl::FloorMap own = engine::sceneFloor(data, settings);
    data.floorRange = std::pair{-5.0F, 95.0F};
    data.floorRangeNote = " (one scale over all steps)";
    const gl::FloorMap shared = engine::sceneFloor(data, settings);
    EXPECT_EQ(shared.values, own.values);
    EXPECT_FLOAT_EQ(shared.minimum, -5.0F);
    EXPECT_FLOAT_EQ(shared.maximum, 95.0F);
    EXPECT_EQ(shared.caption, own.caption + " (one scale over all steps)");
}

TEST(SessionScene, ASectionShowsTheFirstSelectedMemberElseTheOneHoveredLast) {
    EXPECT_EQ(engine::sectionMember({3, 1}, 2), 3);
    EXPECT_EQ(engine::sectionMember({}, 2), 2);
    EXPECT_EQ(engine::sectionMember({}, -1), -1);

    const SmallScene scene = smallScene();
    engine::SceneData data = dataOf(scene);
    data.valueMinimum = -100.0F;
    data.valueMaximum = 100.0F;
    const gl::SectionVolume member = engine::sceneSection(data, gl::SectionField::Member, 2);
    ASSERT_EQ(member.values.size(), scene.ensemble.grid.pointCount());
    EXPECT_EQ(member.values[7], scene.ensemble.members[2].values[7]);
    EXPECT_TRUE(engine::sceneSection(data, gl::SectionField::Member, -1).values.empty());
}

TEST(SessionScene, MembersLookAsTheSessionHidesAndSelectsThemUnderTheClustersShown) {
    session::SessionState state;
    state.hiddenClusters = {1};
    state.hiddenMembers = {0};
    state.selection = {2};
    const std::vector<int> labels{0, 1, 0, 1};
    const std::vector<int> identities{4, 2};  // label 0 is cluster 5, label 1 cluster 3
    const auto look = engine::sceneAppearance(state, labels, identities, 4);
    ASSERT_EQ(look.size(), 4U);
    EXPECT_FALSE(look[0].visible);  // hidden itself
    EXPECT_FALSE(look[1].visible);  // its cluster hidden
    EXPECT_TRUE(look[2].visible);
    EXPECT_TRUE(look[2].selected);
    EXPECT_FALSE(look[3].visible);
    EXPECT_EQ(look[2].cluster, 4);
    EXPECT_EQ(look[3].cluster, 2);
}

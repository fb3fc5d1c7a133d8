// The animation in the main window: play steps through the visible members in cluster then
// similarity order, each shown as the renderer's animated (solid) member; a selection limits it.
#include <gtest/gtest.h>

#include <QSignalSpy>
#include <QTest>

#include "app/main_window.h"
#include "preprocessing/clustering.h"
#include "tests/app/workbench_helpers.h"
#include "tests/support/scoped_cache_home.h"
#include "tests/support/temp_dir.h"
#include "widgets/animation_bar.h"
#include "widgets/silhouette_view.h"
#include "workbench/isovalue_session.h"
#include "workbench/member_selection.h"

using namespace ensil;

TEST(MainWindowAnimation, PlaysTheMembersInClusterThenSimilarityOrder) {
    const test::ScopedCacheHome cache;
    app::MainWindow window;
    ASSERT_TRUE(test::showWorkbench(window, {900, 600}));
    ASSERT_TRUE(
        test::loadDemoAndWait(window, {.members = 6, .nx = 64, .ny = 32, .nz = 8, .seed = 9}));

    ui::AnimationBar& bar = *window.animationBar();
    gl::Renderer& renderer = window.view()->renderer();
    bar.setFramesPerSecond(30.0);
    bar.setLoop(false);
    QSignalSpy shown(&bar, &ui::AnimationBar::memberShown);
    bar.play();
    QTRY_VERIFY_WITH_TIMEOUT(!bar.isPlaying(), 5000);
    const workbench::IsovalueResult& result = *window.isovalueSession()->result();
    const std::vector<int> labels = window.isovalueSession()->labels();
    const int k = *std::max_element(labels.begin(), labels.end()) + 1;
    const std::vector<int> expected = prep::animationOrder(result.tree, result.distances, k);
    std::vector<int> played;
    for (const auto& call : shown) played.push_back(call[0].toInt());
    EXPECT_EQ(played, expected);
    EXPECT_EQ(renderer.animatedMember(), expected.back());

    // With members 1 and 4 selected, only they are played.
    window.memberSelection()->setSelection({1, 4});
    bar.stop();
    EXPECT_EQ(renderer.animatedMember(), -1);
    bar.setSequence({});
    shown.clear();
    bar.step(1);
    bar.step(1);
    std::vector<int> selectedOrder;
    for (const int m : expected)
        if (m == 1 || m == 4) selectedOrder.push_back(m);
    ASSERT_EQ(shown.count(), 2);
    EXPECT_EQ(shown[0][0].toInt(), selectedOrder[0]);
    EXPECT_EQ(shown[1][0].toInt(), selectedOrder[1]);
}

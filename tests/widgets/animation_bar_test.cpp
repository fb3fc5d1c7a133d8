#include "widgets/animation_bar.h"

#include <gtest/gtest.h>

#include <QAction>
#include <QSignalSpy>
#include <QTest>

using namespace ensil;

namespace {
std::vector<int> shown(const QSignalSpy& spy) {
    std::vector<int> members;
    for (const QList<QVariant>& call : spy) members.push_back(call[0].toInt());
    return members;
}
}  // namespace

TEST(AnimationBar, StepsThroughTheSequenceAndWrapsWhenLooping) {
    ui::AnimationBar bar;
    bar.setSequence({4, 1, 7});
    QSignalSpy spy(&bar, &ui::AnimationBar::memberShown);
    bar.step(1);  // from stopped: the first
    bar.step(1);
    bar.step(1);
    bar.step(1);  // wraps
    bar.step(-1);
    EXPECT_EQ(shown(spy), (std::vector<int>{4, 1, 7, 4, 7}));
    EXPECT_EQ(bar.currentMember(), 7);
    bar.stop();
    EXPECT_EQ(spy.last()[0].toInt(), -1);
    EXPECT_EQ(bar.position(), -1);
}

TEST(AnimationBar, WithoutLoopPlayingStopsAtTheLastMember) {
    ui::AnimationBar bar;
    bar.setLoop(false);
    bar.setFramesPerSecond(30.0);
    bar.setSequence({2, 0, 3});
    QSignalSpy spy(&bar, &ui::AnimationBar::memberShown);
    bar.play();
    EXPECT_TRUE(bar.isPlaying());
    QTRY_VERIFY_WITH_TIMEOUT(!bar.isPlaying(), 3000);
    EXPECT_EQ(shown(spy), (std::vector<int>{2, 0, 3}));
    EXPECT_EQ(bar.currentMember(), 3) << "the last member stays on screen";
    // Playing again starts from the beginning.
    bar.play();
    EXPECT_EQ(bar.currentMember(), 2);
    bar.pause();
    EXPECT_FALSE(bar.isPlaying());
}

TEST(AnimationBar, AsksForASequenceWhenItHasNoneAndANewOneStopsTheAnimation) {
    ui::AnimationBar bar;
    QSignalSpy wanted(&bar, &ui::AnimationBar::sequenceWanted);
    QObject::connect(&bar, &ui::AnimationBar::sequenceWanted, &bar, [&bar] {
        bar.setSequence({5, 6}, {"a", "b", "c", "d", "e", "f", "g"});
    });
    QSignalSpy spy(&bar, &ui::AnimationBar::memberShown);
    bar.playAction()->trigger();
    EXPECT_EQ(wanted.count(), 1);
    EXPECT_TRUE(bar.isPlaying());
    EXPECT_EQ(bar.currentMember(), 5);
    bar.setSequence({});  // e.g. a new isovalue
    EXPECT_FALSE(bar.isPlaying());
    EXPECT_EQ(spy.last()[0].toInt(), -1);
}

// The time bar asks for one step at a time and follows what is on screen.
#include "widgets/time_bar.h"

#include <gtest/gtest.h>

#include <QAction>
#include <QLabel>
#include <QSignalSpy>
#include <QSlider>

using namespace ensil;

namespace {
const QStringList kTimes{"2017-01-01T00:00", "2017-01-01T12:00", "2017-01-02T00:00",
                         "2017-01-02T12:00"};
}

TEST(TimeBar, StepsAreAskedForOneAtATimeAndNeverQueued) {
    ui::TimeBar bar;
    bar.setSteps(kTimes, 0);
    QSignalSpy asked(&bar, &ui::TimeBar::stepRequested);
    bar.step(1);
    ASSERT_EQ(asked.size(), 1);
    EXPECT_EQ(asked.back().at(0).toInt(), 1);
    EXPECT_EQ(bar.pendingStep(), 1);
    // Playing while step 1 is still being built: the ticks ask for nothing more.
    bar.play();
    EXPECT_TRUE(bar.isPlaying());
    bar.playbackTick();
    bar.playbackTick();
    EXPECT_EQ(asked.size(), 1) << "no step is queued behind one not yet shown";
    bar.setShownStep(1);
    EXPECT_EQ(bar.pendingStep(), -1);
    EXPECT_TRUE(bar.findChild<QLabel*>()->text().contains("2017-01-01T12:00  (2 of 4)"));
    bar.playbackTick();
    ASSERT_EQ(asked.size(), 2);
    EXPECT_EQ(asked.back().at(0).toInt(), 2);
    // A step asked for again while pending is not asked twice; the slider asks where let go.
    bar.requestStep(2);
    EXPECT_EQ(asked.size(), 2);
    bar.setShownStep(2);
    bar.findChild<QSlider*>("timeSlider")->setValue(0);
    ASSERT_EQ(asked.size(), 3);
    EXPECT_EQ(asked.back().at(0).toInt(), 0);
}

TEST(TimeBar, LoopingWrapsAndWithoutItPlaybackStopsAtTheLastStep) {
    ui::TimeBar bar;
    bar.setSteps(kTimes, 3);
    QSignalSpy asked(&bar, &ui::TimeBar::stepRequested);
    bar.step(1);
    ASSERT_EQ(asked.size(), 1);
    EXPECT_EQ(asked.back().at(0).toInt(), 0) << "looping: after the last, the first";
    bar.setShownStep(0);
    bar.step(-1);
    EXPECT_EQ(asked.back().at(0).toInt(), 3);
    bar.setShownStep(3);
    bar.setLoop(false);
    bar.play();
    EXPECT_EQ(asked.back().at(0).toInt(), 0) << "playing from the end starts again";
    bar.setShownStep(0);
    for (int s = 1; s <= 3; ++s) {
        bar.playbackTick();
        EXPECT_EQ(asked.back().at(0).toInt(), s);
        bar.setShownStep(s);
    }
    bar.playbackTick();
    EXPECT_FALSE(bar.isPlaying()) << "stops at the last step";
}

TEST(TimeBar, OneStepOrNoneLeavesTheControlsOff) {
    ui::TimeBar bar;
    bar.setSteps({"2017-01-01T00:00"}, 0);
    EXPECT_FALSE(bar.playAction()->isEnabled());
    QSignalSpy asked(&bar, &ui::TimeBar::stepRequested);
    bar.step(1);
    bar.play();
    EXPECT_EQ(asked.size(), 0);
    EXPECT_FALSE(bar.isPlaying());
    bar.setSteps(kTimes, 1);
    EXPECT_TRUE(bar.playAction()->isEnabled());
}

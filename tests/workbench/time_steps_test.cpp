// The time steps besides the one shown (workbench/time_steps.h), on a QCoreApplication: which
// step is read ahead, which steps a memory budget keeps, reading in the background, and the
// order in which the cluster strip is filled.
#include "workbench/time_steps.h"

#include <gtest/gtest.h>

#include <QSignalSpy>
#include <QTest>
#include <memory>
#include <stdexcept>
#include <vector>

#include "data/demo_ensemble.h"

using namespace ensil;

namespace {

constexpr int kWaitMs = 60000;  // an upper bound for a loaded CI machine, not a pace

// A step's overview holding a small demo ensemble (what the budget counts is its bytes).
std::unique_ptr<engine::EnsembleOverview> stepOverview(unsigned seed) {
    auto overview = std::make_unique<engine::EnsembleOverview>();
    overview->ensemble = std::make_shared<const data::Ensemble>(
        data::makeDemoEnsemble({.members = 3, .nx = 16, .ny = 8, .nz = 4, .seed = seed}).ensemble);
    return overview;
}

std::size_t stepBytes() { return stepOverview(1)->ensemble->bytes(); }

}  // namespace

TEST(TimeSteps, ReadsAheadInTheDirectionOfTheLastMoveAndRoundTheEndOnlyWhilePlaying) {
    workbench::TimeSteps steps;
    EXPECT_EQ(steps.nextToRead(3, 10, false), 4U);  // forward at first
    EXPECT_EQ(steps.nextToRead(9, 10, false), std::nullopt);
    EXPECT_EQ(steps.nextToRead(9, 10, true), 0U);
    steps.moved(5, 4);
    EXPECT_EQ(steps.direction(), -1);
    EXPECT_EQ(steps.nextToRead(4, 10, false), 3U);
    EXPECT_EQ(steps.nextToRead(0, 10, false), std::nullopt);
    EXPECT_EQ(steps.nextToRead(4, 10, true), 5U);  // playing goes forward whatever the move
    steps.moved(4, 4);                             // no move keeps the direction
    EXPECT_EQ(steps.direction(), -1);
    steps.moved(4, 7);
    EXPECT_EQ(steps.nextToRead(7, 10, false), 8U);
    EXPECT_EQ(steps.nextToRead(0, 1, true), std::nullopt);  // one step: nothing to read
}

TEST(TimeSteps, KeepsStepsWithinTheBudgetDroppingTheFarthestFromTheOneShownFirst) {
    workbench::TimeSteps steps;
    steps.setBudget(3 * stepBytes());
    for (const std::size_t s : {0U, 1U, 2U, 8U}) steps.keep(s, stepOverview(s + 1), 4);
    // Four steps over a budget of three: step 8 lies 4 from step 4 shown, step 0 too, but the
    // first of the farthest found goes (0), then nothing more.
    EXPECT_EQ(steps.keptSteps(), (std::vector<std::size_t>{1, 2, 8}));
    EXPECT_EQ(steps.keptBytes(), 3 * stepBytes());
    // Showing step 2 now: step 8 is the farthest from it.
    steps.keep(3, stepOverview(9), 2);
    EXPECT_EQ(steps.keptSteps(), (std::vector<std::size_t>{1, 2, 3}));

    // A kept step taken out to be shown is no longer kept; one not kept is null.
    const std::unique_ptr<engine::EnsembleOverview> taken = steps.take(2);
    ASSERT_NE(taken, nullptr);
    EXPECT_EQ(steps.kept(2), nullptr);
    EXPECT_EQ(steps.take(7), nullptr);

    // A budget smaller than one step still keeps one.
    steps.setBudget(1);
    steps.keep(5, stepOverview(4), 5);
    EXPECT_EQ(steps.keptSteps().size(), 1U);
}

TEST(TimeSteps, AStepReadAheadIsKeptAndSaidOnceAndAFailedOneLeavesNothing) {
    workbench::TimeSteps steps;
    QSignalSpy read(&steps, &workbench::TimeSteps::stepRead);
    steps.readAhead(6, [](const std::stop_token&, const data::Progress&) {
        return std::move(*stepOverview(6));
    });
    EXPECT_TRUE(steps.isReading(6));
    EXPECT_TRUE(steps.isReadingAny());
    ASSERT_TRUE(read.wait(kWaitMs));
    EXPECT_EQ(read.front().front().value<std::size_t>(), 6U);
    EXPECT_FALSE(steps.isReadingAny());
    ASSERT_NE(steps.kept(6), nullptr);
    EXPECT_EQ(steps.kept(6)->ensemble->members.size(), 3U);

    // A failure: nothing kept, nothing said, and the step may be read again.
    read.clear();
    steps.readAhead(7,
                    [](const std::stop_token&, const data::Progress&) -> engine::EnsembleOverview {
                        throw std::runtime_error("no step 7");
                    });
    EXPECT_TRUE(steps.isReading(7));
    ASSERT_TRUE(QTest::qWaitFor([&steps] { return !steps.isReadingAny(); }, kWaitMs));
    EXPECT_TRUE(read.isEmpty());
    EXPECT_EQ(steps.kept(7), nullptr);

    // Other data: what is kept is forgotten, a read under way is dropped.
    steps.readAhead(8, [](const std::stop_token&, const data::Progress&) {
        return std::move(*stepOverview(8));
    });
    steps.forget();
    EXPECT_FALSE(steps.isReadingAny());
    EXPECT_TRUE(steps.keptSteps().empty());
}

TEST(TimeSteps, TheStripFillsOutwardFromTheStepShownLaterStepsFirst) {
    std::vector<bool> done(7, false);
    const auto clustered = [&done](int s) { return done[static_cast<std::size_t>(s)]; };
    done[3] = true;  // the step shown
    std::vector<std::pair<int, int>> order;
    while (const auto next = workbench::nextStepToCluster(3, 7, clustered)) {
        order.emplace_back(next->step, next->neighbour);
        done[static_cast<std::size_t>(next->step)] = true;
    }
    const std::vector<std::pair<int, int>> expected{{4, 3}, {2, 3}, {5, 4}, {1, 2}, {6, 5}, {0, 1}};
    EXPECT_EQ(order, expected);
    // A step shown that is not clustered yet gives nothing to match with.
    std::vector<bool> none(4, false);
    EXPECT_EQ(workbench::nextStepToCluster(
                  1, 4, [&none](int s) { return none[static_cast<std::size_t>(s)]; }),
              std::nullopt);
}

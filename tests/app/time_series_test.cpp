// Ensembles over time: the steps a --times range names, clusters matched from step to step, and
// the command line's --times in preprocess, render and generate.
#include "engine/time_series.h"

#include <gtest/gtest.h>

#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <algorithm>
#include <filesystem>
#include <stop_token>

#include "data/ensemble_reader.h"
#include "engine/floor_map.h"
#include "engine/picture_title.h"
#include "preprocessing/cluster_identity.h"
#include "preprocessing/ensemble_moments.h"
#include "tests/app/ensil_run.h"
#include "tests/support/temp_dir.h"

using namespace ensil;
using ensil::test::kEra5;

namespace {
const QStringList kEra5Times{"2017-01-01T00:00", "2017-01-01T12:00", "2017-01-02T00:00",
                             "2017-01-02T12:00"};

}  // namespace

TEST(StepRange, AllAndInclusiveRangesAndRefusalsNamingTheSteps) {
    std::string problem;
    EXPECT_EQ(engine::parseStepRange("all", 4, "'f.nc'", problem), (engine::StepRange{0, 3}));
    EXPECT_EQ(engine::parseStepRange("1:2", 4, "'f.nc'", problem), (engine::StepRange{1, 2}));
    EXPECT_EQ(engine::parseStepRange("3:3", 4, "'f.nc'", problem)->count(), 1u);
    EXPECT_FALSE(engine::parseStepRange("2:4", 4, "'f.nc'", problem));
    EXPECT_EQ(problem, "--times '2:4' is refused: 'f.nc' has 4 time steps, 0 to 3");
    EXPECT_FALSE(engine::parseStepRange("3:1", 4, "'f.nc'", problem));
    EXPECT_NE(problem.find("comes after"), std::string::npos) << problem;
    for (const char* bad : {"", "2", "a:b", "-1:2", "1:", ":2", "1:2:3", "0x1:2"}) {
        EXPECT_FALSE(engine::parseStepRange(bad, 4, "'f.nc'", problem)) << bad;
        EXPECT_NE(problem.find("'all' or A:B"), std::string::npos) << bad << ": " << problem;
    }
    EXPECT_FALSE(engine::parseStepRange("all", 0, "'f.nc'", problem));
    EXPECT_NE(problem.find("has no time steps"), std::string::npos) << problem;
}

TEST(StepIdentities, AGroupKeepsItsIdentityWhereMostOfItsMembersGo) {
    // Step 1: members 0-3 form identity 0, members 4-6 identity 1, members 7-8 identity 2.
    const std::vector<int> before{0, 0, 0, 0, 1, 1, 1, 2, 2};
    // Step 2, clustered afresh: members 3 and 4 have joined 7 and 8; the rest of each group
    // stays together. The labels are numbered otherwise on purpose (label 0 = {5, 6}), so
    // colours by label would be wrong.
    const std::vector<int> labels{2, 2, 2, 1, 1, 0, 0, 1, 1};
    const prep::MergeTree unused{};
    const std::vector<int> identities = engine::matchStepIdentities(unused, 3, labels, before);
    // Label 2 holds three of group 0: identity 0. Label 0 holds two of group 1: identity 1.
    // Label 1 holds both of group 2 (and one each of groups 0 and 1): identity 2.
    EXPECT_EQ(identities, (std::vector<int>{1, 2, 0}));
    EXPECT_EQ(prep::memberIdentities(labels, identities),
              (std::vector<int>{0, 0, 0, 2, 2, 1, 1, 2, 2}));
}

TEST(StepIdentities, ANewGroupTakesTheLowestFreeIdentityAndTheFirstStepTheTreesOwn) {
    // Group 1 splits into two: the larger part keeps 1, the new part takes the lowest free (2).
    const std::vector<int> before{0, 0, 1, 1, 1, 1, -1};
    const std::vector<int> labels{0, 0, 1, 1, 1, 2, 2};
    EXPECT_EQ(engine::matchStepIdentities({}, 3, labels, before), (std::vector<int>{0, 1, 2}));
    // Nothing known: the identities of the tree's own walk, as ensil preprocess gives them.
    prep::MergeTree tree;
    tree.memberCount = 3;
    tree.merges = {{.a = 0, .b = 1, .height = 1.0, .size = 2},
                   {.a = 2, .b = 3, .height = 2.0, .size = 3}};
    const std::vector<int> fresh = prep::clusterLabels(tree, 2);
    EXPECT_EQ(engine::matchStepIdentities(tree, 2, fresh, {-1, -1, -1}),
              prep::identitiesFromTree(tree, 2));
}

TEST(StepIdentities, PreviousIdentitiesAreFoundByMemberName) {
    EXPECT_EQ(engine::previousIdentitiesByName({"a", "b", "c"}, {2, 0, 1}, {"c", "x", "a"}),
              (std::vector<int>{1, -1, 2}));
    EXPECT_EQ(engine::previousIdentitiesByName({}, {}, {"a"}), (std::vector<int>{-1}));
}

TEST(PreprocessTimes, Era5GivesOneObjectPerStepWithItsTimeAndColoursThatFollowTheGroups) {
    test::TempDir cache;
    const test::EnsilRun run = test::runEnsil(
        {"preprocess", kEra5, "--var", "t", "--iso", "260", "--clusters", "3", "--times", "all",
         "--json", "--cache-dir", QString::fromStdString(cache.path().string())});
    ASSERT_EQ(run.code, 0) << run.err.toStdString();
    const QJsonObject o = jsonOf(run);
    EXPECT_EQ(o["time_dimension"].toString(), "time");
    EXPECT_EQ(o["isovalue"].toDouble(), 260.0);
    const QJsonArray steps = o["steps"].toArray();
    ASSERT_EQ(steps.size(), 4);
    std::vector<std::map<QString, QString>> colorOfMember(4);
    for (int s = 0; s < 4; ++s) {
        const QJsonObject step = steps[s].toObject();
        EXPECT_EQ(step["time"].toString(), kEra5Times[s]);
        EXPECT_EQ(step["time_index"].toInt(), s);
        EXPECT_EQ(step["distance_matrix"].toArray().size(), 10);
        EXPECT_EQ(step["linkage"].toArray().size(), 9);
        const QJsonArray clusters = step["clusters"].toArray(), colors = step["colors"].toArray();
        ASSERT_EQ(clusters.size(), 10);
        ASSERT_EQ(colors.size(), 10);
        for (int m = 0; m < 10; ++m) {
            // Each member's colour is its cluster number's (the identity + 1).
            EXPECT_EQ(colors[m].toString().toStdString(),
                      engine::identityColorName(clusters[m].toInt() - 1));
        }
    }
    // Reproduced by hand: each step's clusters are numbered as matched to the previous step's
    // (the first step's from its tree alone).
    std::vector<int> previous(10, -1);
    for (int s = 0; s < 4; ++s) {
        const QJsonObject step = steps[s].toObject();
        const prep::MergeTree tree = test::treeOfLinkageJson(step["linkage"].toArray(), 10);
        const std::vector<int> labels = prep::clusterLabels(tree, 3);
        const std::vector<int> identities =
            s == 0 ? prep::identitiesFromTree(tree, 3) : prep::matchIdentities(labels, 3, previous);
        previous = prep::memberIdentities(labels, identities);
        std::vector<int> numbers;
        for (const auto v : step["clusters"].toArray()) numbers.push_back(v.toInt() - 1);
        EXPECT_EQ(numbers, previous) << "step " << s;
    }
    // The second run reads every step from the cache.
    const test::EnsilRun again = test::runEnsil(
        {"preprocess", kEra5, "--var", "t", "--iso", "260", "--clusters", "3", "--times", "1:2",
         "--json", "--cache-dir", QString::fromStdString(cache.path().string())});
    ASSERT_EQ(again.code, 0) << again.err.toStdString();
    const QJsonArray cached = jsonOf(again)["steps"].toArray();
    ASSERT_EQ(cached.size(), 2);
    EXPECT_EQ(cached[0].toObject()["time"].toString(), kEra5Times[1]);
    EXPECT_EQ(cached[1].toObject()["cache"].toString(), "hit");
}

TEST(InfoTimes, JsonListsTheStepsWithTheirDates) {
    const test::EnsilRun run = test::runEnsil({"info", kEra5, "--var", "t", "--json"});
    ASSERT_EQ(run.code, 0) << run.err.toStdString();
    const QJsonObject steps = jsonOf(run)["time_steps"].toObject();
    EXPECT_EQ(steps["dimension"].toString(), "time");
    EXPECT_EQ(steps["labels"].toVariant().toStringList(), kEra5Times);
}

TEST(PreprocessTimes, OutOfRangeNoStepsDemoAndTimeIndexAreRefusedWithExitCode2) {
    const test::EnsilRun past =
        test::runEnsil({"preprocess", kEra5, "--var", "t", "--times", "2:4", "--no-cache"});
    EXPECT_EQ(past.code, 2);
    EXPECT_TRUE(past.err.contains("has 4 time steps, 0 to 3")) << past.err.toStdString();
    const test::EnsilRun garbage =
        test::runEnsil({"preprocess", kEra5, "--var", "t", "--times", "first", "--no-cache"});
    EXPECT_EQ(garbage.code, 2);
    EXPECT_TRUE(garbage.err.contains("'all' or A:B")) << garbage.err.toStdString();
    const test::EnsilRun demo = test::runEnsil({"preprocess", "--demo", "--times", "all"});
    EXPECT_EQ(demo.code, 2);
    EXPECT_TRUE(demo.err.contains("ensil generate --times")) << demo.err.toStdString();
    const test::EnsilRun both =
        test::runEnsil({"preprocess", kEra5, "--var", "t", "--times", "all", "--time-index", "1"});
    EXPECT_EQ(both.code, 2);
    EXPECT_TRUE(both.err.contains("refused together")) << both.err.toStdString();
}

TEST(GenerateTimes, ADemoOverTimeIsDatedAndItsClustersSplitAndMerge) {
    test::TempDir dir;
    const QString path = QString::fromStdString(dir.file("steps.nc"));
    const test::EnsilRun generate = test::runEnsil(
        {"generate", "--members", "20", "--grid", "64x32x8", "--times", "6", "--out", path});
    ASSERT_EQ(generate.code, 0) << generate.err.toStdString();
    EXPECT_TRUE(generate.out.contains("at 6 times from 2026-01-01T00:00"))
        << generate.out.toStdString();
    const test::EnsilRun info = test::runEnsil({"info", path});
    ASSERT_EQ(info.code, 0) << info.err.toStdString();
    EXPECT_TRUE(info.out.contains("time = 0 of 6 (2026-01-01T00:00)")) << info.out.toStdString();
    EXPECT_TRUE(
        info.out.contains("Times:      6 along 'time', 2026-01-01T00:00 ... 2026-01-03T12:00"))
        << info.out.toStdString();

    const test::EnsilRun text =
        test::runEnsil({"preprocess", path, "--clusters", "4", "--times", "all", "--no-cache"});
    ASSERT_EQ(text.code, 0) << text.err.toStdString();
    EXPECT_TRUE(text.out.contains("2026-01-03T12:00  clusters")) << text.out.toStdString();
    const test::EnsilRun run = test::runEnsil(
        {"preprocess", path, "--clusters", "4", "--times", "all", "--json", "--no-cache"});
    ASSERT_EQ(run.code, 0) << run.err.toStdString();
    const QJsonArray steps = jsonOf(run)["steps"].toArray();
    ASSERT_EQ(steps.size(), 6);
    // Members regroup: some member's cluster number at the end differs from its first.
    const auto identitiesOf = [](const QJsonObject& step) {
        std::vector<int> result;
        for (const auto number : step["clusters"].toArray()) result.push_back(number.toInt());
        return result;
    };
    const std::vector<int> first = identitiesOf(steps[0].toObject());
    const std::vector<int> last = identitiesOf(steps[5].toObject());
    ASSERT_EQ(first.size(), 20u);
    int moved = 0;
    for (std::size_t m = 0; m < first.size(); ++m) moved += first[m] != last[m] ? 1 : 0;
    EXPECT_GE(moved, 1) << text.out.toStdString();
    EXPECT_LE(moved, 10) << "most members keep their group: " << text.out.toStdString();

    const test::EnsilRun bad = test::runEnsil({"generate", "--times", "0", "--out", path});
    EXPECT_EQ(bad.code, 2);
    EXPECT_TRUE(bad.err.contains("--times must be a whole number from 1 to 1000"))
        << bad.err.toStdString();
}

TEST(RenderTimes, OnePicturePerStepNamedByItsTimeIndexAndTitledWithItsTime) {
    test::TempDir dir;
    const QString pattern = QString::fromStdString(dir.file("frame_%03d.png"));
    const test::EnsilRun run = test::runEnsil(
        {"render", kEra5, "--var", "t", "--iso", "260", "--times", "1:2", "--out", pattern,
         "--size", "320x200", "--frames", "1", "--no-cache", "--floor", "none"});
    ASSERT_EQ(run.code, 0) << run.err.toStdString();
    const QImage a(QString::fromStdString(dir.file("frame_001.png")));
    const QImage b(QString::fromStdString(dir.file("frame_002.png")));
    ASSERT_FALSE(a.isNull()) << run.out.toStdString();
    ASSERT_FALSE(b.isNull()) << run.out.toStdString();
    EXPECT_FALSE(std::filesystem::exists(dir.file("frame_000.png")));
    EXPECT_EQ(a.size(), QSize(320, 200));
    EXPECT_NE(a, b) << "the steps' surfaces differ";
    // The first frame is the picture of its step alone (but for a floor, whose colours span
    // all the steps: TheFloorHasOneColourScaleOverAllTheSteps).
    const QString single = QString::fromStdString(dir.file("single.png"));
    const test::EnsilRun alone = test::runEnsil(
        {"render", kEra5, "--var", "t", "--iso", "260", "--time-index", "1", "--out", single,
         "--size", "320x200", "--frames", "1", "--no-cache", "--floor", "none"});
    ASSERT_EQ(alone.code, 0) << alone.err.toStdString();
    EXPECT_EQ(a, QImage(single)) << "frame_001.png is time index 1";
    EXPECT_TRUE(run.out.contains("time index 2")) << run.out.toStdString();
    // The title is the picture's: it names the step's time.
    const data::Ensemble at2 =
        data::openEnsemble({.paths = {kEra5.toStdString()}, .variable = "t", .timeIndex = 2});
    EXPECT_NE(engine::pictureTitle(at2, 260.0F).find("time 2017-01-02T00:00"), std::string::npos);
}

TEST(RenderTimes, SeveralStepsNeedANumberPatternAndARangeInsideTheSteps) {
    test::TempDir dir;
    const QString plain = QString::fromStdString(dir.file("one.png"));
    const test::EnsilRun noPattern = test::runEnsil(
        {"render", kEra5, "--var", "t", "--times", "0:3", "--out", plain, "--no-cache"});
    EXPECT_EQ(noPattern.code, 2);
    EXPECT_TRUE(noPattern.err.contains("frame_%03d.png")) << noPattern.err.toStdString();
    EXPECT_TRUE(noPattern.err.contains("4 pictures")) << noPattern.err.toStdString();
    const test::EnsilRun past = test::runEnsil(
        {"render", kEra5, "--var", "t", "--times", "0:9", "--out", "f_%d.png", "--no-cache"});
    EXPECT_EQ(past.code, 2);
    EXPECT_TRUE(past.err.contains("has 4 time steps")) << past.err.toStdString();
    const test::EnsilRun demo =
        test::runEnsil({"render", "--demo", "--times", "all", "--out", "f_%d.png"});
    EXPECT_EQ(demo.code, 2);
    EXPECT_TRUE(demo.err.contains("no time steps")) << demo.err.toStdString();
}

TEST(TimeSeries, ProgressRisesToOneOverAllStepsAndAStopEndsTheSeriesBetweenSteps) {
    engine::TimeSeriesRequest request;
    request.selection = {.paths = {kEra5.toStdString()}, .variable = "t"};
    request.steps = {0, 3};
    request.preprocess.isovalue = 260.0;
    request.preprocess.clusters = 3;
    const auto quiet = [](const std::string&, const std::string&) {};
    std::vector<double> fractions;
    std::vector<std::string> times;
    const auto steps = engine::preprocessTimeSeries(
        request, quiet, {}, [&](double f) { fractions.push_back(f); },
        [&](const engine::TimeStepResult& step) { times.push_back(step.time); });
    ASSERT_EQ(steps.size(), 4u);
    std::vector<std::string> expected;
    for (const QString& t : kEra5Times) expected.push_back(t.toStdString());
    EXPECT_EQ(times, expected);
    ASSERT_FALSE(fractions.empty());
    EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
    EXPECT_DOUBLE_EQ(fractions.back(), 1.0);
    EXPECT_LE(fractions.front(), 0.25);

    // Stopped once the second step is done: no third step is read.
    std::stop_source stop;
    std::size_t done = 0;
    EXPECT_THROW((void)engine::preprocessTimeSeries(request, quiet, stop.get_token(), {},
                                                    [&](const engine::TimeStepResult&) {
                                                        if (++done == 2) stop.request_stop();
                                                    }),
                 data::Cancelled);
    EXPECT_EQ(done, 2u);
}

// The workbench's strip clusters the steps not visited without their surfaces: the same
// clusters and identities as preprocessing each step, matched to the step before.
TEST(StepClustering, AStepsClustersWithoutSurfacesAreThoseOfItsWholePreprocessing) {
    engine::TimeSeriesRequest request;
    request.selection = {.paths = {kEra5.toStdString()}, .variable = "t"};
    request.steps = {0, 3};
    // The workbench's defaults: its isovalue and 5 clusters, where the groups of step 1 on
    // take other identities than their tree alone would give them.
    request.preprocess.clusters = 5;
    const auto steps =
        engine::preprocessTimeSeries(request, [](const std::string&, const std::string&) {});
    ASSERT_EQ(steps.size(), 4u);
    bool someoneMoved = false;
    bool alone = false;  // a step whose tree alone would give other identities
    for (std::size_t s = 1; s < steps.size(); ++s) {
        engine::StepClusteringRequest one;
        one.selection = request.selection;
        one.selection.timeIndex = s;
        one.isovalue = steps[0].result.meshes.isovalue;
        one.k = 5;
        for (const data::Member& m : steps[s - 1].result.ensemble->members) {
            one.previousMembers.push_back(m.name);
        }
        one.previousIdentities = steps[s - 1].memberIdentities;
        const engine::StepClusters clusters = engine::clusterTimeStep(one, {});
        ASSERT_EQ(clusters.members.size(), 10u);
        EXPECT_EQ(clusters.members.front(), "member 0");
        EXPECT_EQ(clusters.memberIdentities, steps[s].memberIdentities) << "step " << s;
        const prep::MergeTree& tree = steps[s].result.tree;
        alone = alone ||
                prep::memberIdentities(steps[s].result.labels, prep::identitiesFromTree(tree, 5)) !=
                    steps[s].memberIdentities;
        someoneMoved = someoneMoved || clusters.memberIdentities != steps[s - 1].memberIdentities;
    }
    EXPECT_TRUE(someoneMoved) << "ERA5's members change group over its steps";
    EXPECT_TRUE(alone) << "the matching to the step before must matter here";

    std::stop_source stop;
    stop.request_stop();
    engine::StepClusteringRequest stopped;
    stopped.selection = request.selection;
    stopped.isovalue = 260.0F;
    EXPECT_THROW((void)engine::clusterTimeStep(stopped, stop.get_token()), data::Cancelled);
}

// ensil render --times with a floor: one colour scale over all the frames, spanning every
// step's floor values, said in the colour bar; a frame then differs from its step drawn alone
// (whose floor spans only its own values), but not where the floor is not drawn.
TEST(RenderTimes, TheFloorHasOneColourScaleOverAllTheSteps) {
    const data::DataSelection era5{.paths = {kEra5.toStdString()}, .variable = "t"};
    gl::RenderSettings settings;
    settings.floor = gl::FloorContent::ColumnMaximum;
    const auto scale = engine::floorScaleOverSteps(era5, {0, 3}, settings);
    ASSERT_TRUE(scale.has_value());
    bool wider = false;
    std::size_t narrower = 0;  // a step whose own floor spans less than the scale
    for (std::size_t t = 0; t < 4; ++t) {
        data::DataSelection one = era5;
        one.timeIndex = t;
        const data::Ensemble e = data::openEnsemble(one);
        const prep::EnsembleMoments moments = prep::computeEnsembleMoments(e);
        const gl::FloorMap own = engine::floorMapFor(
            e, moments.mean, engine::computeColumnMaxima(e, moments.mean), settings);
        EXPECT_LE(scale->first, own.minimum) << "step " << t;
        EXPECT_GE(scale->second, own.maximum) << "step " << t;
        if (scale->first < own.minimum || scale->second > own.maximum) {
            wider = true;
            narrower = t;
        }
    }
    EXPECT_TRUE(wider) << "ERA5's steps differ: some step's own range is narrower";
    EXPECT_FALSE(engine::floorScaleOverSteps(era5, {1, 1}, settings)) << "one step: its own";
    settings.floor = gl::FloorContent::ProbabilityMaximum;
    EXPECT_FALSE(engine::floorScaleOverSteps(era5, {0, 3}, settings)) << "0 to 1 already";

    test::TempDir dir;
    const QString pattern = QString::fromStdString(dir.file("frame_%d.png"));
    // One cluster: the surfaces' colours cannot differ between a frame and its step alone.
    const QStringList common{"--var",          "t",          "--iso",     "260",    "--floor",
                             "column-maximum", "--clusters", "1",         "--size", "320x200",
                             "--frames",       "1",          "--no-cache"};
    const test::EnsilRun run =
        test::runEnsil(QStringList{"render", kEra5, "--times", "0:3", "--out", pattern} + common);
    ASSERT_EQ(run.code, 0) << run.err.toStdString();
    EXPECT_TRUE(run.out.contains("one scale for all 4 steps")) << run.out.toStdString();
    const QString single = QString::fromStdString(dir.file("single.png"));
    const QString step = QString::number(narrower);
    const test::EnsilRun alone = test::runEnsil(
        QStringList{"render", kEra5, "--times", step + ":" + step, "--out", single} + common);
    ASSERT_EQ(alone.code, 0) << alone.err.toStdString();
    EXPECT_FALSE(alone.out.contains("one scale")) << alone.out.toStdString();
    const QImage inSeries(QString::fromStdString(dir.file("frame_" + step.toStdString() + ".png")));
    ASSERT_FALSE(inSeries.isNull());
    EXPECT_NE(inSeries, QImage(single))
        << "the floor of step " << narrower << " takes the colours of the scale over all steps";
    // Without a floor the frame is the step alone: only the floor's colours changed.
    const QString noFloor = QString::fromStdString(dir.file("plain_%d.png"));
    QStringList plain = common;
    plain[plain.indexOf("column-maximum")] = QStringLiteral("none");
    ASSERT_EQ(
        test::runEnsil(QStringList{"render", kEra5, "--times", "0:3", "--out", noFloor} + plain)
            .code,
        0);
    const QString plainAlone = QString::fromStdString(dir.file("plain_alone.png"));
    ASSERT_EQ(
        test::runEnsil(
            QStringList{"render", kEra5, "--times", step + ":" + step, "--out", plainAlone} + plain)
            .code,
        0);
    EXPECT_EQ(QImage(QString::fromStdString(dir.file("plain_" + step.toStdString() + ".png"))),
              QImage(plainAlone));
}

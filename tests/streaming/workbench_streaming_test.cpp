// The workbench's way with an ensemble larger than its memory budget (issue 20): a thinned copy
// read slab by slab (data/thinned_ensemble.h), the choice between it and a whole read
// (engine/workbench_reading.h), and each isovalue's surfaces and distances from the whole
// data in slabs, equal to the in-memory job's (engine/streamed_isovalue_job.h).
#include <gtest/gtest.h>

#include <limits>
#include <set>
#include <string>

#include "data/demo_ensemble.h"
#include "data/ensemble_reader.h"
#include "data/error.h"
#include "data/netcdf_writer.h"
#include "data/thinned_ensemble.h"
#include "engine/isovalue_job.h"
#include "engine/streamed_isovalue_job.h"
#include "engine/streaming_run.h"
#include "engine/time_series.h"
#include "engine/workbench_reading.h"
#include "preprocessing/mesh_cache.h"
#include "preprocessing/streaming_preprocess.h"
#include "tests/streaming/same_results.h"
#include "tests/support/temp_dir.h"

using namespace ensil;

namespace {

// The demo (24 members, 97 x 96 x 25: odd counts along x and z, so their last points are not
// on the stride) written as NetCDF: enough members that the slab passes (a whole-grid sum and
// one member meshed at a time) need less than the whole ensemble in memory.
constexpr std::size_t kNx = 97, kNy = 96, kNz = 25;
std::string writeDemo(const test::TempDir& dir) {
    const std::string path = dir.file("demo.nc");
    data::writeNetcdf(
        data::makeDemoEnsemble({.members = 24, .nx = kNx, .ny = kNy, .nz = kNz}).ensemble, path);
    return path;
}

// A budget the demo's in-memory peak just misses.
std::size_t budgetBetween(const data::EnsembleDescription& d) {
    return engine::inMemoryPeakBytes(d) - 1;
}

}  // namespace

TEST(ThinnedEnsemble, KeepsEveryStridethPointAndTheLastOfEachAxis) {
    EXPECT_EQ(data::thinnedIndices(9, 2), (std::vector<std::size_t>{0, 2, 4, 6, 8}));
    EXPECT_EQ(data::thinnedIndices(10, 3), (std::vector<std::size_t>{0, 3, 6, 9}));
    EXPECT_EQ(data::thinnedIndices(11, 3), (std::vector<std::size_t>{0, 3, 6, 9, 10}));
    EXPECT_EQ(data::thinnedIndices(2, 5), (std::vector<std::size_t>{0, 1}));

    test::TempDir dir;
    const data::DataSelection selection{.paths = {writeDemo(dir)}};
    const data::EnsembleDescription d = data::describeEnsemble(selection);
    const data::Ensemble whole = data::openEnsemble(selection);
    for (const std::size_t stride : {2u, 3u}) {
        // Three slabs: kept layers fall inside slabs and on their first layers.
        const data::Ensemble copy =
            data::openThinnedEnsemble(selection, d, prep::evenSlabs(d, 3), stride);
        const auto xs = data::thinnedIndices(kNx, stride), ys = data::thinnedIndices(kNy, stride),
                   zs = data::thinnedIndices(kNz, stride);
        ASSERT_EQ(copy.grid.nx(), xs.size());
        ASSERT_EQ(copy.grid.ny(), ys.size());
        ASSERT_EQ(copy.grid.nz(), zs.size());
        EXPECT_EQ(copy.grid.x().back(), whole.grid.x().back()) << "the same box";
        EXPECT_EQ(copy.grid.z().values[1], whole.grid.z().values[stride]);
        ASSERT_EQ(copy.memberCount(), whole.memberCount());
        std::size_t differing = 0;
        for (std::size_t m = 0; m < copy.memberCount(); ++m) {
            EXPECT_EQ(copy.members[m].name, whole.members[m].name);
            for (std::size_t k = 0; k < zs.size(); ++k) {
                for (std::size_t j = 0; j < ys.size(); ++j) {
                    for (std::size_t i = 0; i < xs.size(); ++i) {
                        const float want =
                            whole.members[m].values[whole.grid.index(xs[i], ys[j], zs[k])];
                        differing +=
                            copy.members[m].values[copy.grid.index(i, j, k)] == want ? 0 : 1;
                    }
                }
            }
        }
        EXPECT_EQ(differing, 0u) << "stride " << stride;
    }
    // Slabs that leave layers out are refused before anything is read.
    std::vector<data::EnsemblePart> slabs = prep::evenSlabs(d, 3);
    slabs.pop_back();
    EXPECT_THROW((void)data::openThinnedEnsemble(selection, d, slabs, 2), data::Error);
}

TEST(WorkbenchReading, ReadsWholeWithinTheBudgetAndAThinnedCopyBeyondIt) {
    test::TempDir dir;
    const data::DataSelection selection{.paths = {writeDemo(dir)}};
    const data::EnsembleDescription d = data::describeEnsemble(selection);

    const engine::WorkbenchEnsemble whole =
        engine::readForWorkbench(selection, engine::inMemoryPeakBytes(d));
    EXPECT_FALSE(whole.streamed.has_value()) << "the in-memory peak fits the budget exactly";
    EXPECT_EQ(whole.ensemble.grid.pointCount(), d.grid.pointCount());

    const std::size_t budget = budgetBetween(d);
    const engine::WorkbenchEnsemble streamed = engine::readForWorkbench(selection, budget);
    ASSERT_TRUE(streamed.streamed.has_value());
    const engine::StreamedSource& source = *streamed.streamed;
    EXPECT_GE(source.stride, 2u);
    EXPECT_EQ(source.memoryLimit, budget);
    EXPECT_LE(engine::inMemoryPeakBytes(d) / source.stride / source.stride / source.stride,
              budget / 4)
        << "the copy and what is built from it keep to a quarter of the budget";
    EXPECT_LT(source.plan.memoryLimit, budget);
    EXPECT_TRUE(
        streamed.ensemble.grid.sameShapeAndCoordinates(data::thinnedGrid(d.grid, source.stride)));
    const std::string note = engine::streamedDataNote(source, streamed.ensemble);
    EXPECT_NE(note.find("larger than the workbench's memory budget"), std::string::npos) << note;
    EXPECT_NE(note.find(engine::everyNthPoint(source.stride)), std::string::npos) << note;
    EXPECT_EQ(engine::everyNthPoint(2), "every 2nd point");
    EXPECT_EQ(engine::everyNthPoint(3), "every 3rd point");
    EXPECT_EQ(engine::everyNthPoint(11), "every 11th point");

    // Too little for even the slab passes: refused, saying what would do.
    try {
        (void)engine::readForWorkbench(selection, 4096);
        FAIL() << "opened within 4 KiB";
    } catch (const data::Error& e) {
        EXPECT_EQ(e.kind(), data::ErrorKind::OutOfMemory) << e.what();
    }
}

TEST(StreamedIsovalueJob, GivesTheInMemoryJobsSurfacesDistancesAndCacheEntry) {
    test::TempDir dir;
    const data::DataSelection selection{.paths = {writeDemo(dir)}};
    const data::EnsembleDescription d = data::describeEnsemble(selection);
    const auto whole = std::make_shared<const data::Ensemble>(data::openEnsemble(selection));
    const prep::EnsembleMoments wholeMoments = prep::computeEnsembleMoments(*whole);
    engine::IsovalueJobInput input;
    input.options.isovalue = 30.0F;
    input.verticalExaggeration = 2.0F;
    input.ensemble = whole.get();
    input.moments = &wholeMoments;
    const engine::IsovalueOutcome want = engine::runIsovalueJob(input);

    engine::WorkbenchEnsemble read = engine::readForWorkbench(selection, budgetBetween(d));
    ASSERT_TRUE(read.streamed.has_value());
    const prep::EnsembleMoments copyMoments = prep::computeEnsembleMoments(read.ensemble);
    input.ensemble = &read.ensemble;
    input.moments = &copyMoments;
    input.cacheDirectory = dir.file("cache");
    input.sourceKey = data::sourceIdentity(selection);
    const engine::IsovalueOutcome got = engine::runStreamedIsovalueJob(input, *read.streamed);

    ASSERT_EQ(got.meshes.members.size(), want.meshes.members.size());
    for (std::size_t m = 0; m < got.meshes.members.size(); ++m) {
        EXPECT_TRUE(test::sameMesh(got.meshes.members[m], want.meshes.members[m]))
            << "member " << m;
    }
    EXPECT_TRUE(test::sameMesh(got.meshes.mean, want.meshes.mean)) << "the mean member";
    test::expectSameDistances(got.distances, want.distances);
    test::expectSameTree(got.tree, want.tree);
    test::expectSameDistancesToMean(got.distancesToMean, want.distancesToMean);
    EXPECT_EQ(got.meanOutlyingness, want.meanOutlyingness);
    // The copy's contour boxplot and P(f > c): one per member, on the copy's grid.
    EXPECT_EQ(got.boxplot.depth.size(), whole->memberCount());
    ASSERT_TRUE(got.exceedance);
    EXPECT_EQ(got.exceedance->size(), read.ensemble.grid.pointCount());

    // Opened again, the meshes come from the cache, the distances from the whole data again.
    const engine::IsovalueOutcome cachedRun = engine::runStreamedIsovalueJob(input, *read.streamed);
    EXPECT_TRUE(cachedRun.fromCache);
    EXPECT_EQ(cachedRun.distances.values, got.distances.values);
    EXPECT_EQ(cachedRun.distancesToMean, got.distancesToMean);
    EXPECT_TRUE(test::sameMesh(cachedRun.meshes.members.front(), want.meshes.members.front()));

    // Stored under the in-memory job's key: the in-memory job finds them there.
    input.ensemble = whole.get();
    input.moments = &wholeMoments;
    const engine::IsovalueOutcome again = engine::runIsovalueJob(input);
    EXPECT_TRUE(again.fromCache);
    for (std::size_t m = 0; m < again.meshes.members.size(); ++m) {
        EXPECT_TRUE(test::sameMesh(again.meshes.members[m], want.meshes.members[m]))
            << "member " << m;
    }
}

TEST(StreamedStepClusters, AreTheStepsClustersInMemory) {
    test::TempDir dir;
    const data::DataSelection selection{.paths = {writeDemo(dir)}};
    const data::EnsembleDescription d = data::describeEnsemble(selection);
    engine::StepClusteringRequest request;
    request.selection = selection;
    request.isovalue = 30.0F;
    request.k = 4;
    const engine::StepClusters inMemory = engine::clusterTimeStep(request, {});
    request.memoryLimit = budgetBetween(d);  // the distances from the slab pass
    const engine::StepClusters streamed = engine::clusterTimeStep(request, {});
    EXPECT_EQ(streamed.members, inMemory.members);
    EXPECT_EQ(streamed.memberIdentities, inMemory.memberIdentities);
    EXPECT_EQ(
        std::set<int>(inMemory.memberIdentities.begin(), inMemory.memberIdentities.end()).size(),
        4u)
        << "four groups to match";
}

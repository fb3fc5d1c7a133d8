// `ensil preprocess` in slabs (engine/streaming_run.h) against the in-memory run: the same
// results and cache entry; and peak memory within --memory-limit, measured on the real program.
#include "engine/streaming_run.h"

#include <gtest/gtest.h>

#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QStringList>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "data/demo_ensemble.h"
#include "data/ensemble_reader.h"
#include "data/netcdf_writer.h"
#include "preprocessing/mesh_cache.h"
#include "tests/streaming/same_results.h"
#include "tests/support/special_values.h"
#include "tests/support/temp_dir.h"

using namespace ensil;

namespace {

using test::kNaN;

// The demo (8 members, 36 x 20 x 9) with member 5 wholly missing.
std::string writeDemoWithAnEmptyMember(const test::TempDir& dir) {
    const std::string path = dir.file("demo.nc");
    data::Ensemble e = data::makeDemoEnsemble({.members = 8, .nx = 36, .ny = 20, .nz = 9}).ensemble;
    for (float& v : e.members[5].values) v = kNaN;
    data::writeNetcdf(e, path);
    return path;
}

const engine::PreprocessNotice kQuiet = [](const std::string&, const std::string&) {};

// `ensil ARGS...` run to its end: its exit code and the JSON object it printed (empty when
// it printed none).
std::pair<int, QJsonObject> runEnsil(const QStringList& args) {
    QProcess process;
    process.start(QStringLiteral(ENSIL_EXECUTABLE), args);
    if (!process.waitForFinished(600000) || process.exitStatus() != QProcess::NormalExit) {
        return {-1, {}};
    }
    return {process.exitCode(), QJsonDocument::fromJson(process.readAllStandardOutput()).object()};
}

}  // namespace

TEST(StreamingRun, GivesTheInMemoryRunsResultsAndCacheEntry) {
    test::TempDir dir;
    const std::string path = writeDemoWithAnEmptyMember(dir);
    const data::DataSelection selection{.paths = {path}};
    const data::EnsembleDescription d = data::describeEnsemble(selection);
    engine::PreprocessRequest request;
    request.isovalue = 30.0;
    request.clusters = 3;
    request.clustersGiven = true;
    request.sourceKey = data::sourceIdentity(selection);
    request.cacheDirectory = dir.file("memory-cache");
    const engine::PreprocessResult want = engine::preprocessEnsemble(
        std::make_shared<const data::Ensemble>(data::openEnsemble(selection)), request, kQuiet);
    request.cacheDirectory = dir.file("stream-cache");
    // Room for a few layers only: several slabs.
    const prep::StreamingPlan least = prep::planStreaming(d, std::size_t{1} << 30, 1);
    const std::size_t limit = least.resultBytes + least.memberBytes;
    const engine::PreprocessResult got =
        engine::preprocessStreaming(selection, d, request, limit, kQuiet);
    ASSERT_TRUE(got.streaming.has_value());
    EXPECT_GT(got.streaming->slabs.size(), 1u);
    EXPECT_EQ(got.membersWithoutData, want.membersWithoutData);
    ASSERT_EQ(got.ensemble->memberCount(), want.ensemble->memberCount());
    for (std::size_t m = 0; m < got.ensemble->memberCount(); ++m) {
        EXPECT_EQ(got.ensemble->members[m].name, want.ensemble->members[m].name);
    }
    test::expectSameDistances(got.distances, want.distances);
    test::expectSameTree(got.tree, want.tree);
    EXPECT_EQ(got.k, want.k);
    EXPECT_EQ(got.labels, want.labels);
    EXPECT_EQ(got.colors, want.colors);
    test::expectSameDistancesToMean(got.distancesToMean, want.distancesToMean);
    EXPECT_EQ(got.meanOutlyingness, want.meanOutlyingness);
    ASSERT_EQ(got.meshes.members.size(), want.meshes.members.size());
    for (std::size_t m = 0; m < got.meshes.members.size(); ++m) {
        EXPECT_TRUE(test::sameMesh(got.meshes.members[m], want.meshes.members[m])) << m;
    }
    // Stored under the in-memory run's key, so the workbench finds the meshes.
    const prep::PipelineOptions options{.isovalue = 30.0F};
    const std::string key = request.sourceKey +
                            data::membersWithoutDataKey(want.membersWithoutData) + "; " +
                            prep::pipelineKey(options, 1.0F);
    const auto stored = prep::MeshCache(dir.file("stream-cache")).load(key);
    ASSERT_TRUE(stored.has_value()) << "no cache entry under the in-memory run's key";
    ASSERT_TRUE(prep::MeshCache(dir.file("memory-cache")).load(key).has_value());
    for (std::size_t m = 0; m < stored->members.size(); ++m) {
        EXPECT_TRUE(test::sameMesh(stored->members[m], want.meshes.members[m])) << m;
    }
}

TEST(StreamingRun, RefusesWithoutAnIsovalueOrOutsideTheValues) {
    test::TempDir dir;
    const std::string path = writeDemoWithAnEmptyMember(dir);
    const data::DataSelection selection{.paths = {path}};
    const data::EnsembleDescription d = data::describeEnsemble(selection);
    engine::PreprocessRequest request;
    try {
        (void)engine::preprocessStreaming(selection, d, request, std::size_t{1} << 30, kQuiet);
        FAIL() << "streamed without an isovalue";
    } catch (const engine::PreprocessRefused& e) {
        EXPECT_EQ(e.exitCode(), 2);
        EXPECT_NE(std::string(e.what()).find("--iso"), std::string::npos) << e.what();
    }
    request.isovalue = 1e6;
    try {
        (void)engine::preprocessStreaming(selection, d, request, std::size_t{1} << 30, kQuiet);
        FAIL() << "streamed an isovalue outside the values";
    } catch (const engine::PreprocessRefused& e) {
        EXPECT_EQ(e.exitCode(), 1);
        EXPECT_NE(std::string(e.what()).find("outside the values of 'wind_speed'"),
                  std::string::npos)
            << e.what();
    }
}

TEST(StreamingRun, MemorySizesAreParsedOrRefusedSayingWhy) {
    std::string problem;
    EXPECT_EQ(engine::parseMemorySize("1GiB", problem), std::size_t{1} << 30);
    EXPECT_EQ(engine::parseMemorySize("512M", problem), std::size_t{512} << 20);
    EXPECT_EQ(engine::parseMemorySize("1.5 gb", problem), std::size_t{3} << 29);
    EXPECT_EQ(engine::parseMemorySize("64k", problem), std::size_t{64} << 10);
    EXPECT_EQ(engine::parseMemorySize("4096", problem), std::size_t{4096});
    for (const char* bad : {"", "GiB", "-1G", "0", "12 parsecs", "nan", "1e30"}) {
        problem.clear();
        EXPECT_FALSE(engine::parseMemorySize(bad, problem).has_value()) << bad;
        EXPECT_NE(problem.find("--memory-limit"), std::string::npos) << bad;
    }
}

// The memory-bound test: the real program's own peak resident memory over what it held when
// the run began (the libraries' share; `ensil preprocess --json` "memory", the kernel's peak
// counter reset at that point) stays within 1.2 times --memory-limit, while the in-memory run
// of the same file takes more than that.
TEST(StreamingRun, PeakMemoryStaysWithinTheLimitWhereTheInMemoryRunDoesNot) {
    test::TempDir dir;
    const QString path = QString::fromStdString(dir.file("big.nc"));
    // 40 members of 128 x 64 x 64: 80 MiB of values.
    ASSERT_EQ(runEnsil({"generate", "--members", "40", "--grid", "128x64x64", "--out", path}).first,
              0);
    const qint64 limit = qint64{32} << 20;
    const QStringList run{"preprocess", path, "--iso", "30", "--no-cache", "--json"};
    const auto [streamedCode, streamed] = runEnsil(run + QStringList{"--memory-limit", "32M"});
    const auto [wholeCode, whole] = runEnsil(run);
    ASSERT_EQ(streamedCode, 0);
    ASSERT_EQ(wholeCode, 0);
    ASSERT_TRUE(streamed.contains("streaming")) << "the run under the limit was not streamed";
    ASSERT_FALSE(whole.contains("streaming"));
    const auto taken = [](const QJsonObject& o) {
        const QJsonObject memory = o.value("memory").toObject();
        return static_cast<qint64>(memory.value("peak_resident_bytes").toDouble(-1)) -
               static_cast<qint64>(memory.value("resident_at_start_bytes").toDouble(0));
    };
#if defined(__SANITIZE_ADDRESS__)
    // Built with AddressSanitizer (the asan preset), freed memory waits in its quarantine (256
    // MiB by default) and every block has redzones and shadow: the resident memory measures
    // the sanitizer, not ensil (314 MiB over the start here, against 34 MiB in the ci build,
    // which checks the bound). Both runs have still been made and checked above.
    GTEST_SKIP() << "the memory bound is checked in the build without sanitizers";
#endif
    ASSERT_TRUE(streamed.contains("memory") && whole.contains("memory"))
        << "no memory figures: /proc/self/clear_refs could not reset the peak";
    EXPECT_LE(taken(streamed), limit * 12 / 10)
        << "streamed: " << (taken(streamed) >> 10) << " KiB over the start's resident memory";
    EXPECT_GT(taken(whole), limit * 12 / 10)
        << "the in-memory run (" << (taken(whole) >> 10) << " KiB) fits the limit too: the test "
        << "cannot tell";
}

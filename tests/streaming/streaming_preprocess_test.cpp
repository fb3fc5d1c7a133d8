// Streaming preprocessing (preprocessing/streaming_preprocess.h) against the in-memory path on
// the same file: the same meshes, distances, linkage and clusters, whatever the slabs.
#include "preprocessing/streaming_preprocess.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include "data/demo_ensemble.h"
#include "data/display_frame.h"
#include "data/ensemble_reader.h"
#include "data/error.h"
#include "data/netcdf_writer.h"
#include "preprocessing/clustering.h"
#include "preprocessing/default_isovalue.h"
#include "preprocessing/field_statistics.h"
#include "preprocessing/member_summaries.h"
#include "tests/support/special_values.h"
#include "tests/support/temp_dir.h"

using namespace ensil;

namespace {

using test::kNaN;

// What the in-memory path gives for the file (as engine/preprocess_run does it).
struct InMemory {
    data::Ensemble ensemble;
    std::vector<std::string> withoutData;
    prep::IsovalueMeshes meshes;
    prep::DistanceMatrix distances;
    std::vector<double> distancesToMean;
    float isovalue = 0.0F;
};

InMemory inMemory(const data::DataSelection& selection, const prep::PipelineOptions& given) {
    InMemory r;
    r.ensemble = data::openEnsemble(selection);
    r.withoutData = data::leaveOutMembersWithoutData(r.ensemble);
    const prep::FieldStatistics stats =
        prep::computeFieldStatistics(r.ensemble, prep::kIsovalueHistogramBins);
    r.isovalue = prep::defaultIsovalue(r.ensemble, stats);
    prep::PipelineOptions options = given;
    options.isovalue = r.isovalue;
    const prep::EnsembleMoments moments = prep::computeEnsembleMoments(r.ensemble);
    r.meshes = prep::buildIsovalueMeshes(r.ensemble, moments,
                                         data::DisplayFrame(r.ensemble.grid, 1.0F), options);
    r.distances = prep::computeDistanceMatrix(r.ensemble, r.isovalue);
    const auto& mean = moments.mean.values;
    r.distancesToMean = prep::distancesToField(r.ensemble, {mean.data(), mean.size()}, r.isovalue);
    return r;
}

bool sameMesh(const data::PackedMesh& a, const data::PackedMesh& b) {
    return a.vertices.size() == b.vertices.size() && a.indices == b.indices &&
           std::memcmp(a.vertices.data(), b.vertices.data(),
                       a.vertices.size() * sizeof(data::PackedVertex)) == 0 &&
           a.boundsMin == b.boundsMin && a.boundsMax == b.boundsMax &&
           a.outlyingnessScale == b.outlyingnessScale;
}

// The demo with member 2 wholly missing and member 4 missing over its lowest two layers, written
// to `path`.
void writeEnsembleWithGaps(const std::string& path) {
    data::Ensemble e =
        data::makeDemoEnsemble({.members = 7, .nx = 40, .ny = 24, .nz = 11}).ensemble;
    for (float& v : e.members[2].values) v = kNaN;
    for (std::size_t p = 0; p < 2 * 40 * 24; ++p) e.members[4].values[p] = kNaN;
    data::writeNetcdf(e, path);
}

}  // namespace

TEST(StreamingPreprocess, EqualsTheInMemoryPathForAnySlabs) {
    test::TempDir dir;
    const std::string path = dir.file("gaps.nc");
    writeEnsembleWithGaps(path);
    const data::DataSelection selection{.paths = {path}};
    const data::EnsembleDescription d = data::describeEnsemble(selection);
    const InMemory want = inMemory(selection, {});
    ASSERT_EQ(want.withoutData.size(), 1u);
    prep::PipelineOptions options;
    options.isovalue = want.isovalue;
    // Any partition of the 11 layers into slabs, one member meshed at a time or two.
    using Slabs = std::vector<std::pair<std::size_t, std::size_t>>;  // first layer, layers
    for (const auto& [slabs, atOnce] :
         {std::pair{Slabs{{0, 11}}, std::size_t{2}},
          std::pair{Slabs{{0, 2}, {2, 3}, {5, 2}, {7, 4}}, std::size_t{1}},
          std::pair{Slabs{{0, 2}, {2, 2}, {4, 2}, {6, 2}, {8, 3}}, std::size_t{2}}}) {
        prep::StreamingPlan plan;
        for (const auto& [first, layers] : slabs) plan.slabs.push_back({0, 7, first, layers});
        plan.membersAtOnce = atOnce;
        SCOPED_TRACE(testing::Message() << plan.slabs.size() << " slabs");
        double seenMin = 0.0, seenMax = 0.0;
        const prep::StreamedEnsemble got =
            prep::streamPreprocess(selection, d, plan, options, 1.0F, [&](double lo, double hi) {
                seenMin = lo;
                seenMax = hi;
            });
        EXPECT_EQ(got.membersWithoutData, std::vector<std::size_t>{2});
        ASSERT_EQ(got.memberNames.size(), want.ensemble.memberCount());
        for (std::size_t m = 0; m < got.memberNames.size(); ++m) {
            EXPECT_EQ(got.memberNames[m], want.ensemble.members[m].name);
        }
        const prep::FieldStatistics stats =
            prep::computeFieldStatistics(want.ensemble, prep::kIsovalueHistogramBins);
        EXPECT_EQ(seenMin, stats.minimum);
        EXPECT_EQ(seenMax, stats.maximum);
        // Distances: the same sums over another partition of the points.
        ASSERT_EQ(got.distances.size, want.distances.size);
        for (std::size_t i = 0; i < want.distances.size; ++i) {
            for (std::size_t j = 0; j < want.distances.size; ++j) {
                EXPECT_NEAR(got.distances.at(i, j), want.distances.at(i, j),
                            1e-9 * want.distances.at(i, j))
                    << i << ", " << j;
            }
        }
        // The same linkage and clusters.
        const prep::MergeTree a = prep::clusterMembers(got.distances);
        const prep::MergeTree b = prep::clusterMembers(want.distances);
        ASSERT_EQ(a.merges.size(), b.merges.size());
        for (std::size_t m = 0; m < a.merges.size(); ++m) {
            EXPECT_EQ(a.merges[m].a, b.merges[m].a);
            EXPECT_EQ(a.merges[m].b, b.merges[m].b);
            EXPECT_EQ(a.merges[m].size, b.merges[m].size);
            EXPECT_NEAR(a.merges[m].height, b.merges[m].height, 1e-9 * b.merges[m].height);
        }
        EXPECT_EQ(prep::clusterLabels(a, 3), prep::clusterLabels(b, 3));
        // The meshes exactly: each is made from the whole member, with the same moments.
        ASSERT_EQ(got.meshes.members.size(), want.meshes.members.size());
        for (std::size_t m = 0; m < want.meshes.members.size(); ++m) {
            EXPECT_FALSE(want.meshes.members[m].indices.empty());
            EXPECT_TRUE(sameMesh(got.meshes.members[m], want.meshes.members[m])) << "member " << m;
        }
        EXPECT_TRUE(sameMesh(got.meshes.mean, want.meshes.mean));
        EXPECT_EQ(got.meshes.triangles, want.meshes.triangles);
        EXPECT_EQ(got.distancesToMean, want.distancesToMean);
    }
}

TEST(StreamingPreprocess, PlansCoverTheGridWithinTheBudget) {
    test::TempDir dir;
    const std::string path = dir.file("demo.nc");
    data::writeNetcdf(data::makeDemoEnsemble({.members = 9, .nx = 30, .ny = 20, .nz = 13}).ensemble,
                      path);
    const data::EnsembleDescription d = data::describeEnsemble({.paths = {path}});
    const prep::StreamingPlan roomy = prep::planStreaming(d, std::size_t{1} << 30, 4);
    EXPECT_EQ(roomy.slabs.size(), 1u);
    EXPECT_EQ(roomy.membersAtOnce, 4u);
    const std::size_t least = roomy.resultBytes + roomy.memberBytes;
    for (std::size_t limit = least; limit < least + 13 * 30 * 20 * (4 * 9 + 40); limit += 9999) {
        const prep::StreamingPlan plan = prep::planStreaming(d, limit, 4);
        EXPECT_LE(plan.peakBytes(), limit);
        std::size_t next = 0;
        for (const data::EnsemblePart& slab : plan.slabs) {
            EXPECT_EQ(slab.firstLayer, next);
            EXPECT_GE(slab.layerCount, 2u);
            EXPECT_EQ(slab.firstMember, 0u);
            EXPECT_EQ(slab.memberCount, 9u);
            next += slab.layerCount;
        }
        EXPECT_EQ(next, 13u) << "limit " << limit;
    }
    try {
        (void)prep::planStreaming(d, least - 1, 4);
        FAIL() << "a budget below the least was planned";
    } catch (const data::Error& e) {
        EXPECT_EQ(e.kind(), data::ErrorKind::OutOfMemory);
        EXPECT_NE(std::string(e.what()).find("--memory-limit"), std::string::npos) << e.what();
    }
}

// The default isovalue (METHODS.md section 14): on every real file and variable a user opens,
// most members have a surface there, checked by meshing them; and the rule picks what it says.
#include "preprocessing/default_isovalue.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "data/display_frame.h"
#include "data/ensemble_reader.h"
#include "preprocessing/ensemble_moments.h"
#include "preprocessing/isosurface_pipeline.h"

using namespace ensil;

namespace {

struct RealCase {
    const char* file;
    const char* variable;
    const char* memberDim;
};

// Every file in tests/data/real that holds a 3D ensemble, with each of its variables.
constexpr RealCase kCases[] = {
    {"era5_eda_members.nc", "t", ""},         {"era5_eda_members.nc", "z", ""},
    {"eraint_uvz.nc", "z", "month"},          {"eraint_uvz.nc", "u", "month"},
    {"eraint_uvz.nc", "wind_speed", "month"}, {"uk_hires.nc", "air_potential_temperature", "time"},
    {"contour.cdf", "T", "frtime"},           {"contour.cdf", "Z", "frtime"},
};

struct Opened {
    data::Ensemble ensemble;
    prep::FieldStatistics statistics;
};

Opened open(const RealCase& c) {
    Opened o{data::openEnsemble({.paths = {std::string(ENSIL_SHARED_DATA_DIR "/") + c.file},
                                 .variable = c.variable,
                                 .memberDimension = c.memberDim}),
             {}};
    o.statistics = prep::computeFieldStatistics(o.ensemble, prep::kIsovalueHistogramBins);
    return o;
}

}  // namespace

TEST(DefaultIsovalue, OnEveryRealFileMostMembersHaveASurfaceThere) {
    for (const RealCase& c : kCases) {
        const Opened opened = open(c);
        const data::Ensemble& e = opened.ensemble;
        const prep::FieldStatistics& stats = opened.statistics;
        const float iso = prep::defaultIsovalue(e, stats);
        prep::PipelineOptions options;
        options.isovalue = iso;
        const prep::IsovalueMeshes meshes = prep::buildIsovalueMeshes(
            e, prep::computeEnsembleMoments(e), data::DisplayFrame(e.grid, 1.0F), options);
        // Independently of the rule's sample: every point of every member, and the meshes.
        std::size_t withSurface = 0;
        for (std::size_t m = 0; m < e.memberCount(); ++m) {
            std::size_t above = 0, valid = 0;
            for (const float v : e.members[m].values) {
                if (std::isnan(v)) continue;
                ++valid;
                above += v >= iso ? 1 : 0;
            }
            const double share = static_cast<double>(above) / static_cast<double>(valid);
            const bool surface = !meshes.members[m].indices.empty() && share >= prep::kLeastShare &&
                                 share <= 1.0 - prep::kLeastShare;
            withSurface += surface ? 1 : 0;
        }
        EXPECT_GE(static_cast<double>(withSurface), prep::kMostMembers * e.memberCount())
            << c.file << " " << c.variable << " at " << iso << ": " << withSurface << " of "
            << e.memberCount();
    }
}

TEST(DefaultIsovalue, PicksTheEligibleCandidateNearestTheNinetiethPercentile) {
    for (const RealCase& c : kCases) {
        const Opened opened = open(c);
        const data::Ensemble& e = opened.ensemble;
        const prep::FieldStatistics& stats = opened.statistics;
        const auto candidates = prep::isovalueCandidates(e, stats);
        ASSERT_EQ(candidates.size(), 10U);
        double best = 0.0;
        for (const auto& x : candidates) {
            if (x.membersWithSurface >= prep::kMostMembers) best = std::max(best, x.disagreement);
        }
        const auto eligible = [&](const prep::IsovalueCandidate& x) {
            return x.membersWithSurface >= prep::kMostMembers && x.disagreement >= 0.5 * best;
        };
        const float chosen = prep::defaultIsovalue(e, stats);
        const auto it = std::find_if(candidates.begin(), candidates.end(),
                                     [&](const auto& x) { return x.isovalue == chosen; });
        ASSERT_NE(it, candidates.end()) << c.file << " " << c.variable;
        EXPECT_TRUE(eligible(*it)) << c.file << " " << c.variable;
        for (const auto& x : candidates) {
            if (eligible(x)) {
                EXPECT_LE(std::abs(it->percentile - 90), std::abs(x.percentile - 90))
                    << c.file << " " << c.variable << ": " << x.percentile << " is nearer";
            }
        }
    }
}

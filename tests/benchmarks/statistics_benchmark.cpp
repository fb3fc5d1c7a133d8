// Speed of the ensemble statistics and the contour boxplot on the paper-sized demo ensemble
// (50 members, 256 x 128 x 16 points) at its default isovalue: computeEnsembleStatistics (every
// per-point statistic and the cells' level-crossing probability) and computeContourBoxplot
// (the inclusion depths of all members, median, band and outliers); then what a data set's
// or a time step's overview and each isovalue compute beside them: the value statistics, the
// moments, the spread alone, the exceedance alone and the distances to the mean, and the fields
// of the context surfaces: the members' median and the band's envelope. Prints medians
// over several runs, in seconds, and what the boxplot found, with the demo's regime of each
// outlier.
//
//   ensil_statistics_benchmark [--runs N]   (7 by default)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "data/demo_ensemble.h"
#include "data/working_memory.h"
#include "preprocessing/band_envelope.h"
#include "preprocessing/default_isovalue.h"
#include "preprocessing/ensemble_moments.h"
#include "preprocessing/ensemble_statistics.h"
#include "preprocessing/exceedance.h"
#include "preprocessing/field_statistics.h"
#include "preprocessing/inclusion_depth.h"
#include "preprocessing/member_median.h"
#include "preprocessing/member_spread.h"
#include "preprocessing/member_summaries.h"
#include "timing.h"

using ensil::bench::medianMs;

namespace {
const char* regimeName(ensil::data::DemoRegime regime) {
    switch (regime) {
        case ensil::data::DemoRegime::Zonal:
            return "zonal";
        case ensil::data::DemoRegime::Split:
            return "split";
        case ensil::data::DemoRegime::NorthFading:
            return "north-fading";
        case ensil::data::DemoRegime::Outlier:
            return "outlier";
    }
    return "?";
}
}  // namespace

int main(int argc, char** argv) {
    ensil::data::keepWorkingMemoryForReuse();  // as ensil does (data/working_memory.h)
    using namespace ensil;
    int runs = 7;
    for (int i = 1; i < argc; ++i) {
        if (std::string(argv[i]) == "--runs" && i + 1 < argc)
            runs = std::max(1, std::atoi(argv[++i]));
    }
    const auto demo = data::makeDemoEnsemble({});
    const auto& e = demo.ensemble;
    const float isovalue =
        prep::defaultIsovalue(e, prep::computeFieldStatistics(e, prep::kIsovalueHistogramBins));
    std::printf(
        "demo ensemble: %zu members x %zu x %zu x %zu = %zu points, %.1f MiB; "
        "default isovalue %.3f\n",
        e.memberCount(), e.grid.nx(), e.grid.ny(), e.grid.nz(), e.grid.pointCount(),
        static_cast<double>(e.bytes()) / (1024.0 * 1024.0), static_cast<double>(isovalue));

    prep::EnsembleStatistics statistics;
    const double statisticsMs =
        medianMs(runs, [&] { statistics = prep::computeEnsembleStatistics(e, isovalue); });
    std::printf("computeEnsembleStatistics:  %7.3f s  (median of %d)\n", statisticsMs / 1000.0,
                runs);

    prep::ContourBoxplot box;
    const double boxplotMs =
        medianMs(runs, [&] { box = prep::computeContourBoxplot(e, isovalue); });
    std::printf("computeContourBoxplot:      %7.3f s  (median of %d)\n", boxplotMs / 1000.0, runs);

    const auto time = [&](const char* what, const auto& work) {
        std::printf("%-28s%7.3f s  (median of %d)\n", what, medianMs(runs, work) / 1000.0, runs);
    };
    time("computeFieldStatistics:",
         [&] { (void)prep::computeFieldStatistics(e, prep::kIsovalueHistogramBins); });
    prep::EnsembleMoments moments;
    time("computeEnsembleMoments:", [&] { moments = prep::computeEnsembleMoments(e); });
    time("computeMemberSpread:", [&] { (void)prep::computeMemberSpread(e); });
    time("computeExceedance:", [&] { (void)prep::computeExceedance(e, isovalue); });
    time("computeMemberMedian:", [&] { (void)prep::computeMemberMedian(e); });
    time("computeBandEnvelope:", [&] { (void)prep::computeBandEnvelope(e, box.bandMembers); });
    const auto& mean = moments.mean.values;
    time("distancesToField (mean):", [&] {
        (void)prep::distancesToField(e, {mean.data(), mean.size()}, isovalue);
    });

    const auto [lowest, highest] = std::minmax_element(box.depth.begin(), box.depth.end());
    std::printf(
        "depths %.3f .. %.3f; median member %zu (depth %.3f); band of %zu members; "
        "lower fence %.3f\n",
        *lowest, *highest, box.median, box.depth[box.median], box.bandMembers.size(),
        box.lowerFence);
    std::printf("outliers:");
    for (const std::size_t m : box.outliers) {
        std::printf(" %zu (%s, depth %.3f)", m, regimeName(demo.regimes[m]), box.depth[m]);
    }
    std::printf("%s\n", box.outliers.empty() ? " none" : "");
    return 0;
}

// Stepping through an ensemble over time (issue 17, section 5): the paper-sized demo (`ensil
// generate`'s defaults: 50 members, 256 x 128 x 16) over 10 steps, written as one NetCDF file
// with a CF time dimension, then preprocessed step by step as `ensil preprocess --times all`
// does (preprocessTimeSeries: read the step, cache, meshes, similarity, clustering, matching
// to the previous step). Prints per step and as medians: a new step (mesh cache empty) and a
// cached step (the same steps again: mesh cache hit), and the matching alone.
//
//   ensil_time_benchmark [--steps N] [--dir DIR]   (DIR: where the file and cache go; a
//                                                    temporary folder by default, removed)
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "data/demo_ensemble.h"
#include "data/netcdf_writer.h"
#include "data/working_memory.h"
#include "engine/time_series.h"
#include "timing.h"

using ensil::bench::median;
namespace engine = ensil::engine;
namespace data = ensil::data;
using Clock = std::chrono::steady_clock;

namespace {

double since(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// Each stage's seconds (PreprocessResult::seconds) over the steps.
using Stages = std::map<std::string, std::vector<double>>;

// Each step's wall time from the end of the previous one, in ms.
std::vector<double> stepTimes(const engine::TimeSeriesRequest& request, std::vector<bool>& hits,
                              Stages& stages) {
    std::vector<double> times;
    hits.clear();
    auto last = Clock::now();
    (void)engine::preprocessTimeSeries(
        request, [](const std::string&, const std::string&) {}, {}, {},
        [&](const engine::TimeStepResult& step) {
            times.push_back(since(last));
            hits.push_back(step.result.fromCache);
            for (const auto& [name, value] : step.result.seconds) stages[name].push_back(value);
            last = Clock::now();
        });
    return times;
}

}  // namespace

int main(int argc, char** argv) {
    ensil::data::keepWorkingMemoryForReuse();  // as ensil does (data/working_memory.h)
    std::size_t steps = 10;
    std::string dirArgument;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--steps" && i + 1 < argc) {
            steps = std::max<std::size_t>(2, std::strtoul(argv[++i], nullptr, 10));
        } else if (a == "--dir" && i + 1 < argc) {
            dirArgument = argv[++i];
        }
    }
    const bool temporary = dirArgument.empty();
    const std::filesystem::path dir =
        temporary ? std::filesystem::temp_directory_path() /
                        ("ensil-time-benchmark-" + std::to_string(::getpid()))
                  : std::filesystem::path(dirArgument);
    std::filesystem::create_directories(dir);
    const std::string path = (dir / "demo_steps.nc").string();
    const std::filesystem::path cache = dir / "cache";
    std::filesystem::remove_all(cache);

    const data::DemoEnsembleParams params;  // ensil generate's defaults
    auto start = Clock::now();
    data::TimeCoordinate time{.units = data::kDemoTimeUnits, .values = {}};
    for (std::size_t t = 0; t < steps; ++t) {
        time.values.push_back(data::kDemoHoursPerStep * static_cast<double>(t));
    }
    data::writeNetcdfSteps(
        [&](std::size_t t) { return data::makeDemoEnsembleAt(params, t, steps).ensemble; }, time,
        path);
    std::printf("ensemble: %zu members, %zu x %zu x %zu, %zu steps, written in %.1f s to %s\n",
                params.members, params.nx, params.ny, params.nz, steps, since(start) / 1000.0,
                path.c_str());

    engine::TimeSeriesRequest request;
    request.selection.paths = {path};
    request.steps = {0, steps - 1};
    request.preprocess.clusters = 5;
    request.preprocess.cacheDirectory = cache.string();

    // One step alone, the read only: how much of a step is reading the file.
    std::vector<double> reads;
    for (std::size_t t = 0; t < steps; ++t) {
        data::DataSelection s = request.selection;
        s.timeIndex = t;
        start = Clock::now();
        (void)data::openEnsemble(s);
        reads.push_back(since(start));
    }

    std::vector<bool> hits;
    Stages freshStages, cachedStages;
    const std::vector<double> fresh = stepTimes(request, hits, freshStages);
    std::size_t freshHits = 0;
    for (const bool h : hits) freshHits += h ? 1 : 0;
    const std::vector<double> cached = stepTimes(request, hits, cachedStages);
    std::size_t cachedHits = 0;
    for (const bool h : hits) cachedHits += h ? 1 : 0;

    // The matching of one step to the previous alone (what the strip adds to a step kept in
    // memory): 50 members, 5 clusters.
    std::vector<int> labels(params.members), previous(params.members);
    for (std::size_t m = 0; m < params.members; ++m) {
        labels[m] = static_cast<int>(m % 5);
        previous[m] = static_cast<int>((m / 10) % 5);
    }
    const double matchMs = ensil::bench::medianMs(
        101, [&] { (void)engine::matchStepIdentities({}, 5, labels, previous); });

    std::printf("per step (ms):   step  read  new(uncached)  cached(mesh cache hit)\n");
    for (std::size_t t = 0; t < steps; ++t) {
        std::printf("                 %4zu %6.0f %10.0f %12.0f\n", t, reads[t], fresh[t],
                    cached[t]);
    }
    std::printf(
        "median of %zu steps (ms): read %.0f, new step %.0f (%zu of %zu from the cache), "
        "cached step %.0f (%zu of %zu from the cache), matching %.3f\n",
        steps, median(reads), median(fresh), freshHits, steps, median(cached), cachedHits, steps,
        matchMs);
    // Where a step's time goes (the stages preprocessing times; reading and field statistics
    // are the rest).
    for (const auto* stages : {&freshStages, &cachedStages}) {
        std::printf("median stage (ms), %s:", stages == &freshStages ? "new step" : "cached step");
        for (const auto& [name, values] : *stages) {
            std::printf(" %s %.0f", name.c_str(), median(values) * 1000.0);
        }
        std::printf("\n");
    }
    if (temporary) std::filesystem::remove_all(dir);
    return 0;
}

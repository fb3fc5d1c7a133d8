// The built-in demo ensemble: a wind-speed-like field of jet streams over the North Atlantic
// and Europe on pressure levels. Members fall into flow regimes (a single meandering jet, a
// split jet, a jet shifted north that fades eastward), so clusters exist, and one member is an
// outlier with a strong southern jet streak. A weaker subtropical jet that all members share
// gives a region where members agree. Deterministic for a given seed on every platform (only
// the fully specified mt19937_64 engine is used, never the implementation-defined
// distributions). Pure function; callable from any thread.
#pragma once

#include <cstddef>
#include <cstdint>
#include <stop_token>

#include "data/ensemble.h"
#include "data/job.h"

namespace ensil::data {

struct DemoEnsembleParams {
    std::size_t members = 50;
    std::size_t nx = 256;  // longitude, 80 W .. 40 E
    std::size_t ny = 128;  // latitude, 25 N .. 75 N
    std::size_t nz = 16;   // pressure levels, 1000 .. 100 hPa, evenly spaced in log-pressure
    std::uint64_t seed = 1;

    bool operator==(const DemoEnsembleParams&) const = default;
};

// Which flow regime a demo member was generated from (exposed so tests can check clusters).
enum class DemoRegime { Zonal, Split, NorthFading, Outlier };

struct DemoEnsemble {
    Ensemble ensemble;
    std::vector<DemoRegime> regimes;  // one per member
};

// Throws Error(InvalidArgument) for fewer than 1 member or fewer than 2 points along an axis,
// Error(OutOfMemory) before allocating when the members would not fit (checkMemoryFor), and
// Cancelled when stopped (checked per member).
DemoEnsemble makeDemoEnsemble(const DemoEnsembleParams& params, const std::stop_token& stop = {},
                              const Progress& progress = {});

// The demo as it evolves over `steps` steps, at step `step` (0 .. steps - 1): every jet drifts
// east and its core north, and about a third of the members change regime, each at its own
// step (a smooth blend over a few steps), so clusters split and merge from step to step. Step 0
// is makeDemoEnsemble's ensemble. `regimes` gives each member's nearer regime at that step.
// Throws as makeDemoEnsemble, and Error(InvalidArgument) for step >= steps.
DemoEnsemble makeDemoEnsembleAt(const DemoEnsembleParams& params, std::size_t step,
                                std::size_t steps, const std::stop_token& stop = {},
                                const Progress& progress = {});

// The hours between the demo's steps, and its first step's date (the CF time units).
inline constexpr double kDemoHoursPerStep = 12.0;
inline constexpr const char* kDemoTimeUnits = "hours since 2026-01-01 00:00:00";

}  // namespace ensil::data

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

}  // namespace ensil::data

// Value statistics of a whole ensemble: range, missing points, and a histogram. They feed the
// isovalue control (its range and the histogram drawn behind it) and `ensil info`. Pure
// function; runs on any thread.
#pragma once

#include <cstddef>
#include <cstdint>
#include <stop_token>
#include <vector>

#include "data/ensemble.h"
#include "data/job.h"

namespace ensil::prep {

struct FieldStatistics {
    float minimum = 0.0F;  // over valid (non-NaN) values; 0 when none are valid
    float maximum = 0.0F;
    double mean = 0.0;
    std::size_t validCount = 0;
    std::size_t missingCount = 0;          // NaN values over all members
    std::vector<std::uint64_t> histogram;  // bins of equal width over [minimum, maximum]
};

// The histogram the workbench's isovalue control shows and the default isovalue is taken from.
inline constexpr std::size_t kIsovalueHistogramBins = 128;

// Throws data::Cancelled if stop is requested.
FieldStatistics computeFieldStatistics(const data::Ensemble& ensemble, std::size_t bins,
                                       const std::stop_token& stop = {},
                                       const data::Progress& progress = {});

}  // namespace ensil::prep

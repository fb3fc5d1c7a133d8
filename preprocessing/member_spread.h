// The members' sample standard deviation at every grid point, alone: the spread the floor and
// the sections show (METHODS.md section 17), by the rule of EnsembleStatistics::stddev (finite
// values count; NaN where fewer than two members have one). Computing the whole
// EnsembleStatistics for it (minimum, maximum, exceedance, level crossings) took about four
// times as long, at every data set opened and every time step read. Pure function; any thread.
#pragma once

#include <stop_token>

#include "data/ensemble.h"

namespace ensil::prep {

// One pass over blocks of points on every core; per point, the deviations from the first
// member's value there (0 where it has none) summed in double, so the sums stay exact for large
// values such as geopotential: s^2 = (sum d^2 - (sum d)^2 / n) / (n - 1). Each point's members
// are taken in member order, so the result does not depend on the threads.
// Throws data::Cancelled; data::Error(InvalidArgument) for an ensemble without members or a
// member whose value count differs from the grid's point count.
data::FieldValues computeMemberSpread(const data::Ensemble& ensemble,
                                      const std::stop_token& stop = {});

}  // namespace ensil::prep

// The mean member (METHODS.md section 5): the grid-point mean over all members, meshed
// later like any member and drawn as a gray surface for context. A point missing (NaN) in some
// members is averaged over the members that have it; it is NaN only where every member misses
// it, so masked regions stay masked without one member's gap punching holes in the mean.
// Pure function; runs on any thread.
#pragma once

#include <stop_token>

#include "data/ensemble.h"
#include "data/job.h"

namespace ensil::prep {

// Throws data::Cancelled if stop is requested, data::Error(InvalidArgument) for an empty ensemble.
data::Member computeMeanMember(const data::Ensemble& ensemble, const std::stop_token& stop = {},
                               const data::Progress& progress = {});

}  // namespace ensil::prep

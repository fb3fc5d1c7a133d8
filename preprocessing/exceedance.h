// The exceedance probability alone, P(f > c) at every grid point (METHODS.md section 17): the
// share of the members with a finite value there that exceed c, by the rule of
// EnsembleStatistics::exceedance (NaN where no member has a value). The context surfaces (the
// floor's column maximum, a section) need nothing else of the statistics; computing all of them
// (mean, standard deviation, minimum, maximum, level crossings) took about five times as long,
// at every isovalue and time step. Pure function; any thread.
#pragma once

#include <stop_token>

#include "data/ensemble.h"

namespace ensil::prep {

// One pass over blocks of points on every core, counting without branches. The same values as
// computeEnsembleStatistics(...).exceedance, to the bit. Throws data::Cancelled;
// data::Error(InvalidArgument) for an ensemble without members, a non-finite isovalue or a
// member whose value count differs from the grid's point count.
data::FieldValues computeExceedance(const data::Ensemble& ensemble, float isovalue,
                                    const std::stop_token& stop = {});

}  // namespace ensil::prep

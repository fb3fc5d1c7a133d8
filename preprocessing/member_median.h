// The members' median at every grid point (METHODS.md section 17): the middle of the finite
// values there, or the mean of the two middle ones when their count is even; NaN where no
// member has a value. Its isosurface at c is the surface where half the members exceed c: at a
// grid point the median exceeds c where more than half of the members with a value there do
// (P(f > c) > 0.5), and not where fewer than half do, so it separates the same points as the
// 0.5 surface of P(f > c). Between grid points it is placed by the same linear interpolation as
// the members' own surfaces, where the 0.5 surface of the probability, a field that steps
// between multiples of 1/n, puts a vertex half-way along every cell edge it crosses (on ERA5's
// two levels, flat curtains half-way between them). Pure function; any thread.
#pragma once

#include <stop_token>

#include "data/ensemble.h"

namespace ensil::prep {

// On every core, a block of points at a time. Throws data::Cancelled, and
// data::Error(InvalidArgument) for an ensemble without members or a member whose value count
// differs from the grid's point count.
data::FieldValues computeMemberMedian(const data::Ensemble& ensemble,
                                      const std::stop_token& stop = {});

}  // namespace ensil::prep

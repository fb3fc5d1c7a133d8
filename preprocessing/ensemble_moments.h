// Grid-point mean and (population) variance over the members, NaN-aware: a point counts only
// the members that have it. The mean is the mean member of METHODS.md section 5. Together
// they give every member's outlyingness at any point on its isosurface without an N x N pass:
//   o_i(x) = sum_j (f_j(x) - f_i(x))^2 / N = variance(x) + (f_i(x) - mean(x))^2,
// and on member i's isosurface f_i(x) is the isovalue. The centred form keeps float precision
// even for large values such as geopotential. Pure function; any thread.
#pragma once

#include <stop_token>

#include "data/ensemble.h"
#include "data/job.h"

namespace ensil::prep {

struct EnsembleMoments {
    data::Member mean;  // NaN where every member misses the point
    data::FieldValues variance;
};

// Throws data::Cancelled, data::Error(InvalidArgument) for an empty ensemble.
EnsembleMoments computeEnsembleMoments(const data::Ensemble& ensemble,
                                       const std::stop_token& stop = {},
                                       const data::Progress& progress = {});

}  // namespace ensil::prep

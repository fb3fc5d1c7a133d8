// Writes an ensemble as one CF-1.8 NetCDF file: variable (member, z, y, x) with a member
// dimension, coordinate variables for every dimension, and units / long_name / standard_name /
// axis attributes, so ncdump, xarray and ensil's own reader understand it. Callable from any
// thread; the caller owns the ensemble.
#pragma once

#include <functional>
#include <string>

#include "data/ensemble.h"

namespace ensil::data {

// Called after each member is written with (members written, members total).
using WriteProgress = std::function<void(std::size_t, std::size_t)>;

// Throws Error(WriteFailed) naming the file and the netCDF library's reason. A failed write
// removes the partial file so no truncated ensemble is left behind.
void writeNetcdf(const Ensemble& ensemble, const std::string& path,
                 const WriteProgress& progress = {});

}  // namespace ensil::data

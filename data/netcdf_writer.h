// Writes an ensemble as one CF-1.8 NetCDF file: variable (member, z, y, x) with a member
// dimension, coordinate variables for every dimension, and units / long_name / standard_name /
// axis attributes, so ncdump, xarray and ensil's own reader understand it. Callable from any
// thread; the caller owns the ensemble.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "data/ensemble.h"

namespace ensil::data {

// Called after each member is written with (members written, members total).
using WriteProgress = std::function<void(std::size_t, std::size_t)>;

// Throws Error(WriteFailed) naming the file and the netCDF library's reason. A failed write
// removes the partial file so no truncated ensemble is left behind.
void writeNetcdf(const Ensemble& ensemble, const std::string& path,
                 const WriteProgress& progress = {});

// A CF time coordinate: "hours since 2026-01-01 00:00:00" and one value per step.
struct TimeCoordinate {
    std::string units;
    std::vector<double> values;
};

// The ensemble at each time step, made when it is written (one step in memory at a time).
using EnsembleAtStep = std::function<Ensemble(std::size_t step)>;

// Writes one ensemble per step of `time` as variable (time, member, z, y, x) with the CF time
// coordinate, so the readers offer the steps with their dates (TimeSteps). Every step must
// have the first's members and grid. Progress: (members written, members of all steps).
// Throws as writeNetcdf, Error(InvalidArgument) when a step does not match the first.
void writeNetcdfSteps(const EnsembleAtStep& stepAt, const TimeCoordinate& time,
                      const std::string& path, const WriteProgress& progress = {});

}  // namespace ensil::data

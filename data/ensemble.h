// An ensemble of scalar fields on one rectilinear grid. Each member owns one contiguous float
// block in the grid's x-fastest order, so preprocessing walks it without copies. Missing values
// are NaN. Built by a reader or the demo generator, then treated as immutable and shared
// read-only between threads (std::shared_ptr<const Ensemble>).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "data/bulk_allocator.h"
#include "data/grid.h"
#include "data/grid_mapping.h"

namespace ensil::data {

// (Here rather than in ensemble_reader.h, which includes this file, so that Ensemble can hold it.)
// The steps DataSelection::timeIndex picks from (the dimension(s) fixed to one index, e.g.
// forecast times): the dimension's name and one label per step, ISO 8601 where the file dates
// it ("2017-01-01T12:00"), else the index. Empty (no labels) when the data have no steps.
struct TimeSteps {
    std::string dimension;
    std::vector<std::string> labels;
    [[nodiscard]] std::size_t count() const { return labels.size(); }
    bool operator==(const TimeSteps&) const = default;
};

struct Member {
    std::string name;    // e.g. "member 7", "2012-10-17T00"
    FieldValues values;  // grid.pointCount() values, NaN where missing
};

struct Ensemble {
    std::string variable;         // variable name, e.g. "wind_speed"
    std::string longName;         // CF long_name, may be empty
    std::string units;            // e.g. "m s-1"
    std::string memberDimension;  // name of the dimension members came from, e.g. "number"
    std::string source;           // where it came from (file path or "demo"), for the UI
    Grid grid;
    // The other dimensions fixed to one index, as EnsembleDescription says them:
    // "time = 0 of 4 (2017-01-01T00:00)".
    std::vector<std::string> fixedDimensions;
    // The steps the time index picks from, as EnsembleDescription::timeSteps says them.
    TimeSteps timeSteps;
    GridMapping gridMapping;  // the horizontal axes' map projection, when the file names one
    std::vector<Member> members;
    // Values that were +inf or -inf in the file: openEnsemble() makes them NaN (missing), since
    // no isosurface, range or distance can use them; the count is kept so it can be said.
    std::size_t infiniteValues = 0;
    // What the reader read around and the user should know, one sentence each: e.g. a damaged
    // GRIB message it skipped, naming the byte offset. Empty for a clean read.
    std::vector<std::string> warnings;

    [[nodiscard]] std::size_t memberCount() const { return members.size(); }
    [[nodiscard]] std::size_t bytes() const {
        return members.size() * grid.pointCount() * sizeof(float);
    }
};

}  // namespace ensil::data

// ensil's errors as Python exceptions, with the command line's messages (without its
// "ensil <command>: " prefix):
//   ensil.Error (RuntimeError)        what ensil cannot do with these data: a missing or
//                                     unreadable file, an isovalue outside the values, a project
//                                     that does not validate (the command line's exit status 1);
//                                     `.kind` names the data error ("file_not_found", ...) and
//                                     `.choices` lists what would work, where there is a list
//   ensil.ArgumentError (ensil.Error, ValueError)
//                                     a refused argument: a setting out of its range, more
//                                     clusters than members (the command line's exit status 2)
// data::Cancelled becomes the Python exception that asked for it (interruptible.h).
#pragma once

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>
#include <stdexcept>
#include <string>

#include "data/level_range.h"
#include "data/region.h"

namespace ensil::python {

// A refused argument, raised as ensil.ArgumentError.
class ArgumentError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The level range a `levels=` argument gives ("1000:100hPa"; data/level_range.h), none for "";
// a malformed one raises ensil.ArgumentError naming the argument.
std::optional<data::LevelRange> levelsArgument(const std::string& text);

// The region a `bbox=` argument gives (data/region.h): (lon0, lon1, lat0, lat1) in degrees, any
// sequence of four numbers, or the command line's text "LON0,LON1,LAT0,LAT1"; none for None. A
// malformed one raises ensil.ArgumentError naming the argument.
std::optional<data::Region> bboxArgument(const pybind11::object& given);

// Creates the exception types in `m` and translates ensil's C++ exceptions into them.
void bindErrors(pybind11::module_& m);

}  // namespace ensil::python

namespace ensil::python {
// Says `message` as an ensil.DataWarning (a UserWarning), as the command line prints its
// "warning:" and "note:" lines, pointing at the Python frame `stackLevel` up (1: the one that
// called into the module). Throws pybind11::error_already_set when warnings are errors.
void warn(const std::string& message, int stackLevel = 1);
}  // namespace ensil::python

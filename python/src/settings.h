// Settings between Python and the one setting table (session/setting_table.h): a value
// given from Python is written as the command line's text and checked by the command line's own
// parser, so the ranges and the refusals are the same ("--thickness '5' is refused: it must be
// a number from 0.0001 to 0.5"); a setting without a command-line option is named by its id.
// Called with the GIL held.
#pragma once

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string_view>

#include "session/setting_table.h"

namespace ensil::python {

// The setting named `id`; ensil.ArgumentError naming the settings there are when none is.
const session::Setting& settingNamed(std::string_view id);
// Python's bool, int, float or str (a choice's name, "#rrggbb") as the setting's value, parsed
// as the command line parses it. Throws ArgumentError when refused, naming `argument` (the
// Python argument it came as, e.g. "colour_map"), else the setting's option or id.
double settingFromPython(const session::Setting& setting, const pybind11::handle& value,
                         const std::string& argument = {});
// The value as Python has it: float, int, bool, or str for choices and colours.
pybind11::object settingToPython(const session::Setting& setting, double value);
// A number the command line takes as `option` (--iso, --error) with its range and refusal.
double boundedNumber(const char* option, double given, double minimum, double maximum);

}  // namespace ensil::python

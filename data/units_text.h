// A variable's units as a person reads them in a picture or a control: "m**2 s**-2" (ECMWF's
// files), "m2 s-2" and "m^2.s^-2" become "m² s⁻²". Only the exponents are typeset; the units
// stay as the file gives them, symbol for symbol. Units that are not all symbols with
// exponents ("days since 1900-01-01", "1", "degrees_north") come back unchanged. Files, the
// command line's messages and the statistics file keep the units as written. Pure; any thread.
#pragma once

#include <string>
#include <string_view>

namespace ensil::data {

// Written by hand, not with udunits: ut_format prints the unit udunits parsed, in its own
// terms, not the file's text (to udunits "kg kg**-1", specific humidity, is a dimensionless
// unit like any ratio), where a picture must say what the file says; only the exponents'
// notation is changed here.
std::string readableUnits(std::string_view units);

}  // namespace ensil::data

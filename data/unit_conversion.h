// Converting values between units by UDUNITS-2, Unidata's library and unit database (what CF,
// CDO and xarray's pint-xarray rely on): "hPa" to "Pa", "km" to "m", "millibars", "degC" to "K".
// The database is read once, on first use. Thread-safe: one lock around every UDUNITS-2 call
// (its parser keeps global state).
#pragma once

#include <optional>
#include <string>

namespace ensil::data {

// `value` in `from` expressed in `to`; nullopt when either unit is unknown to UDUNITS-2 or the
// two measure different things (hPa and m).
std::optional<double> convertUnits(double value, const std::string& from, const std::string& to);

// Whether UDUNITS-2 knows the unit ("degrees_north" yes, "level" no).
bool isKnownUnit(const std::string& units);

}  // namespace ensil::data

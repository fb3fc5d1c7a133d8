// Where a map or a cross-section lies (engine/ensemble_section.h), resolved against a grid:
// the samples' fractional grid indices, where each column and row of them lies across the
// plot, the axes' ticks and titles, and a map's coastlines, borders and graticule. A level is
// taken in its own units (500 hPa on an axis in Pa), a latitude or longitude through the grid's
// map projection (geo::MapProjection), a path along the great circle. Pure; any thread.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "data/ensemble.h"
#include "engine/ensemble_section.h"
#include "preprocessing/field_section.h"

namespace ensil::engine {

// A place resolved against a grid: its layout and the grid places of its samples.
struct PlacedSection : SectionLayout {
    prep::SectionLattice lattice;
};

// Throws data::Error(InvalidArgument) naming the place and the grid's range when the place
// lies outside the data, or when a latitude or longitude is asked of data without geography.
PlacedSection placeSection(const data::Ensemble& ensemble, const SectionPlace& place);

// A place given as text, as the command line takes it: a level "500hPa", "850 hPa", "5km",
// "1500m", "index:3" or a bare number (the vertical axis's own units); a latitude "45",
// "45N", "45S", "45°N"; a longitude "10", "10E", "10W", "10°W"; a path "LON,LAT:LON,LAT".
// nullopt with `problem` set (what was wrong, what is taken) when the text does not read.
std::optional<SectionPlace> parseLevel(const std::string& text, std::string& problem);
std::optional<SectionPlace> parseLatitude(const std::string& text, std::string& problem);
std::optional<SectionPlace> parseLongitude(const std::string& text, std::string& problem);
std::optional<SectionPlace> parsePath(const std::string& text, std::string& problem);
// The one of those four that reads a place of `kind`.
std::optional<SectionPlace> parseSectionPlace(SectionKind kind, const std::string& text,
                                              std::string& problem);

// "10°E", "45°N", "0°": a longitude is put within -180 to 180 first.
std::string degreesText(double value, bool latitude);

}  // namespace ensil::engine

// How a grid's horizontal axes relate to the Earth: the CF conventions' grid mapping (a
// variable named by the data variable's `grid_mapping` attribute, whose `grid_mapping_name`
// and numeric attributes define a map projection, e.g. rotated_latitude_longitude with
// grid_north_pole_latitude). The geo/ layer turns it into a PROJ transformation; the data
// layer only records what the file says. A value type; any thread.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace ensil::data {

struct GridMapping {
    // The CF grid_mapping_name ("rotated_latitude_longitude", "lambert_conformal_conic", ...);
    // empty when the file names none (plain longitude/latitude axes, or no geography at all).
    std::string name;
    // The mapping variable's numeric attributes, in file order; a list-valued attribute (two
    // standard parallels) keeps all its values. A mapping made from WRF's global attributes
    // (data/wrf_conventions.h) has CF names plus origin_longitude and origin_latitude, the
    // point where the grid's x and y are 0 (data/proj_definition.h sets the false easting and
    // northing so), and wrf_map_proj, WRF's MAP_PROJ.
    std::vector<std::pair<std::string, std::vector<double>>> parameters;

    [[nodiscard]] bool empty() const { return name.empty(); }
    // The attribute's first (index 0) or second value; nullopt when absent.
    [[nodiscard]] std::optional<double> parameter(const std::string& key,
                                                  std::size_t index = 0) const {
        for (const auto& [k, values] : parameters) {
            if (k == key && index < values.size()) return values[index];
        }
        return std::nullopt;
    }
    bool operator==(const GridMapping&) const = default;
};

}  // namespace ensil::data

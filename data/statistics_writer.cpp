#include "data/statistics_writer.h"

#include <netcdf.h>

#include <array>
#include <charconv>
#include <cstddef>
#include <limits>

#include "data/error.h"
#include "data/netcdf_cf.h"

namespace ensil::data {
namespace {

// The shortest text that reads back as the same float: "260", "28.4".
std::string numberText(float value) {
    std::array<char, 32> text{};
    const auto [end, status] = std::to_chars(text.data(), text.data() + text.size(), value);
    return status == std::errc() ? std::string(text.data(), end) : std::to_string(value);
}

std::string joined(const std::vector<std::string>& parts, const std::string& separator) {
    std::string text;
    for (const std::string& part : parts) {
        if (!text.empty()) text += separator;
        text += part;
    }
    return text;
}

// The variable the data variables' grid_mapping attribute names: "crs", unless an axis took
// that name.
std::string mappingVariableName(const Grid& grid) {
    for (const char* candidate : {"crs", "grid_mapping", "ensil_grid_mapping"}) {
        bool taken = false;
        for (int a = 0; a < 3; ++a) {
            taken = taken || grid.axis(a).name == candidate ||
                    cellDimensionName(grid.axis(a)) == candidate;
        }
        if (!taken) return candidate;
    }
    return "ensil_crs";
}

void writeFile(const StatisticsFile& f, const NetcdfOutput& nc) {
    const Grid& grid = f.grid;
    std::array<CfCoordinate, 3> points{};
    std::array<CfCoordinate, 3> cells{};
    for (int a = 2; a >= 0; --a) {  // z, y, x: the CF order of dimensions
        const Axis& axis = grid.axis(a);
        points[static_cast<std::size_t>(a)] =
            defineCfCoordinate(nc, axis, a, axis.name, axis.size());
    }
    for (int a = 2; a >= 0; --a) {
        const Axis& axis = grid.axis(a);
        const std::string what = axis.standardName.empty() ? axis.name : axis.standardName;
        cells[static_cast<std::size_t>(a)] = defineCfCoordinate(
            nc, axis, a, cellDimensionName(axis), axis.size() - 1, what + " at cell centres");
    }
    std::string mapping;
    if (!f.gridMapping.empty()) {
        mapping = mappingVariableName(grid);
        int var = -1;
        nc.check(nc_def_var(nc.id(), mapping.c_str(), NC_INT, 0, nullptr, &var),
                 "define variable " + mapping);
        nc.text(var, "grid_mapping_name", f.gridMapping.name);
        for (const auto& [key, values] : f.gridMapping.parameters) {
            // Attributes starting with '_' are the library's own (_FillValue): not parameters.
            if (!key.empty() && key.front() != '_') nc.doubleAttribute(var, key.c_str(), values);
        }
    }
    const std::array<int, 3> pointDims{points[2].dimension, points[1].dimension,
                                       points[0].dimension};
    const std::array<int, 3> cellDims{cells[2].dimension, cells[1].dimension, cells[0].dimension};
    const std::vector<StatisticsField> fields = statisticsFields(f);
    std::vector<int> ids;
    for (const StatisticsField& field : fields) {
        int var = -1;
        nc.check(nc_def_var(nc.id(), field.name, NC_FLOAT, 3,
                            field.onCells ? cellDims.data() : pointDims.data(), &var),
                 std::string("define variable ") + field.name);
        nc.text(var, "long_name", field.longName);
        nc.text(var, "units", field.units);
        nc.text(var, "cell_methods", field.cellMethods);
        nc.floatAttribute(var, "_FillValue", std::numeric_limits<float>::quiet_NaN());
        nc.text(var, "grid_mapping", mapping);
        ids.push_back(var);
    }
    std::string title = "ensemble statistics of " + f.variable;
    if (!f.longName.empty() && f.longName != f.variable) title += " (" + f.longName + ")";
    title += " at isovalue " + numberText(f.isovalue) + (f.units.empty() ? "" : " " + f.units);
    if (!f.fixedDimensions.empty()) title += ", " + joined(f.fixedDimensions, ", ");
    nc.text(NC_GLOBAL, "Conventions", "CF-1.8");
    nc.text(NC_GLOBAL, "title", title);
    nc.text(NC_GLOBAL, "source", joined(f.sources, ", "));
    nc.text(NC_GLOBAL, "history", f.history);
    nc.text(NC_GLOBAL, "variable", f.variable);
    nc.floatAttribute(NC_GLOBAL, "isovalue", f.isovalue);  // the float the statistics used
    nc.text(NC_GLOBAL, "members", joined(f.members, ", "));
    nc.check(nc_enddef(nc.id()), "finish the header");

    for (int a = 0; a < 3; ++a) {
        const Axis& axis = grid.axis(a);
        const auto ai = static_cast<std::size_t>(a);
        nc.check(nc_put_var_double(nc.id(), points[ai].variable, axis.values.data()),
                 "write coordinate " + axis.name);
        const std::vector<double> centres = cellCentres(axis);
        nc.check(nc_put_var_double(nc.id(), cells[ai].variable, centres.data()),
                 "write coordinate " + cellDimensionName(axis));
    }
    for (std::size_t v = 0; v < fields.size(); ++v) {
        nc.check(nc_put_var_float(nc.id(), ids[v], fields[v].values.data()),
                 std::string("write variable ") + fields[v].name);
    }
}

}  // namespace

std::vector<StatisticsField> statisticsFields(const StatisticsFile& f) {
    const std::string of = " of " + f.variable;
    const std::string over = (f.memberAxis.empty() ? "realization" : f.memberAxis) + ": ";
    const std::string value = numberText(f.isovalue) + (f.units.empty() ? "" : " " + f.units);
    return {
        {"mean", f.mean, f.units, "ensemble mean" + of, over + "mean"},
        {"stddev", f.stddev, f.units, "ensemble standard deviation" + of + " (sample, n - 1)",
         over + "standard_deviation"},
        {"min", f.minimum, f.units, "ensemble minimum" + of, over + "minimum"},
        {"max", f.maximum, f.units, "ensemble maximum" + of, over + "maximum"},
        {"range", f.range, f.units, "ensemble range" + of + " (max - min)", over + "range"},
        {"exceedance_probability", f.exceedance, "1",
         "probability that " + f.variable + " exceeds " + value, ""},
        {"member_count", f.count, "1", "number of members with a finite value" + of, ""},
        {"level_crossing_probability", f.levelCrossing, "1",
         "probability that the " + f.variable + " = " + value + " isosurface crosses the cell", "",
         true},
    };
}

std::string cellDimensionName(const Axis& axis) { return axis.name + "_cell"; }

std::vector<double> cellCentres(const Axis& axis) {
    std::vector<double> centres;
    for (std::size_t i = 0; i + 1 < axis.size(); ++i) {
        centres.push_back(0.5 * (axis.values[i] + axis.values[i + 1]));
    }
    return centres;
}

void writeStatisticsNetcdf(const StatisticsFile& file, const std::string& path) {
    const Grid& grid = file.grid;
    if (grid.pointCount() == 0) {
        throw Error(ErrorKind::InvalidArgument, "cannot write '" + path + "': the grid is empty");
    }
    const std::size_t cells = (grid.nx() - 1) * (grid.ny() - 1) * (grid.nz() - 1);
    for (const StatisticsField& field : statisticsFields(file)) {
        const std::size_t expected = field.onCells ? cells : grid.pointCount();
        if (field.values.size() != expected) {
            throw Error(ErrorKind::InvalidArgument,
                        "cannot write '" + path + "': field " + field.name + " has " +
                            std::to_string(field.values.size()) + " values, the " +
                            (field.onCells ? "cell grid " : "grid ") + std::to_string(expected));
        }
    }
    writeCfFile(path, [&](const NetcdfOutput& nc) { writeFile(file, nc); });
}

}  // namespace ensil::data

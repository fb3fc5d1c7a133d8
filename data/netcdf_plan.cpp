#include "data/netcdf_plan.h"

#include <netcdf.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "data/cf_conventions.h"
#include "data/error.h"
#include "data/reader_support.h"
#include "data/variable_choice.h"
#include "data/wrf_conventions.h"

namespace ensil::data {
namespace {

struct Analysis {
    std::optional<NcComponent> component;
    int memberDim = -1;
    std::string memberReason;
    std::string whyNot;
};

bool isCoordinateVariable(const NetcdfFile& file, const NcVariable& var) {
    return var.dimIds.size() == 1 && file.dimension(var.dimIds[0]).name == var.name;
}

Analysis analyze(const NetcdfFile& file, const NcVariable& var, const std::string& memberDim) {
    Analysis a;
    const std::string dims = describeDimensions(file, var);
    if (var.type == NC_CHAR || var.type == NC_STRING) {
        a.whyNot = "holds text, not numbers";
        return a;
    }
    if (!memberDim.empty()) {
        const NcDimension* d = file.findDimension(memberDim);
        if (d == nullptr ||
            std::find(var.dimIds.begin(), var.dimIds.end(), d->id) == var.dimIds.end()) {
            a.whyNot = "has dimensions " + dims + ", none of them named '" + memberDim + "'";
            return a;
        }
        a.memberDim = d->id;
        a.memberReason = "chosen by the user";
    } else {
        const MemberDimensionGuess guess = findMemberDimension(file, var);
        if (guess.dimension != nullptr) {
            a.memberDim = guess.dimension->id;
            a.memberReason = guess.reason;
        }
    }
    NcComponent c;
    c.variable = &var;
    for (int id : var.dimIds) {
        if (id == a.memberDim) continue;
        const AxisRole role = classifyDimension(file, file.dimension(id));
        const int slot = role == AxisRole::X   ? 0
                         : role == AxisRole::Y ? 1
                         : role == AxisRole::Z ? 2
                                               : -1;
        if (slot >= 0 && c.spatialDims[static_cast<std::size_t>(slot)] < 0) {
            c.spatialDims[static_cast<std::size_t>(slot)] = id;
            c.sizes[static_cast<std::size_t>(slot)] = file.dimension(id).size;
        }
    }
    static constexpr std::array<const char*, 3> kAxisWords{"x (longitude)", "y (latitude)",
                                                           "vertical (level)"};
    std::vector<std::string> missing;
    for (std::size_t s = 0; s < 3; ++s) {
        if (c.spatialDims[s] < 0) missing.emplace_back(kAxisWords[s]);
    }
    if (!missing.empty()) {
        std::string list;
        for (std::size_t i = 0; i < missing.size(); ++i) list += (i ? " and " : "") + missing[i];
        a.whyNot = "has dimensions " + dims + ": it needs three spatial dimensions, but has no " +
                   list + " dimension";
        return a;
    }
    for (std::size_t s = 0; s < 3; ++s) {
        if (c.sizes[s] < 2) {
            a.whyNot = "has only one value along '" + file.dimension(c.spatialDims[s]).name +
                       "': isosurfaces need at least two points along every axis";
            return a;
        }
    }
    a.component = c;
    return a;
}

// u and v for the derived wind speed, by standard_name first, then by common names.
std::optional<std::pair<const NcVariable*, const NcVariable*>> windComponents(
    const NetcdfFile& file) {
    const NcVariable* u = nullptr;
    const NcVariable* v = nullptr;
    for (const NcVariable& var : file.variables()) {
        const std::string sn = file.text(var.id, "standard_name");
        if (sn == "eastward_wind" && u == nullptr) u = &var;
        if (sn == "northward_wind" && v == nullptr) v = &var;
    }
    // Grid-relative components (x_wind, y_wind: the Met Office's, on rotated or projected grids)
    // give the same speed: a rotation keeps a vector's length.
    for (const NcVariable& var : file.variables()) {
        const std::string sn = file.text(var.id, "standard_name");
        if ((sn == "x_wind" || sn == "grid_eastward_wind") && u == nullptr) u = &var;
        if ((sn == "y_wind" || sn == "grid_northward_wind") && v == nullptr) v = &var;
    }
    static constexpr std::array<std::pair<const char*, const char*>, 5> kNames{
        {{"u", "v"}, {"U", "V"}, {"ua", "va"}, {"uwnd", "vwnd"}, {"x_wind", "y_wind"}}};
    for (const auto& [un, vn] : kNames) {
        if (u != nullptr && v != nullptr) break;
        if (file.findVariable(un) != nullptr && file.findVariable(vn) != nullptr) {
            u = file.findVariable(un);
            v = file.findVariable(vn);
        }
    }
    if (u == nullptr || v == nullptr) return std::nullopt;
    return std::make_pair(u, v);
}

Axis makeAxis(const NetcdfFile& file, const NcDimension& dim, std::size_t size, int slot) {
    Axis axis;
    axis.name = dim.name;
    const NcVariable* coord = file.coordinateVariable(dim);
    if (coord != nullptr && dim.size == size) {
        axis.values = file.readDoubles(*coord);
        axis.units = file.text(coord->id, "units");
        axis.standardName = file.text(coord->id, "standard_name");
        // CF: pressure coordinates point down even without a `positive` attribute.
        axis.positiveUp = file.text(coord->id, "positive") != "down" && !isPressureUnit(axis.units);
    } else {
        axis.values.resize(size);
        for (std::size_t i = 0; i < size; ++i) axis.values[i] = static_cast<double>(i);
    }
    // Model levels are bare indices; a 1D length variable over the same dimension (e.g.
    // level_height) says where they are.
    if (slot == 2 && !isLengthUnit(axis.units) && axis.standardName != "air_pressure") {
        for (const NcVariable& var : file.variables()) {
            if (var.dimIds.size() == 1 && var.dimIds[0] == dim.id && &var != coord &&
                isLengthUnit(file.text(var.id, "units"))) {
                std::vector<double> heights = file.readDoubles(var);
                const bool increasing = std::adjacent_find(heights.begin(), heights.end(),
                                                           std::greater_equal<>()) == heights.end();
                if (increasing) {
                    axis.values = std::move(heights);
                    axis.units = file.text(var.id, "units");
                    axis.name = var.name;
                    axis.positiveUp = true;
                    break;
                }
            }
        }
    }
    return axis;
}

Grid makeGrid(const NetcdfFile& file, NcPlan& plan) {
    // The mass grid: along each axis the smallest size among the components (WRF's staggered
    // U and V have one more point along x or y), coordinates from a component that has it.
    std::array<Axis, 3> axes;
    std::array<int, 3> axisDims{};  // the dimension each axis was made from
    for (std::size_t s = 0; s < 3; ++s) {
        const NcComponent* best = &plan.components.front();
        for (const NcComponent& c : plan.components) {
            if (c.sizes[s] < best->sizes[s]) best = &c;
        }
        axisDims[s] = best->spatialDims[s];
        axes[s] = makeAxis(file, file.dimension(best->spatialDims[s]), best->sizes[s],
                           static_cast<int>(s));
    }
    // WRF output: x and y are bare indices along west_east and south_north; the global map
    // attributes say where they lie, unless the variable names a CF grid mapping.
    if (plan.gridMapping.empty()) {
        const auto isWrfIndexAxis = [&](std::size_t s) {
            const NcDimension& dim = file.dimension(plan.components.front().spatialDims[s]);
            return isWrfHorizontalDimension(dim.name) && file.coordinateVariable(dim) == nullptr;
        };
        if (isWrfIndexAxis(0) && isWrfIndexAxis(1)) {
            if (auto wrf = readWrfProjection(file)) {
                const auto staggered = [&](std::size_t s) {
                    return file.dimension(axisDims[s]).name.ends_with("_stag");
                };
                placeWrfGrid(file, *wrf, axes[0], staggered(0), axes[1], staggered(1));
                plan.gridMapping = wrf->mapping;
            }
        }
    }
    try {
        return Grid(std::move(axes[0]), std::move(axes[1]), std::move(axes[2]));
    } catch (const Error& e) {
        throw Error(ErrorKind::CorruptFile,
                    "'" + file.path() + "', variable '" + plan.name + "': " + e.what());
    }
}

std::string candidatesText(const std::vector<VariableInfo>& variables) {
    std::string usable, others;
    for (const VariableInfo& v : variables) {
        (v.usable ? usable : others) +=
            (v.usable ? (usable.empty() ? "" : ", ") : (others.empty() ? "" : ", ")) + v.name;
    }
    std::string text = usable.empty() ? "no variable has three spatial dimensions"
                                      : "variables usable as ensembles: " + usable;
    if (!others.empty()) text += "; others: " + others;
    return text;
}

// Dimensions of the plan's variable that are not spatial and hold more than one value.
std::vector<std::string> memberDimensionCandidates(const NetcdfFile& file, const NcPlan& plan) {
    std::vector<std::string> candidates;
    const auto& sd = plan.components.front().spatialDims;
    for (int id : plan.components.front().variable->dimIds) {
        if (file.dimension(id).size > 1 && std::find(sd.begin(), sd.end(), id) == sd.end()) {
            candidates.push_back(file.dimension(id).name);
        }
    }
    return candidates;
}

std::string suggestMemberDimension(const NetcdfFile& file, const NcPlan& plan) {
    std::string dims;
    for (int id : plan.components.front().variable->dimIds) {
        const NcDimension& d = file.dimension(id);
        dims += (dims.empty() ? "" : ", ") + d.name + " (" + std::to_string(d.size) + ")";
    }
    const auto candidates = memberDimensionCandidates(file, plan);
    const std::string suggestion = candidates.empty() ? "" : candidates.front();
    std::string text = "found no member dimension for '" + plan.name + "' in '" + file.path() +
                       "'; its dimensions are " + dims + ". ";
    if (!suggestion.empty()) {
        text += "If '" + suggestion + "' stands in for members, say so with --member-dim " +
                suggestion + "; ";
    } else {
        text += "Name the member dimension with --member-dim, ";
    }
    return text + "or open one file per member";
}

// WRF's T, the perturbation potential temperature (theta - 300 K), from which ensil derives the
// potential temperature itself; null for files that are not WRF's or hold theta already.
const NcVariable* wrfPerturbationTheta(const NetcdfFile& file) {
    const NcVariable* t = file.findVariable("T");
    if (t == nullptr || file.findVariable("theta") != nullptr ||
        file.findVariable("THETA") != nullptr) {
        return nullptr;
    }
    const std::string description = file.text(t->id, "description");
    const std::vector<std::string> global = file.attributeNames(NC_GLOBAL);
    const bool wrf = description.find("perturbation potential temperature") != std::string::npos ||
                     std::find(global.begin(), global.end(), "MAP_PROJ") != global.end();
    return wrf ? t : nullptr;
}

constexpr double kWrfThetaBase = 300.0;  // WRF's t0

}  // namespace

std::vector<VariableInfo> listVariables(const NetcdfFile& file, const std::string& memberDim) {
    std::vector<VariableInfo> list;
    for (const NcVariable& var : file.variables()) {
        if (isCoordinateVariable(file, var) || var.dimIds.size() < 2) continue;
        VariableInfo info;
        info.name = var.name;
        info.longName = file.text(var.id, "long_name");
        // WRF says what a field is in `description`.
        if (info.longName.empty()) info.longName = file.text(var.id, "description");
        info.standardName = file.text(var.id, "standard_name");
        info.units = file.text(var.id, "units");
        for (int id : var.dimIds) {
            info.dimensions.push_back(file.dimension(id).name);
            info.shape.push_back(file.dimension(id).size);
        }
        const Analysis a = analyze(file, var, memberDim);
        info.usable = a.component.has_value();
        if (a.component) info.levels = a.component->sizes[2];
        info.whyNotUsable = a.whyNot;
        list.push_back(std::move(info));
    }
    if (file.findVariable("wind_speed") == nullptr) {
        if (auto uv = windComponents(file)) {
            const Analysis au = analyze(file, *uv->first, memberDim);
            const Analysis av = analyze(file, *uv->second, memberDim);
            VariableInfo info;
            info.name = "wind_speed";
            info.longName = windSpeedLongName(uv->first->name, uv->second->name);
            info.standardName = "wind_speed";
            info.units = file.text(uv->first->id, "units");
            info.derived = true;
            for (int id : uv->first->dimIds) info.dimensions.push_back(file.dimension(id).name);
            info.usable = au.component && av.component;
            if (info.usable) info.levels = std::min(au.component->sizes[2], av.component->sizes[2]);
            info.whyNotUsable = !au.component   ? uv->first->name + " " + au.whyNot
                                : !av.component ? uv->second->name + " " + av.whyNot
                                                : "";
            list.push_back(std::move(info));
        }
    }
    if (const NcVariable* t = wrfPerturbationTheta(file)) {
        const Analysis a = analyze(file, *t, memberDim);
        VariableInfo info;
        info.name = "theta";
        info.longName = "potential temperature, WRF's T + 300 K, derived by ensil";
        info.standardName = "air_potential_temperature";
        info.units = "K";
        info.derived = true;
        for (int id : t->dimIds) info.dimensions.push_back(file.dimension(id).name);
        info.usable = a.component.has_value();
        if (a.component) info.levels = a.component->sizes[2];
        info.whyNotUsable = a.component ? "" : "T " + a.whyNot;
        list.push_back(std::move(info));
    }
    return list;
}

NcPlan planVariable(const NetcdfFile& file, const DataSelection& selection, bool requireMemberDim) {
    const std::vector<VariableInfo> variables = listVariables(file, selection.memberDimension);
    // Named, that variable; else the one a meteorologist would look at first
    // (data/variable_choice.h).
    const VariableInfo* chosen = nullptr;
    if (selection.variable.empty()) {
        if (const auto index = chooseVariable(variables)) chosen = &variables[*index];
    }
    for (const VariableInfo& v : variables) {
        if (!selection.variable.empty() && v.name == selection.variable) {
            chosen = &v;
            break;
        }
    }
    if (chosen == nullptr && !selection.variable.empty()) {
        std::vector<std::string> usable;
        for (const VariableInfo& v : variables) {
            if (v.usable) usable.push_back(v.name);
        }
        throw Error(ErrorKind::VariableNotFound,
                    "'" + file.path() + "' has no variable '" + selection.variable + "'; " +
                        candidatesText(variables),
                    usable);
    }
    if (chosen == nullptr || !chosen->usable) {
        std::string reasons;
        for (const VariableInfo& v : variables) {
            if (!v.usable && (chosen == nullptr || &v == chosen)) {
                reasons += (reasons.empty() ? "" : "; ") + v.name + " " + v.whyNotUsable;
            }
        }
        throw Error(ErrorKind::NotThreeDimensional,
                    "cannot make isosurfaces from '" + file.path() + "': " +
                        (reasons.empty() ? "it holds no variable with dimensions" : reasons) +
                        ". ensil needs a variable over x, y and a vertical level");
    }
    NcPlan plan;
    plan.name = chosen->name;
    plan.longName = chosen->longName;
    plan.units = chosen->units;
    plan.derived = chosen->derived;
    plan.timeIndex = selection.timeIndex;
    std::vector<const NcVariable*> parts;
    if (chosen->derived && chosen->name == "theta") {
        parts = {wrfPerturbationTheta(file)};
        plan.offset = kWrfThetaBase;
    } else if (chosen->derived) {
        const auto uv = windComponents(file);
        parts = {uv->first, uv->second};
    } else {
        parts = {file.findVariable(chosen->name)};
    }
    for (const NcVariable* part : parts) {
        const Analysis a = analyze(file, *part, selection.memberDimension);
        plan.components.push_back(*a.component);
        if (plan.components.size() == 1) {
            plan.memberDim = a.memberDim;
            plan.memberReason = a.memberReason;
        } else if (a.memberDim != plan.memberDim) {
            throw Error(ErrorKind::GridMismatch, "'" + file.path() + "': " + parts[0]->name +
                                                     " and " + part->name +
                                                     " have different member dimensions");
        }
    }
    // A netCDF-4 variable may declare any size and never be written (a template, an aborted
    // run): every value would be the fill value, and reading them all took minutes and more
    // memory than the machine has. Told from the file's own metadata, before anything is read.
    for (const NcVariable* part : parts) {
        if (const auto stored = file.storedBytes(*part); stored && *stored == 0) {
            std::size_t values = 1;
            for (const int d : part->dimIds) values *= file.dimension(d).size;
            std::size_t valueBytes = 0;
            nc_inq_type(file.id(), part->type, nullptr, &valueBytes);
            throw Error(
                ErrorKind::AllValuesMissing,
                "'" + file.path() + "', variable '" + part->name + "' " +
                    describeDimensions(file, *part) + " holds no values: its " +
                    sizeText(static_cast<double>(values) * static_cast<double>(valueBytes)) +
                    " are declared, but none was ever written to the file (each would "
                    "read as the fill value)");
        }
    }
    for (std::size_t s = 0; s < 3; ++s) {
        const std::size_t a = plan.components.front().sizes[s];
        const std::size_t b = plan.components.back().sizes[s];
        if (std::max(a, b) - std::min(a, b) > 1) {
            throw Error(ErrorKind::GridMismatch, "'" + file.path() + "': " + parts.front()->name +
                                                     " and " + parts.back()->name +
                                                     " lie on different grids");
        }
    }
    for (int id : plan.components.front().variable->dimIds) {
        const auto& sd = plan.components.front().spatialDims;
        if (id == plan.memberDim || std::find(sd.begin(), sd.end(), id) != sd.end()) continue;
        const NcDimension& d = file.dimension(id);
        if (selection.timeIndex >= d.size) {
            throw Error(ErrorKind::InvalidArgument,
                        "--time-index " + std::to_string(selection.timeIndex) +
                            " is past the end of dimension '" + d.name + "' in '" + file.path() +
                            "' (" + std::to_string(d.size) + " values: 0 to " +
                            std::to_string(d.size - 1) + ")");
        }
    }
    if (requireMemberDim && plan.memberDim < 0) {
        throw Error(ErrorKind::MemberDimensionNotFound, suggestMemberDimension(file, plan),
                    memberDimensionCandidates(file, plan));
    }
    plan.gridMapping = readGridMapping(file, *plan.components.front().variable);
    plan.grid = makeGrid(file, plan);
    return plan;
}

std::vector<std::string> describeFixedDimensions(const NetcdfFile& file, const NcPlan& plan) {
    std::vector<std::string> lines;
    const auto& sd = plan.components.front().spatialDims;
    for (int id : plan.components.front().variable->dimIds) {
        if (id == plan.memberDim || std::find(sd.begin(), sd.end(), id) != sd.end()) continue;
        const NcDimension& d = file.dimension(id);
        std::string line =
            d.name + " = " + std::to_string(plan.timeIndex) + " of " + std::to_string(d.size);
        if (const NcVariable* coord = file.coordinateVariable(d)) {
            const double value = file.readDoubles(*coord).at(plan.timeIndex);
            const auto date = formatCfTime(value, file.text(coord->id, "units"),
                                           file.text(coord->id, "calendar"));
            std::ostringstream number;
            number << value;
            line += " (" + date.value_or(number.str()) + ")";
        }
        lines.push_back(line);
    }
    return lines;
}

TimeSteps describeTimeSteps(const NetcdfFile& file, const NcPlan& plan) {
    TimeSteps steps;
    const auto& sd = plan.components.front().spatialDims;
    const NcDimension* first = nullptr;
    std::size_t count = 0;
    for (int id : plan.components.front().variable->dimIds) {
        if (id == plan.memberDim || std::find(sd.begin(), sd.end(), id) != sd.end()) continue;
        const NcDimension& d = file.dimension(id);
        count = first == nullptr ? d.size : std::min(count, d.size);
        if (first == nullptr) first = &d;
    }
    if (first == nullptr) return steps;
    steps.dimension = first->name;
    std::vector<double> values;
    std::string units, calendar;
    if (const NcVariable* coord = file.coordinateVariable(*first)) {
        if (coord->type != NC_CHAR && coord->type != NC_STRING) {
            values = file.readDoubles(*coord);
            units = file.text(coord->id, "units");
            calendar = file.text(coord->id, "calendar");
        }
    }
    const std::vector<std::string> wrfTimes =
        values.empty() ? wrfTimeLabels(file, *first) : std::vector<std::string>{};
    for (std::size_t i = 0; i < count; ++i) {
        std::optional<std::string> date;
        if (i < values.size()) date = formatCfTime(values[i], units, calendar);
        if (!date && i < wrfTimes.size() && !wrfTimes[i].empty()) date = wrfTimes[i];
        steps.labels.push_back(date.value_or(std::to_string(i)));
    }
    return steps;
}

std::vector<std::string> memberNames(const NetcdfFile& file, const NcPlan& plan) {
    if (plan.memberDim < 0) return {};
    const NcDimension& dim = file.dimension(plan.memberDim);
    std::vector<std::string> names(dim.size);
    const NcVariable* coord = file.coordinateVariable(dim);
    std::vector<double> values;
    std::string units, calendar;
    if (coord != nullptr && coord->type != NC_CHAR && coord->type != NC_STRING) {
        values = file.readDoubles(*coord);
        units = file.text(coord->id, "units");
        calendar = file.text(coord->id, "calendar");
    }
    // WRF names its times in Times(Time, DateStrLen), not in a coordinate.
    const std::vector<std::string> wrfTimes =
        values.empty() ? wrfTimeLabels(file, dim) : std::vector<std::string>{};
    for (std::size_t m = 0; m < dim.size; ++m) {
        if (m < wrfTimes.size() && !wrfTimes[m].empty()) {
            names[m] = wrfTimes[m];
            continue;
        }
        if (values.empty()) {
            // Without a coordinate the file names no member: the name is ensil's number, 1..N,
            // as the demo's, HDF5's and every output's (METHODS.md, numbers of members).
            names[m] = "member " + std::to_string(m + 1);
            continue;
        }
        if (auto date = formatCfTime(values[m], units, calendar)) {
            names[m] = *date;
            continue;
        }
        std::ostringstream text;
        text << (dim.name == "number" || dim.name == "realization" || dim.name.starts_with("ens")
                     ? "member "
                     : dim.name + " ")
             << values[m];
        names[m] = text.str();
    }
    return names;
}

}  // namespace ensil::data

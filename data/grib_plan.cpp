#include "data/grib_plan.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <tuple>

#include "data/error.h"
#include "data/reader_support.h"
#include "data/variable_choice.h"

namespace ensil::data {
namespace {

// The vertical axis a GRIB level type makes.
struct LevelKind {
    std::string family;  // messages of one variable and one family share an axis
    std::string axisName;
    std::string units;
    std::string standardName;
    bool positiveUp = true;
};

LevelKind levelKindOf(const std::string& typeOfLevel) {
    // hPa and Pa levels are one pressure axis: GRIB 2 writers code pressures below 1 hPa in Pa.
    if (typeOfLevel == "isobaricInhPa" || typeOfLevel == "isobaricInPa") {
        return {"isobaric", "plev", "Pa", "air_pressure", false};
    }
    // Model level numbers count down from the top of the atmosphere.
    if (typeOfLevel == "hybrid") return {"hybrid", "hybrid", "", "", false};
    if (typeOfLevel == "heightAboveGround") return {typeOfLevel, "height", "m", "height", true};
    if (typeOfLevel == "heightAboveSea") return {typeOfLevel, "altitude", "m", "altitude", true};
    if (typeOfLevel == "depthBelowSea") return {typeOfLevel, "depth", "m", "depth", false};
    if (typeOfLevel == "theta") {
        return {typeOfLevel, "theta", "K", "air_potential_temperature", true};
    }
    return {typeOfLevel, typeOfLevel.empty() ? "level" : typeOfLevel, "", "", true};
}

std::string levelText(const LevelKind& kind, double level) {
    std::ostringstream text;
    if (kind.family == "isobaric") {
        text << level / 100.0 << " hPa";
    } else {
        text << kind.axisName << " " << level << (kind.units.empty() ? "" : " " + kind.units);
    }
    return text.str();
}

std::string levelsText(const LevelKind& kind, const std::vector<double>& levels) {
    std::string text;
    for (double level : levels) text += (text.empty() ? "" : ", ") + levelText(kind, level);
    return text.empty() ? "none" : text;
}

struct Variable {
    std::string name;      // unique in the file
    std::string identity;  // shortName, or "param<paramId>" when ecCodes knows no short name
    std::string longName, units;
    LevelKind kind;
    std::vector<const GribMessage*> messages;
    std::vector<long> members, times;  // sorted, distinct
    std::vector<double> levels;        // increasing, distinct
    GribGrid grid;
    GribAxes axes;
    std::string whyNot;        // empty when usable
    bool gridRefused = false;  // whyNot is a grid ensil does not read (UnsupportedFormat)
    bool derived = false;
    std::array<std::size_t, 2> parts{};  // u and v for wind_speed, by index in the file's list
};

std::string identityOf(const GribMessage& m) {
    if (!m.shortName.empty() && m.shortName != "unknown") return m.shortName;
    return "param" + std::to_string(m.paramId);
}

template <typename T>
std::vector<T> distinctSorted(std::vector<T> values) {
    std::sort(values.begin(), values.end());
    values.erase(std::unique(values.begin(), values.end()), values.end());
    return values;
}

template <typename T>
std::vector<T> common(const std::vector<T>& a, const std::vector<T>& b) {
    std::vector<T> both;
    std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(both));
    return both;
}

std::string messageText(const GribMessage& m) {
    return "message " + std::to_string(m.number) +
           (m.field > 0 ? " (its field " + std::to_string(m.field + 1) + ")" : std::string()) +
           " at byte offset " + std::to_string(m.offset);
}

std::string gridText(const GribGrid& g) {
    return std::to_string(g.ni) + " x " + std::to_string(g.nj) + " " + g.type;
}

// Fills in what the messages of one variable say together, and whether it can be read.
void finish(Variable& v, const std::string& path) {
    std::vector<long> members, times;
    std::vector<double> levels;
    for (const GribMessage* m : v.messages) {
        members.push_back(m->member);
        times.push_back(m->validity);
        levels.push_back(m->level);
    }
    v.members = distinctSorted(members);
    v.times = distinctSorted(times);
    v.levels = distinctSorted(levels);
    const GribMessage& first = *v.messages.front();
    v.grid = first.grid;
    for (const GribMessage* m : v.messages) {
        if (!(m->grid == v.grid)) {
            v.whyNot = "lies on different grids: " + messageText(first) + " on " +
                       gridText(v.grid) + ", " + messageText(*m) + " on " + gridText(m->grid) +
                       " (scanning or corners differ when the sizes agree); an ensemble needs "
                       "one grid";
            return;
        }
    }
    if (const std::string advice = unsupportedGridAdvice(v.grid.type, path); !advice.empty()) {
        v.whyNot = advice;
        v.gridRefused = true;
        return;
    }
    for (const GribMessage* m : v.messages) {
        if (m->values != v.grid.pointCount()) {
            v.whyNot = "has " + std::to_string(m->values) + " values in " + messageText(*m) +
                       " where its " + gridText(v.grid) + " grid has " +
                       std::to_string(v.grid.pointCount()) + " points; the message is damaged";
            return;
        }
    }
    v.axes = gribAxes(v.grid);
    if (!v.axes.why.empty()) {
        v.whyNot = v.axes.why;
        return;
    }
    if (v.levels.size() < 2) {
        v.whyNot = "has one level only (" + (first.typeOfLevel.empty() ? "?" : first.typeOfLevel) +
                   ", " + levelsText(v.kind, v.levels) + "): isosurfaces need at least two levels";
    }
}

std::vector<Variable> groupVariables(const GribInventory& inventory, const std::string& path) {
    std::vector<Variable> variables;
    std::map<std::string, std::size_t> byKey;
    std::map<std::string, std::vector<std::string>> familiesOf;  // identity -> level families
    for (const GribMessage& m : inventory.messages) {
        const LevelKind kind = levelKindOf(m.typeOfLevel);
        const std::string identity = identityOf(m);
        const auto [at, added] = byKey.try_emplace(identity + '\n' + kind.family, variables.size());
        if (added) {
            Variable v;
            v.identity = v.name = identity;
            v.longName = m.name;
            v.units = m.units;
            v.kind = kind;
            variables.push_back(std::move(v));
            familiesOf[identity].push_back(kind.family);
        }
        variables[at->second].messages.push_back(&m);
    }
    for (Variable& v : variables) {
        // t on pressure levels and t on model levels are two variables: name both apart.
        if (familiesOf[v.identity].size() > 1) v.name = v.identity + "_" + v.kind.family;
        finish(v, path);
    }
    // wind_speed from u and v on one kind of level, where they share the most levels.
    const Variable* bestU = nullptr;
    const Variable* bestV = nullptr;
    for (const Variable& u : variables) {
        for (const Variable& v : variables) {
            if (u.identity != "u" || v.identity != "v" || u.kind.family != v.kind.family) continue;
            if (bestU == nullptr ||
                common(u.levels, v.levels).size() > common(bestU->levels, bestV->levels).size()) {
                bestU = &u;
                bestV = &v;
            }
        }
    }
    const bool taken = std::any_of(variables.begin(), variables.end(),
                                   [](const Variable& v) { return v.name == "wind_speed"; });
    if (bestU != nullptr && !taken) {
        Variable w;
        w.name = w.identity = "wind_speed";
        w.longName = windSpeedLongName(bestU->name, bestV->name);
        w.units = bestU->units;
        w.kind = bestU->kind;
        w.derived = true;
        w.parts = {static_cast<std::size_t>(bestU - variables.data()),
                   static_cast<std::size_t>(bestV - variables.data())};
        w.members = common(bestU->members, bestV->members);
        w.times = common(bestU->times, bestV->times);
        w.levels = common(bestU->levels, bestV->levels);
        w.grid = bestU->grid;
        w.axes = bestU->axes;
        for (const Variable* part : {bestU, bestV}) {
            if (w.whyNot.empty() && !part->whyNot.empty() && part->levels.size() >= 2) {
                w.whyNot = "needs " + part->name + ", which " + part->whyNot;
                w.gridRefused = part->gridRefused;
            }
        }
        if (w.whyNot.empty() && !(bestU->grid == bestV->grid)) {
            w.whyNot = "needs " + bestU->name + " and " + bestV->name + " on one grid, but " +
                       bestU->name + " lies on " + gridText(bestU->grid) + " and " + bestV->name +
                       " on " + gridText(bestV->grid);
        }
        if (w.whyNot.empty() && w.levels.size() < 2) {
            w.whyNot = "needs " + bestU->name + " and " + bestV->name +
                       " on at least two common levels, but " + bestU->name + " is on " +
                       levelsText(w.kind, bestU->levels) + " and " + bestV->name + " on " +
                       levelsText(w.kind, bestV->levels);
        }
        variables.push_back(std::move(w));
    }
    return variables;
}

VariableInfo infoOf(const Variable& v) {
    VariableInfo info;
    info.name = v.name;
    info.longName = v.longName;
    info.units = v.units;
    info.dimensions = {"number", "time", v.kind.axisName, "lat", "lon"};
    info.shape = {v.members.size(), v.times.size(), v.levels.size(),
                  static_cast<std::size_t>(std::max(0L, v.grid.nj)),
                  static_cast<std::size_t>(std::max(0L, v.grid.ni))};
    info.usable = v.whyNot.empty();
    info.levels = info.usable ? v.levels.size() : 0;
    info.derived = v.derived;
    info.whyNotUsable = v.whyNot;
    return info;
}

std::string candidatesText(const std::vector<Variable>& variables) {
    std::vector<std::string> usable, others;
    for (const Variable& v : variables) (v.whyNot.empty() ? usable : others).push_back(v.name);
    std::string text = usable.empty() ? "no variable has two or more levels on a regular grid"
                                      : "variables usable as ensembles: " + quotedList(usable);
    if (!others.empty()) text += "; others: " + quotedList(others);
    return text;
}

using FieldKey = std::tuple<long, long, double>;  // member, validity, level

// Each component's messages by member, time and level. Two messages for one field are
// refused: which one is meant cannot be guessed (two forecasts valid at one time, say).
std::map<FieldKey, const GribMessage*> fieldsOf(const Variable& v, const std::string& path) {
    std::map<FieldKey, const GribMessage*> fields;
    for (const GribMessage* m : v.messages) {
        const auto [at, added] = fields.try_emplace(FieldKey{m->member, m->validity, m->level}, m);
        if (!added) {
            throw Error(
                ErrorKind::CorruptFile,
                "'" + path + "': " + messageText(*at->second) + " and " + messageText(*m) +
                    " both hold '" + v.name + "' for member " + std::to_string(m->member) + " at " +
                    levelText(v.kind, m->level) + ", valid at " + validityText(m->validity) +
                    " (two forecasts valid at one time, or a copy); keep one with grib_copy, "
                    "e.g. 'grib_copy -w step=0 " +
                    path + " one.grib'");
        }
    }
    return fields;
}

}  // namespace

std::vector<VariableInfo> listGribVariables(const GribInventory& inventory,
                                            const std::string& path) {
    std::vector<VariableInfo> list;
    for (const Variable& v : groupVariables(inventory, path)) list.push_back(infoOf(v));
    return list;
}

GribPlan planGribVariable(const GribInventory& inventory, const std::string& path,
                          const DataSelection& selection) {
    const std::vector<Variable> variables = groupVariables(inventory, path);
    // Named, that variable; else the one a meteorologist would look at first, as the NetCDF
    // reader chooses (data/variable_choice.h).
    const Variable* chosen = nullptr;
    if (selection.variable.empty()) {
        std::vector<VariableInfo> infos;
        for (const Variable& v : variables) infos.push_back(infoOf(v));
        if (const auto index = chooseVariable(infos)) chosen = &variables[*index];
    }
    for (const Variable& v : variables) {
        if (!selection.variable.empty() && v.name == selection.variable) chosen = &v;
    }
    if (chosen == nullptr && !selection.variable.empty()) {
        std::vector<std::string> usable;
        for (const Variable& v : variables) {
            if (v.whyNot.empty()) usable.push_back(v.name);
        }
        throw Error(ErrorKind::VariableNotFound,
                    "'" + path + "' has no variable '" + selection.variable + "'; " +
                        candidatesText(variables),
                    usable);
    }
    if (chosen == nullptr || !chosen->whyNot.empty()) {
        std::string reasons;
        bool gridRefused = false;
        for (const Variable& v : variables) {
            if (chosen == nullptr || &v == chosen) {
                reasons += (reasons.empty() ? "'" : "; '") + v.name + "' " + v.whyNot;
                gridRefused = gridRefused || v.gridRefused;
            }
        }
        throw Error(gridRefused ? ErrorKind::UnsupportedFormat : ErrorKind::NotThreeDimensional,
                    "cannot make isosurfaces from '" + path + "': " + reasons);
    }
    const Variable& v = *chosen;
    GribPlan plan;
    plan.name = v.name;
    plan.longName = v.longName;
    plan.units = v.units;
    plan.derived = v.derived;

    const std::string& dim = selection.memberDimension;
    // cfgrib (xarray's GRIB engine) names the forecast's lead time `step` and the time it is
    // valid at `valid_time`: ensil's time axis is the validity time (reference plus step), and
    // a file it reads has one field per validity, so both name that axis.
    const bool cfgribTime = dim == "step" || dim == "valid_time";
    if (!dim.empty() && dim != "number" && dim != "time" && !cfgribTime) {
        throw Error(ErrorKind::MemberDimensionNotFound,
                    "'" + path +
                        "' is a GRIB file, whose members come from the key 'number' "
                        "(the perturbation number); --member-dim " +
                        dim + " names no dimension of it. Name 'number', or 'time' (cfgrib's " +
                        "'step' or 'valid_time') to make its " + std::to_string(v.times.size()) +
                        " times the members",
                    {"number", "time"});
    }
    const bool byTime = dim == "time" || cfgribTime;
    plan.memberDimension = byTime ? "time" : "number";
    plan.memberReason = cfgribTime ? "chosen by the user as cfgrib's '" + dim +
                                         "': the times the fields are valid at"
                        : byTime ? "chosen by the user"
                                 : "GRIB key 'number', the perturbation number; 0 is the "
                                   "control forecast";
    const std::vector<long>& memberValues = byTime ? v.times : v.members;
    const std::vector<long>& fixedValues = byTime ? v.members : v.times;
    const std::string fixedName = byTime ? "number" : "time";
    if (selection.timeIndex >= fixedValues.size()) {
        throw Error(ErrorKind::InvalidArgument,
                    "--time-index " + std::to_string(selection.timeIndex) +
                        " is past the end of dimension '" + fixedName + "' in '" + path + "' (" +
                        std::to_string(fixedValues.size()) + " values: 0 to " +
                        std::to_string(fixedValues.size() - 1) + ")");
    }
    const long fixed = fixedValues[selection.timeIndex];
    plan.fixedDimensions.push_back(
        fixedName + " = " + std::to_string(selection.timeIndex) + " of " +
        std::to_string(fixedValues.size()) + " (" +
        (byTime ? "member " + std::to_string(fixed) : validityText(fixed)) + ")");
    plan.timeSteps.dimension = fixedName;
    for (std::size_t i = 0; i < fixedValues.size(); ++i) {
        plan.timeSteps.labels.push_back(byTime ? std::to_string(i) : validityText(fixedValues[i]));
    }
    plan.oneMember = memberValues.size() == 1;
    for (long m : memberValues) {
        plan.memberNames.push_back(byTime ? validityText(m) : "member " + std::to_string(m));
    }

    // Every member at every level, at the chosen time, from each component.
    std::vector<std::map<FieldKey, const GribMessage*>> components;
    if (v.derived) {
        for (std::size_t part : v.parts) components.push_back(fieldsOf(variables[part], path));
    } else {
        components.push_back(fieldsOf(v, path));
    }
    std::vector<std::string> missing;
    std::size_t wanted = 0;
    for (long m : memberValues) {
        auto& levels = plan.fields.emplace_back();
        for (double level : v.levels) {
            auto& field = levels.emplace_back();
            for (std::size_t c = 0; c < components.size(); ++c) {
                ++wanted;
                const long member = byTime ? fixed : m, time = byTime ? m : fixed;
                const auto at = components[c].find(FieldKey{member, time, level});
                if (at != components[c].end()) {
                    field[c] = at->second;
                } else {
                    missing.push_back(
                        (v.derived ? variables[v.parts[c]].name + " of member " : "member ") +
                        std::to_string(member) + " at " + levelText(v.kind, level) + ", valid at " +
                        validityText(time));
                }
            }
        }
    }
    if (!missing.empty()) {
        std::string text = "'" + path + "' has no message for " + missing.front();
        if (missing.size() > 1) {
            text += " (" + std::to_string(missing.size()) + " of the " + std::to_string(wanted) +
                    " fields of '" + v.name + "' are missing)";
        }
        text += ": an ensemble needs every member at every level";
        if (!inventory.warnings.empty()) {
            text +=
                ". The file is damaged; the messages ensil could not read may have held "
                "them: " +
                inventory.warnings.front();
        } else {
            text +=
                ". Choose another time (--time-index), or a variable whose fields are all "
                "there";
        }
        throw Error(ErrorKind::CorruptFile, text);
    }
    Axis z;
    z.name = v.kind.axisName;
    z.units = v.kind.units;
    z.standardName = v.kind.standardName;
    z.positiveUp = v.kind.positiveUp;
    z.values = v.levels;
    plan.grid = Grid(v.axes.x, v.axes.y, std::move(z));
    return plan;
}

}  // namespace ensil::data

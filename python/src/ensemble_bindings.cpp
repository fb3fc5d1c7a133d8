// ensil.open, ensil.from_numpy, ensil.demo and the Ensemble type.
#include <QJsonDocument>
#include <cmath>
#include <cstring>

#include "data/cf_conventions.h"
#include "data/error.h"
#include "data/grid_mapping.h"
#include "data/level_range.h"
#include "engine/ensemble_info.h"
#include "engine/session_renderer.h"
#include "python/src/bindings.h"
#include "python/src/errors.h"
#include "python/src/interruptible.h"
#include "python/src/numpy_arrays.h"
#include "python/src/py_ensemble.h"

namespace py = pybind11;

namespace ensil::python {

std::string PyEnsemble::sourceKey() const {
    if (selection) return data::sourceIdentity(*selection);
    if (demo) return engine::demoSourceKey(*demo);
    return {};
}

namespace {

std::string memberName(const data::Ensemble& e, std::size_t m) {
    const std::string& name = e.members[m].name;
    return name.empty() ? "member " + std::to_string(m + 1) : name;
}

// What info() says of an ensemble no reader described (an array, the demo).
data::EnsembleDescription describeLoaded(const data::Ensemble& e, const std::string& format,
                                         const std::string& memberReason) {
    data::EnsembleDescription d;
    d.format = format;
    d.variable = e.variable;
    d.longName = e.longName;
    d.units = e.units;
    d.memberDimension = e.memberDimension;
    d.memberDimensionReason = memberReason;
    d.members = e.memberCount();
    for (std::size_t m = 0; m < e.memberCount(); ++m) d.memberNames.push_back(memberName(e, m));
    d.fixedDimensions = e.fixedDimensions;
    d.timeSteps = e.timeSteps;
    d.grid = e.grid;
    d.gridMapping = e.gridMapping;
    data::VariableInfo v;
    v.name = e.variable;
    v.longName = e.longName;
    v.units = e.units;
    v.dimensions = {e.memberDimension, e.grid.z().name, e.grid.y().name, e.grid.x().name};
    v.shape = {e.memberCount(), e.grid.nz(), e.grid.ny(), e.grid.nx()};
    v.usable = true;
    v.levels = e.grid.nz();
    d.variables.push_back(v);
    return d;
}

void warnAboutValues(const data::Ensemble& e) {
    // What the reader read around (a damaged GRIB message skipped, by its byte offset).
    for (const std::string& w : e.warnings) warn(w);
    if (const auto note = data::infiniteValuesWarning(e)) warn(*note);
    for (const std::size_t m : data::membersWithoutData(e)) {
        warn("'" + memberName(e, m) + "' of '" + e.variable +
             "' has no valid value (every value is missing)");
    }
}

PyEnsemble openFiles(const std::vector<std::string>& paths, const std::string& variable,
                     const std::string& memberDim, long long timeIndex, const std::string& levels,
                     const py::object& bbox, const py::object& progress) {
    if (paths.empty()) throw ArgumentError("name at least one file, e.g. ensil.open('data.nc')");
    if (timeIndex < 0) {
        throw ArgumentError("time_index must be a whole number from 0, not '" +
                            std::to_string(timeIndex) + "'");
    }
    PyEnsemble result;
    result.selection =
        data::DataSelection{paths, variable, memberDim, static_cast<std::size_t>(timeIndex)};
    result.selection->levels = levelsArgument(levels);
    result.selection->region = bboxArgument(bbox);
    data::EnsembleDescription description;
    data::Ensemble ensemble;
    runInterruptible(
        [&](const std::stop_token& stop, const data::Progress& report) {
            ensemble = data::openEnsemble(*result.selection, stop, report, &description);
        },
        progress);
    result.description = std::move(description);
    result.data = std::make_shared<const data::Ensemble>(std::move(ensemble));
    warnAboutValues(*result.data);
    return result;
}

data::Axis axisFrom(const py::tuple& given) {
    data::Axis axis;
    axis.name = given[0].cast<std::string>();
    const auto values =
        given[1].cast<py::array_t<double, py::array::c_style | py::array::forcecast>>();
    if (values.ndim() != 1) {
        throw ArgumentError("the coordinates of axis '" + axis.name + "' must be 1-D");
    }
    axis.values.assign(values.data(), values.data() + values.size());
    axis.units = given[2].cast<std::string>();
    axis.positiveUp = !data::isPressureUnit(axis.units);
    return axis;
}

// A CF grid mapping given as its variable's attributes ({"grid_mapping_name": ..., numbers or
// lists of numbers}), as the NetCDF reader takes it from a file: other attributes (text such as
// crs_wkt) are left out, as the reader leaves them. An empty dict: none.
data::GridMapping gridMappingFrom(const py::dict& attributes) {
    data::GridMapping mapping;
    if (attributes.empty()) return mapping;
    if (!attributes.contains("grid_mapping_name")) {
        throw ArgumentError("grid_mapping must name its grid_mapping_name, as CF's attributes do");
    }
    mapping.name = py::str(attributes["grid_mapping_name"]);
    for (const auto& [key, value] : attributes) {
        const std::string name = py::str(key);
        if (name == "grid_mapping_name" || py::isinstance<py::str>(value)) continue;
        std::vector<double> numbers;
        try {
            if (py::isinstance<py::iterable>(value)) {
                for (const py::handle item : value) numbers.push_back(item.cast<double>());
            } else {
                numbers.push_back(value.cast<double>());
            }
        } catch (const py::cast_error&) {
            continue;  // neither a number nor numbers: not a projection parameter
        }
        if (!numbers.empty()) mapping.parameters.emplace_back(name, std::move(numbers));
    }
    return mapping;
}

PyEnsemble fromArray(const py::array_t<float, py::array::c_style | py::array::forcecast>& values,
                     const std::vector<py::tuple>& axes, const std::string& variable,
                     const std::string& units, const std::vector<std::string>& names,
                     const std::string& memberDim, const py::dict& gridMapping) {
    if (values.ndim() != 4) {
        throw ArgumentError("values must be 4-D, (member, z, y, x); these have " +
                            std::to_string(values.ndim()) + " dimensions");
    }
    if (axes.size() != 3) {
        throw ArgumentError("give three axes, (z, y, x), not " + std::to_string(axes.size()));
    }
    data::Ensemble e;
    data::Axis z = axisFrom(axes[0]), y = axisFrom(axes[1]), x = axisFrom(axes[2]);
    const std::array<const data::Axis*, 3> zyx{&z, &y, &x};
    for (int a = 0; a < 3; ++a) {
        if (static_cast<py::ssize_t>(zyx[a]->size()) != values.shape(a + 1)) {
            throw ArgumentError("axis '" + zyx[a]->name + "' has " +
                                std::to_string(zyx[a]->size()) + " coordinates but the values " +
                                std::to_string(values.shape(a + 1)) + " points along it");
        }
    }
    e.grid = data::Grid(std::move(x), std::move(y), std::move(z));  // checks monotonic axes
    const auto members = static_cast<std::size_t>(values.shape(0));
    if (members == 0) throw ArgumentError("values hold no member");
    if (!names.empty() && names.size() != members) {
        throw ArgumentError("names has " + std::to_string(names.size()) + " entries for " +
                            std::to_string(members) + " members");
    }
    e.variable = variable;
    e.units = units;
    e.memberDimension = memberDim;
    e.source = "NumPy array";
    e.gridMapping = gridMappingFrom(gridMapping);
    const std::size_t points = e.grid.pointCount();
    const float* source = values.data();
    {
        const py::gil_scoped_release released;  // copying gigabytes takes a while
        e.members.resize(members);
        for (std::size_t m = 0; m < members; ++m) {
            e.members[m].name = names.empty() ? "member " + std::to_string(m + 1) : names[m];
            data::FieldValues& v = e.members[m].values;
            v.resize(points);
            std::memcpy(v.data(), source + m * points, points * sizeof(float));
            // As the readers do: infinities are missing values, counted so they can be said.
            for (float& f : v) {
                if (std::isinf(f)) {
                    f = std::nanf("");
                    ++e.infiniteValues;
                }
            }
        }
    }
    PyEnsemble result;
    result.data = std::make_shared<const data::Ensemble>(std::move(e));
    result.description = describeLoaded(*result.data, "NumPy array", "the array's first axis");
    warnAboutValues(*result.data);
    return result;
}

PyEnsemble demoEnsemble(std::size_t members, std::uint64_t seed, const py::object& progress) {
    if (members < 1 || members > 1000) {
        throw ArgumentError("members must be a whole number from 1 to 1000, not " +
                            std::to_string(members));
    }
    PyEnsemble result;
    result.demo = data::DemoEnsembleParams{};
    result.demo->members = members;
    result.demo->seed = seed;
    data::Ensemble e;
    runInterruptible(
        [&](const std::stop_token& stop, const data::Progress& report) {
            e = data::makeDemoEnsemble(*result.demo, stop, report).ensemble;
        },
        progress);
    result.data = std::make_shared<const data::Ensemble>(std::move(e));
    result.description = describeLoaded(*result.data, "demo", "generated");
    return result;
}

// (member, z, y, x) over the members' blocks: a view when they lie at one stride from each
// other, as blocks allocated one after another usually do; otherwise a read-only copy.
py::array valuesOf(const py::object& self) {
    const data::Ensemble& e = *self.cast<const PyEnsemble&>().data;
    const auto f = static_cast<py::ssize_t>(sizeof(float));
    const auto nx = static_cast<py::ssize_t>(e.grid.nx()),
               ny = static_cast<py::ssize_t>(e.grid.ny()),
               nz = static_cast<py::ssize_t>(e.grid.nz());
    const std::vector<py::ssize_t> shape{static_cast<py::ssize_t>(e.memberCount()), nz, ny, nx};
    const float* first = e.members.front().values.data();
    py::ssize_t stride = nx * ny * nz * f;
    bool even = true;
    if (e.memberCount() > 1) {
        stride = reinterpret_cast<const char*>(e.members[1].values.data()) -
                 reinterpret_cast<const char*>(first);
        for (std::size_t m = 2; m < e.memberCount() && even; ++m) {
            even = reinterpret_cast<const char*>(e.members[m].values.data()) -
                       reinterpret_cast<const char*>(first) ==
                   static_cast<py::ssize_t>(m) * stride;
        }
    }
    if (even) return readOnlyView(first, shape, {stride, nx * ny * f, nx * f, f}, self);
    py::array_t<float> copy(shape);
    float* out = copy.mutable_data();
    for (std::size_t m = 0; m < e.memberCount(); ++m) {
        std::memcpy(out + m * e.grid.pointCount(), e.members[m].values.data(),
                    e.grid.pointCount() * sizeof(float));
    }
    copy.attr("setflags")(py::arg("write") = false);
    return copy;
}

py::dict axesOf(const data::Ensemble& e) {
    py::dict axes;
    for (const int a : {2, 1, 0}) {
        const data::Axis& axis = e.grid.axis(a);
        axes[py::str(axis.name)] = copyOf<double>(axis.values);
    }
    return axes;
}

py::object infoOf(const PyEnsemble& self) {
    const data::Ensemble& e = *self.data;
    prep::FieldStatistics stats;
    {
        const py::gil_scoped_release released;
        stats = prep::computeFieldStatistics(e, 0);
    }
    QStringList withoutData;
    for (const std::size_t m : data::membersWithoutData(e)) {
        withoutData << QString::fromStdString(memberName(e, m));
    }
    const QByteArray json =
        QJsonDocument(engine::ensembleInfoJson(*self.description, stats, e, withoutData))
            .toJson(QJsonDocument::Compact);
    return py::module_::import("json").attr("loads")(py::str(json.constData(), json.size()));
}

}  // namespace

void bindEnsemble(py::module_& module) {
    py::class_<PyEnsemble>(module, "Ensemble", R"doc(
An ensemble: members of one variable on one rectilinear grid, as ensil reads it (NaN where a
value is missing). Made by ensil.open(), ensil.from_numpy() or ensil.demo(); never changed
afterwards.

    values   (member, z, y, x) float32, read-only
    axes     {name: coordinates} in (z, y, x) order
    members  the members' names
)doc")
        .def_property_readonly("values", &valuesOf, R"doc(
The values as a read-only float32 NumPy array of shape (member, z, y, x), NaN where missing.
A view of ensil's own memory (no copy) when the members' blocks lie evenly in memory, as they
do when they were allocated one after another; otherwise a read-only copy. member_values(i) is
always a view.)doc")
        .def(
            "member_values",
            [](const py::object& self, long long index) {
                const data::Ensemble& e = *self.cast<const PyEnsemble&>().data;
                const auto count = static_cast<long long>(e.memberCount());
                if (index < -count || index >= count) {
                    throw py::index_error("member " + std::to_string(index) + " of " +
                                          std::to_string(count));
                }
                const auto m = static_cast<std::size_t>(index < 0 ? index + count : index);
                const auto f = static_cast<py::ssize_t>(sizeof(float));
                const auto nx = static_cast<py::ssize_t>(e.grid.nx());
                const auto ny = static_cast<py::ssize_t>(e.grid.ny());
                return readOnlyView(e.members[m].values.data(),
                                    {static_cast<py::ssize_t>(e.grid.nz()), ny, nx},
                                    {nx * ny * f, nx * f, f}, self);
            },
            py::arg("index"),
            "One member's values, (z, y, x), as a read-only view of ensil's memory (no copy).")
        .def_property_readonly(
            "axes", [](const PyEnsemble& self) { return axesOf(*self.data); },
            "The grid's coordinates, {name: 1-D float64 array}, in (z, y, x) order.")
        .def_property_readonly(
            "axis_units",
            [](const PyEnsemble& self) {
                py::dict units;
                for (const int a : {2, 1, 0}) {
                    units[py::str(self.data->grid.axis(a).name)] = self.data->grid.axis(a).units;
                }
                return units;
            },
            "Each axis's units, {name: units}, in (z, y, x) order.")
        .def_property_readonly(
            "dims",
            [](const PyEnsemble& self) {
                const data::Grid& g = self.data->grid;
                return py::make_tuple(self.data->memberDimension, g.z().name, g.y().name,
                                      g.x().name);
            },
            "The names of the values' four dimensions: (member, z, y, x).")
        .def_property_readonly(
            "shape",
            [](const PyEnsemble& self) {
                const data::Grid& g = self.data->grid;
                return py::make_tuple(self.data->memberCount(), g.nz(), g.ny(), g.nx());
            },
            "(members, nz, ny, nx).")
        .def_property_readonly(
            "members",
            [](const PyEnsemble& self) {
                std::vector<std::string> names;
                for (std::size_t m = 0; m < self.data->memberCount(); ++m) {
                    names.push_back(memberName(*self.data, m));
                }
                return names;
            },
            "The members' names, in member order.")
        .def_property_readonly(
            "variable", [](const PyEnsemble& self) { return self.data->variable; },
            "The variable's name.")
        .def_property_readonly(
            "units", [](const PyEnsemble& self) { return self.data->units; },
            "The variable's units ('' when none are given).")
        .def_property_readonly(
            "long_name", [](const PyEnsemble& self) { return self.data->longName; },
            "The variable's long name ('' when none is given).")
        .def_property_readonly(
            "source", [](const PyEnsemble& self) { return self.data->source; },
            "Where the data came from: a file's path, 'demo' or 'NumPy array'.")
        .def_property_readonly(
            "warnings", [](const PyEnsemble& self) { return self.data->warnings; },
            "What the readers said of these data (also given as ensil.DataWarning when read): "
            "few levels, members of different valid times, dropped messages; [] when nothing.")
        .def("info", &infoOf, R"doc(
What `ensil info --json` says of these data, as a dict: format, variable, units, members and
how their dimension was found, grid, axes, grid mapping, true longitude/latitude bounds, value
range and mean, missing values, the file's variables.)doc")
        .def("__len__", [](const PyEnsemble& self) { return self.data->memberCount(); })
        .def("__repr__", [](const PyEnsemble& self) {
            const data::Ensemble& e = *self.data;
            return "<ensil.Ensemble '" + e.variable + "'" +
                   (e.units.empty() ? std::string() : " [" + e.units + "]") + ": " +
                   std::to_string(e.memberCount()) + " members on " + std::to_string(e.grid.nx()) +
                   " x " + std::to_string(e.grid.ny()) + " x " + std::to_string(e.grid.nz()) +
                   " (" + e.grid.x().name + ", " + e.grid.y().name + ", " + e.grid.z().name + ")>";
        });

    module.def("_open", &openFiles, py::arg("paths"), py::arg("var"), py::arg("member_dim"),
               py::arg("time_index"), py::arg("levels"), py::arg("bbox"), py::arg("progress"));
    module.def("_from_numpy", &fromArray, py::arg("values"), py::arg("axes"), py::arg("variable"),
               py::arg("units"), py::arg("names"), py::arg("member_dim"),
               py::arg("grid_mapping") = py::dict());
    // For the tests only: the date ensil names a time step with, against python3-cftime.
    module.def(
        "_format_cf_time",
        [](double value, const std::string& units, const std::string& calendar) {
            return data::formatCfTime(value, units, calendar);
        },
        py::arg("value"), py::arg("units"), py::arg("calendar"));
    module.def("demo", &demoEnsemble, py::arg("members") = 50, py::arg("seed") = 1,
               py::arg("progress") = py::none(), R"doc(
The workbench's built-in demo ensemble: `members` members (1 to 1000) of a wind-speed-like
field on a 256 x 128 x 16 longitude/latitude/pressure grid, in four flow regimes, drawn from
`seed`. The same members as `ensil preprocess --demo` and the workbench's demo.)doc");
}

}  // namespace ensil::python

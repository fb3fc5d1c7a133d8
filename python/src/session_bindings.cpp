// ensil.Session: projects (.ensil) loaded, changed and saved from Python, with the settings of
// the one setting table under their ids, the command line's ranges and refusals.
#include <pybind11/stl.h>

#include <QString>

#include "python/src/bindings.h"
#include "python/src/errors.h"
#include "python/src/py_session.h"
#include "python/src/settings.h"
#include "session/project_file.h"
#include "session/view_presets.h"

namespace py = pybind11;

namespace ensil::python {
namespace {

// session.settings: a live mapping onto the session's state.
struct PySettings {
    std::shared_ptr<session::SessionState> state;
};

py::object getSetting(const PySettings& self, const std::string& id) {
    const session::Setting& s = settingNamed(id);
    return settingToPython(s, s.get(*self.state));
}

void setSetting(PySettings& self, const std::string& id, const py::handle& value) {
    const session::Setting& s = settingNamed(id);
    s.set(*self.state, settingFromPython(s, value));
}

std::vector<std::string> settingIds() {
    std::vector<std::string> ids;
    for (const session::Setting& s : session::settingTable()) ids.emplace_back(s.id);
    return ids;
}

// A path, or a sequence of them (str or os.PathLike), as ensil.open takes them; absolute, as
// a session holds them.
std::vector<std::string> pathList(const py::object& given) {
    if (given.is_none()) return {};
    const py::module_ os = py::module_::import("os");
    const auto one = [&os](const py::handle& p) {
        return os.attr("path")
            .attr("abspath")(os.attr("fsdecode")(os.attr("fspath")(p)))
            .cast<std::string>();
    };
    if (py::isinstance<py::str>(given) || py::hasattr(given, "__fspath__")) return {one(given)};
    std::vector<std::string> paths;
    for (const py::handle p : given) paths.push_back(one(p));
    return paths;
}

PySession newSession(const py::object& given, const std::string& variable,
                     const std::string& memberDim, long long timeIndex, const std::string& levels,
                     const py::object& bbox) {
    PySession s;
    const std::vector<std::string> paths = pathList(given);
    if (timeIndex < 0) {
        throw ArgumentError("time_index must be a whole number from 0, not '" +
                            std::to_string(timeIndex) + "'");
    }
    const std::optional<data::LevelRange> kept = levelsArgument(levels);
    const std::optional<data::Region> region = bboxArgument(bbox);
    if (paths.empty()) {
        s.state->demo = true;
        return s;
    }
    s.state->data =
        data::DataSelection{paths, variable, memberDim, static_cast<std::size_t>(timeIndex)};
    s.state->data.levels = kept;
    s.state->data.region = region;
    return s;
}

}  // namespace

void bindSession(py::module_& module) {
    py::class_<PySettings>(module, "Settings", R"doc(
A session's settings as a live mapping, {id: value}, with the ids, ranges and refusals of the
one setting table the command line, projects and panels share (`ensil render --help` lists
them as options). Numbers are float or int, flags bool, choices and colours str ('spaghetti',
'#1c1f24'). Setting a value outside its range raises ensil.ArgumentError with the command
line's message.)doc")
        .def("__getitem__", &getSetting, py::arg("id"))
        .def("__setitem__", &setSetting, py::arg("id"), py::arg("value"))
        .def("__contains__",
             [](const PySettings&, const std::string& id) {
                 for (const session::Setting& s : session::settingTable()) {
                     if (s.id == id) return true;
                 }
                 return false;
             })
        .def("__iter__", [](const PySettings&) { return py::iter(py::cast(settingIds())); })
        .def("__len__", [](const PySettings&) { return session::settingTable().size(); })
        .def("keys", [](const PySettings&) { return settingIds(); })
        .def("items",
             [](const PySettings& self) {
                 std::vector<std::pair<std::string, py::object>> items;
                 for (const session::Setting& s : session::settingTable()) {
                     items.emplace_back(s.id, settingToPython(s, s.get(*self.state)));
                 }
                 return items;
             })
        .def(
            "describe",
            [](const PySettings&, const std::string& id) {
                const session::Setting& s = settingNamed(id);
                py::dict d;
                d["label"] = std::string(s.label);
                d["help"] = std::string(s.help);
                d["unit"] = std::string(s.unit);
                d["allowed"] = s.allowed();
                d["default"] = settingToPython(s, s.defaultValue());
                d["option"] = s.option.empty() ? py::object(py::none())
                                               : py::object(py::str("--" + std::string(s.option)));
                d["project_key"] = std::string(s.projectKey);
                return d;
            },
            py::arg("id"), "What the setting is: label, help, unit, allowed values, default.")
        .def("__repr__", [](const PySettings& self) {
            std::string text = "{";
            for (const session::Setting& s : session::settingTable()) {
                text += (text.size() > 1 ? ", '" : "'") + std::string(s.id) + "': " +
                        py::repr(settingToPython(s, s.get(*self.state))).cast<std::string>();
            }
            return text + "}";
        });

    py::class_<PySession>(module, "Session", R"doc(
A workbench session: the data (files, or the demo), the isovalue, every rendering setting, the
camera and which members are hidden or selected, as a project file (.ensil) saves it.
Session.load() reads a project (validated whole, as the workbench and `ensil render` do);
save() writes one atomically; ensil.render(session) draws it as the workbench shows it.)doc")
        .def(py::init(&newSession), py::arg("paths") = py::none(), py::arg("var") = "",
             py::arg("member_dim") = "", py::arg("time_index") = 0, py::arg("levels") = "",
             py::arg("bbox") = py::none(), R"doc(
A new session with the default settings over data files (the selection as ensil.open takes
it, levels='1000:100hPa' and bbox=(-10, 40, 35, 72) included), or over the built-in demo when
no paths are given.)doc")
        .def_static(
            "load",
            [](const std::string& path) {
                PySession s;
                *s.state = session::loadProject(QString::fromStdString(path));
                s.path = path;
                return s;
            },
            py::arg("path"), "Reads and validates a project file; ensil.Error says what is wrong.")
        .def(
            "save",
            [](PySession& self, const std::optional<std::string>& path) {
                const std::optional<std::string> target = path ? path : self.path;
                if (!target) {
                    throw ArgumentError("say where to save the session: session.save('x.ensil')");
                }
                session::saveProject(*self.state, QString::fromStdString(*target));
                self.path = target;
            },
            py::arg("path") = py::none(), R"doc(
Writes the session as a project file (atomically: a failed write leaves the old file), to
`path` or to the file it was loaded from or last saved to. The workbench and
`ensil render x.ensil` open it.)doc")
        .def_property_readonly(
            "settings", [](const PySession& self) { return PySettings{self.state}; },
            "The settings, a live mapping (ensil.Settings).")
        .def(
            "set",
            [](PySession& self, const py::kwargs& values) {
                session::SessionState changed = *self.state;  // all or nothing
                for (const auto& [id, value] : values) {
                    const session::Setting& s = settingNamed(id.cast<std::string>());
                    s.set(changed, settingFromPython(s, value));
                }
                *self.state = changed;
            },
            "Sets several settings at once, by id: session.set(mode='spaghetti', thickness=0.02). "
            "Nothing changes when one is refused.")
        .def_property(
            "isovalue",
            [](const PySession& self) -> py::object {
                return self.state->isovalue ? py::object(py::float_(*self.state->isovalue))
                                            : py::object(py::none());
            },
            [](PySession& self, const std::optional<double>& iso) {
                self.state->isovalue = iso ? std::optional<float>(static_cast<float>(
                                                 boundedNumber("--iso", *iso, -1e30, 1e30)))
                                           : std::nullopt;
            },
            "The isovalue; None: the default for the variable (its 90th percentile).")
        .def(
            "look_from",
            [](PySession& self, const std::string& view) {
                const session::ViewPreset* preset = session::findViewPreset(view);
                if (preset == nullptr) {
                    throw ArgumentError("--view '" + view + "' is refused: it must be one of " +
                                        session::viewPresetNames());
                }
                session::lookFrom(*preset, self.state->camera);
            },
            py::arg("view"),
            "Places the camera at a named view: top, north, south, east, west, default.")
        .def_property_readonly(
            "demo", [](const PySession& self) { return self.state->demo; },
            "Whether the session shows the built-in demo.")
        .def_property_readonly(
            "paths", [](const PySession& self) { return self.state->data.paths; },
            "The data files (absolute once loaded from a project).")
        .def_property_readonly(
            "variable", [](const PySession& self) { return self.state->data.variable; },
            "The variable chosen ('' for the default one).")
        .def_property(
            "hidden_members", [](const PySession& self) { return self.state->hiddenMembers; },
            [](PySession& self, const std::vector<int>& members) {
                self.state->hiddenMembers = members;
            },
            "The members hidden, by index.")
        .def_property(
            "selection", [](const PySession& self) { return self.state->selection; },
            [](PySession& self, const std::vector<int>& members) {
                self.state->selection = members;
            },
            "The members selected, by index.")
        .def_property_readonly(
            "path", [](const PySession& self) { return self.path; },
            "The project file it was loaded from or last saved to, or None.")
        .def("__repr__", [](const PySession& self) {
            const session::SessionState& s = *self.state;
            std::string data = s.demo ? "the demo"
                               : s.data.paths.size() == 1
                                   ? "'" + s.data.paths.front() + "'"
                                   : std::to_string(s.data.paths.size()) + " files";
            return "<ensil.Session of " + data + ", isovalue " +
                   (s.isovalue ? QString::number(*s.isovalue).toStdString()
                               : std::string("default")) +
                   ">";
        });
}

}  // namespace ensil::python

#include "python/src/errors.h"

#include <array>
#include <new>
#include <string_view>
#include <utility>
#include <vector>

#include "data/error.h"
#include "data/job.h"
#include "engine/preprocess_run.h"
#include "session/project_file.h"

namespace py = pybind11;

namespace ensil::python {

std::optional<data::LevelRange> levelsArgument(const std::string& text) {
    if (text.empty()) return std::nullopt;
    try {
        return data::parseLevelRange(text);
    } catch (const data::Error& e) {
        throw ArgumentError(std::string("levels: ") + e.what());
    }
}

std::optional<data::Region> bboxArgument(const py::object& given) {
    if (given.is_none()) return std::nullopt;
    const std::string form =
        "give it as (lon0, lon1, lat0, lat1) in degrees, e.g. (-10, 40, 35, 72)";
    try {
        if (py::isinstance<py::str>(given)) return data::parseRegion(given.cast<std::string>());
        std::vector<double> values;
        try {
            values = given.cast<std::vector<double>>();
        } catch (const py::cast_error&) {
            throw ArgumentError("bbox: " + py::repr(given).cast<std::string>() +
                                " is not four numbers; " + form);
        }
        if (values.size() != 4) {
            throw ArgumentError("bbox: " + py::repr(given).cast<std::string>() + " has " +
                                std::to_string(values.size()) + " numbers, not 4; " + form);
        }
        const data::Region region{values[0], values[1], values[2], values[3]};
        data::checkRegion(region);
        return region;
    } catch (const data::Error& e) {
        throw ArgumentError(std::string("bbox: ") + e.what());
    }
}

namespace {

PyObject* g_error = nullptr;          // ensil.Error
PyObject* g_argumentError = nullptr;  // ensil.ArgumentError
PyObject* g_dataWarning = nullptr;    // ensil.DataWarning

// In data::ErrorKind's order.
constexpr std::array<std::string_view, 11> kKinds{
    "file_not_found",     "unsupported_format",    "corrupt_file",
    "variable_not_found", "not_three_dimensional", "member_dimension_not_found",
    "grid_mismatch",      "all_values_missing",    "out_of_memory",
    "write_failed",       "invalid_argument"};

void raise(PyObject* type, const char* message, const char* kind = nullptr,
           const std::vector<std::string>& choices = {}) {
    py::object error = py::reinterpret_borrow<py::object>(type)(message);
    error.attr("kind") = kind == nullptr ? py::object(py::none()) : py::object(py::str(kind));
    error.attr("choices") = py::cast(choices);
    PyErr_SetObject(type, error.ptr());
}

void translate(std::exception_ptr failure) {
    try {
        std::rethrow_exception(std::move(failure));
    } catch (const ArgumentError& e) {
        raise(g_argumentError, e.what(), "invalid_argument");
    } catch (const engine::PreprocessRefused& e) {
        raise(e.exitCode() == 2 ? g_argumentError : g_error, e.what(), "invalid_argument");
    } catch (const data::Error& e) {
        const auto kind = static_cast<std::size_t>(e.kind());
        raise(e.kind() == data::ErrorKind::InvalidArgument ? g_argumentError : g_error, e.what(),
              kind < kKinds.size() ? kKinds[kind].data() : nullptr, e.choices());
    } catch (const session::ProjectError& e) {
        raise(g_error, e.what(), "project");
    } catch (const data::Cancelled& e) {
        raise(g_error, e.what(), "cancelled");
    } catch (const py::builtin_exception&) {
        throw;  // IndexError and the like, raised on purpose: pybind11's own translation
    } catch (const std::runtime_error& e) {
        // What the renderer cannot do (no OpenGL 4.1 context, no display server and no EGL, a
        // call from another thread), said as the command line says it.
        raise(g_error, e.what());
    }
    // Anything else (std::bad_alloc as MemoryError): pybind11's own translation.
}

}  // namespace

void warn(const std::string& message, int stackLevel) {
    if (PyErr_WarnEx(g_dataWarning, message.c_str(), stackLevel) != 0) {
        throw py::error_already_set();
    }
}

void bindErrors(py::module_& m) {
    g_error = PyErr_NewExceptionWithDoc(
        "ensil.Error",
        "What ensil cannot do with these data, with the command line's message. `kind` names "
        "the problem ('file_not_found', 'variable_not_found', 'project', ...; None when there "
        "is no name for it); `choices` lists what would work instead, where there is a list.",
        PyExc_RuntimeError, nullptr);
    const py::tuple bases = py::make_tuple(py::handle(g_error), py::handle(PyExc_ValueError));
    g_argumentError = PyErr_NewExceptionWithDoc(
        "ensil.ArgumentError",
        "A refused argument (a setting outside its range, more clusters than members), with the "
        "command line's message. Also a ValueError.",
        bases.ptr(), nullptr);
    g_dataWarning = PyErr_NewExceptionWithDoc(
        "ensil.DataWarning",
        "What the command line says as a warning or note: members without data, infinite "
        "values, few vertical levels, pairs of members without a common point.",
        PyExc_UserWarning, nullptr);
    m.add_object("DataWarning", py::handle(g_dataWarning));
    m.add_object("Error", py::handle(g_error));
    m.add_object("ArgumentError", py::handle(g_argumentError));
    py::register_exception_translator(&translate);
}

}  // namespace ensil::python

// Ensemble.time_series: `ensil preprocess --times` from Python, through the same code
// (engine::preprocessTimeSeries): every step of the files read at its time index and
// preprocessed at one isovalue, its clusters matched to the previous step's so that a colour
// follows a group of members from step to step (METHODS.md section 8).
#include <string>
#include <vector>

#include "engine/time_series.h"
#include "python/src/bindings.h"
#include "python/src/errors.h"
#include "python/src/numpy_arrays.h"
#include "python/src/py_ensemble.h"
#include "python/src/py_preprocess.h"

namespace py = pybind11;

namespace ensil::python {
namespace {

struct PyTimeStep {
    std::size_t index = 0;
    std::string time;
    PyPreprocessResult result;
    std::vector<int> memberIdentities;
};

std::vector<PyTimeStep> timeSeries(const PyEnsemble& self, const std::string& times,
                                   const std::optional<double>& iso, const py::object& clusters,
                                   const py::object& linkage, double error, bool decimate,
                                   bool cache, const std::optional<std::string>& cacheDir,
                                   const py::object& progress) {
    if (!self.selection) {
        throw ArgumentError(
            "time_series needs an ensemble opened from files (ensil.open): its steps are read "
            "from them one at a time");
    }
    std::string problem;
    const auto steps =
        engine::parseStepRange(times, self.data->timeSteps.count(), "this ensemble", problem);
    if (!steps) throw ArgumentError("times " + problem.substr(problem.find(' ') + 1));
    engine::TimeSeriesRequest request;
    request.selection = *self.selection;
    request.steps = *steps;
    request.preprocess =
        preprocessRequestOf(self, iso, clusters, linkage, error, decimate, cache, cacheDir);
    std::vector<engine::TimeStepResult> done;
    runPreprocessing(
        [&](const std::stop_token& stop, const data::Progress& report,
            const engine::PreprocessNotice& notice) {
            done = engine::preprocessTimeSeries(request, notice, stop, report);
        },
        progress);
    std::vector<PyTimeStep> out;
    out.reserve(done.size());
    for (engine::TimeStepResult& step : done) {
        out.push_back({step.index,
                       step.time,
                       {std::make_shared<const engine::PreprocessResult>(std::move(step.result)),
                        request.preprocess.linkage},
                       std::move(step.memberIdentities)});
    }
    return out;
}

}  // namespace

void bindTimeSeries(py::module_& module) {
    py::class_<PyTimeStep>(module, "TimeStep", R"doc(
One time step of Ensemble.time_series: its time index, its time (ISO 8601 where the file dates
it), its PreprocessResult (clusters numbered and coloured by identities matched to the previous
step's) and each member's cluster identity, as `ensil preprocess --times --json` gives them.)doc")
        .def_readonly("index", &PyTimeStep::index)
        .def_readonly("time", &PyTimeStep::time)
        .def_readonly("result", &PyTimeStep::result)
        .def_property_readonly(
            "identities", [](const PyTimeStep& s) { return copyOf<int>(s.memberIdentities); },
            "Per member, its cluster's identity: the same number for a group followed from step "
            "to step.")
        .def("__repr__", [](const PyTimeStep& s) {
            return "<ensil.TimeStep " + std::to_string(s.index) + " (" + s.time + ")>";
        });

    auto ensemble = py::reinterpret_borrow<py::class_<PyEnsemble>>(module.attr("Ensemble"));
    ensemble.def("time_series", &timeSeries, py::arg("times") = "all", py::arg("iso") = py::none(),
                 py::arg("clusters") = py::none(), py::arg("linkage") = "average",
                 py::arg("error") = 0.25, py::arg("decimate") = true, py::arg("cache") = true,
                 py::arg("cache_dir") = py::none(), py::arg("progress") = py::none(),
                 R"doc(
`ensil preprocess --times` from Python: the steps `times` ("all", or "A:B", both included, from
0) of the files this ensemble was opened from, each read at its time index and preprocessed as
Ensemble.preprocess does, at one isovalue (`iso`, else the first step's default, kept for every
step), its clusters matched to the previous step's so that a colour follows a group of members.
Returns a list of ensil.TimeStep. Raises ensil.ArgumentError for an ensemble made from arrays or
a range the files do not have.)doc");
}

}  // namespace ensil::python

// The parts of the `ensil._ensil` extension module, one file each; module.cpp calls them in
// order (errors first: the others raise them).
#pragma once

#include <pybind11/pybind11.h>
// In every file of the module: pybind11's conversions must be the same in all of them.
#include <pybind11/stl.h>

namespace ensil::python {

void bindEnsemble(pybind11::module_& m);    // ensemble_bindings.cpp
void bindPreprocess(pybind11::module_& m);  // preprocess_bindings.cpp
void bindSession(pybind11::module_& m);     // session_bindings.cpp
void bindRender(pybind11::module_& m);      // render_bindings.cpp
void bindSection(pybind11::module_& m);     // section_bindings.cpp
void bindTimeSeries(pybind11::module_& m);  // time_series_bindings.cpp

}  // namespace ensil::python

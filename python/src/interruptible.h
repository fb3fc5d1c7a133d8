// Runs a long C++ step (reading, preprocessing, statistics) from Python without holding the
// GIL, so other Python threads go on, and keeps it cancellable: the step runs on a worker
// thread while the calling thread waits with the GIL released. Each time the step reports
// progress, the calling thread (GIL re-acquired) calls the user's progress callable and
// checks for Ctrl+C (PyErr_CheckSignals); the step waits for that before going on, so a
// KeyboardInterrupt or an exception raised by the callable requests the stop token before the
// step's next check, and the step ends by throwing data::Cancelled. The calling thread also
// checks for Ctrl+C every tenth of a second when no progress comes. The Python exception is
// then raised in place of the cancellation. Called with the GIL held.
#pragma once

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <functional>
#include <stop_token>

#include "data/job.h"

namespace ensil::python {

using Step = std::function<void(const std::stop_token& stop, const data::Progress& progress)>;

// Throws whatever `step` throws (translated to Python by errors.h), or
// pybind11::error_already_set for a KeyboardInterrupt or the callable's own exception.
// `progress` may be None.
void runInterruptible(const Step& step, const pybind11::object& progress);

}  // namespace ensil::python

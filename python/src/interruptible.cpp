#include "python/src/interruptible.h"

#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>

namespace py = pybind11;

namespace ensil::python {
namespace {

// What the worker and the waiting Python thread share.
struct Handshake {
    std::mutex mutex;
    std::condition_variable changed;
    std::optional<double> pending;  // a report the Python side has not answered yet
    double reported = -1.0;         // the highest fraction handed over so far
    bool finished = false;
};

}  // namespace

void runInterruptible(const Step& step, const py::object& progress) {
    Handshake h;
    std::stop_source stop;
    std::exception_ptr failure;
    // The step's progress, from the worker or its own workers: handed to the Python side, then
    // waited for, so that a stop asked for in answer is seen at the step's next check.
    const data::Progress report = [&h](double fraction) {
        std::unique_lock lock(h.mutex);
        h.changed.wait(lock, [&h] { return !h.pending.has_value(); });
        // The step's parallel workers report as they finish, not always in order: Python sees
        // the fraction rise only.
        if (fraction <= h.reported) return;
        h.reported = fraction;
        h.pending = fraction;
        h.changed.notify_all();
        h.changed.wait(lock, [&h] { return !h.pending.has_value(); });
    };
    std::optional<py::error_already_set> raised;  // the Python exception that stopped the step
    {
        std::jthread worker([&] {
            try {
                step(stop.get_token(), report);
            } catch (...) {
                failure = std::current_exception();
            }
            const std::lock_guard lock(h.mutex);
            h.finished = true;
            h.changed.notify_all();
        });
        std::unique_lock lock(h.mutex);
        while (!h.finished || h.pending) {
            {
                const py::gil_scoped_release released;
                h.changed.wait_for(lock, std::chrono::milliseconds(100),
                                   [&h] { return h.finished || h.pending.has_value(); });
            }
            // Python runs with the lock released, so the step's other workers never wait on it
            // for longer than a report takes.
            const std::optional<double> fraction = h.pending;
            lock.unlock();
            if (!raised) {
                try {
                    if (fraction && !progress.is_none()) progress(*fraction);
                    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
                } catch (py::error_already_set& e) {
                    raised.emplace(std::move(e));
                    stop.request_stop();
                }
            }
            lock.lock();
            if (fraction) {
                h.pending.reset();
                h.changed.notify_all();
            }
        }
        lock.unlock();
        const py::gil_scoped_release released;
        worker.join();
    }
    if (raised) throw std::move(*raised);
    if (failure) std::rethrow_exception(failure);
}

}  // namespace ensil::python

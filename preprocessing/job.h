// The contract every preprocessing step follows: a pure function that takes its inputs by
// value or const reference, a std::stop_token, and a progress callback, and returns a value.
// A step checks the token often enough to notice a cancel within ~100 ms and then throws
// Cancelled, so nothing half-done escapes. Progress is reported as a fraction in [0, 1],
// monotonically, from the worker thread that runs the step (the callback must be thread-safe).
#pragma once

#include <functional>
#include <stdexcept>
#include <stop_token>

namespace ensil::prep {

using Progress = std::function<void(double fraction)>;

class Cancelled : public std::runtime_error {
public:
    Cancelled() : std::runtime_error("cancelled") {}
};

inline void throwIfStopped(const std::stop_token& stop) {
    if (stop.stop_requested()) throw Cancelled();
}

inline void report(const Progress& progress, double fraction) {
    if (progress) progress(fraction);
}

}  // namespace ensil::prep

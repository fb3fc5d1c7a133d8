// The contract every long-running step follows, in every layer that links no Qt: it takes a
// std::stop_token and a progress callback, checks the token often enough to notice a cancel
// within ~100 ms, and then throws Cancelled so nothing half-done escapes. Progress is a fraction
// in [0, 1], reported monotonically from the worker thread running the step (the callback must
// be thread-safe).
#pragma once

#include <functional>
#include <stdexcept>
#include <stop_token>

namespace ensil::data {

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

}  // namespace ensil::data

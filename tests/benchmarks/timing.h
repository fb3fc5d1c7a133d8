// Medians for benchmark programs.
#pragma once

#include <algorithm>
#include <chrono>
#include <vector>

namespace ensil::bench {

inline double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

// The median wall time of `runs` calls of f, in milliseconds.
template <typename F>
double medianMs(int runs, F&& f) {
    std::vector<double> times;
    for (int r = 0; r < runs; ++r) {
        const auto start = std::chrono::steady_clock::now();
        f();
        times.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count());
    }
    return median(std::move(times));
}

}  // namespace ensil::bench

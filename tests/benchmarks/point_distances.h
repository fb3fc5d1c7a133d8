// Synthetic distance matrices for the benchmarks that time clustering and the panels.
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

#include "preprocessing/similarity.h"

namespace ensil::bench {

// Euclidean distances between n points of `dims` coordinates each (point i at points[dims * i]).
inline prep::DistanceMatrix euclideanDistances(const std::vector<double>& points, std::size_t n,
                                               std::size_t dims) {
    prep::DistanceMatrix d{n, std::vector<double>(n * n), {}};
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = 0; j < n; ++j) {
            double sum = 0.0;
            for (std::size_t a = 0; a < dims; ++a) {
                const double diff = points[dims * i + a] - points[dims * j + a];
                sum += diff * diff;
            }
            d.values[i * n + j] = std::sqrt(sum);
        }
    }
    return d;
}

}  // namespace ensil::bench

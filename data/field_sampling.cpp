#include "data/field_sampling.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace ensil::data {

float sampleTrilinear(const Grid& grid, std::span<const float> values, const glm::dvec3& index) {
    constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
    if (values.size() != grid.pointCount()) return kNaN;
    const std::array<std::size_t, 3> n{grid.nx(), grid.ny(), grid.nz()};
    std::array<std::size_t, 3> lo{};
    std::array<double, 3> f{};
    for (int a = 0; a < 3; ++a) {
        const auto ua = static_cast<std::size_t>(a);
        const double i = std::clamp(index[a], 0.0, static_cast<double>(n[ua] - 1));
        lo[ua] = std::min(static_cast<std::size_t>(i), n[ua] - 2);
        f[ua] = i - static_cast<double>(lo[ua]);
    }
    double sum = 0.0;
    double weights = 0.0;
    for (int c = 0; c < 8; ++c) {
        const std::size_t i = lo[0] + (c & 1), j = lo[1] + ((c >> 1) & 1),
                          k = lo[2] + ((c >> 2) & 1);
        const double w = ((c & 1) ? f[0] : 1.0 - f[0]) * (((c >> 1) & 1) ? f[1] : 1.0 - f[1]) *
                         (((c >> 2) & 1) ? f[2] : 1.0 - f[2]);
        const float v = values[grid.index(i, j, k)];
        if (std::isnan(v) || w <= 0.0) continue;
        sum += w * v;
        weights += w;
    }
    return weights > 0.0 ? static_cast<float>(sum / weights) : kNaN;
}

}  // namespace ensil::data

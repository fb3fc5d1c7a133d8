#include "gl/axis_ticks.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace ensil::gl {

std::vector<double> niceTicks(double lo, double hi, int wanted) {
    if (lo > hi) std::swap(lo, hi);
    if (!std::isfinite(lo) || !std::isfinite(hi) || hi - lo <= 0.0 || wanted < 1) return {};
    const double rough = (hi - lo) / wanted;
    const double power = std::pow(10.0, std::floor(std::log10(rough)));
    // The smallest round step at least as large as the rough one.
    double step = 10.0 * power;
    for (const double m : std::array{1.0, 2.0, 2.5, 5.0}) {
        if (m * power >= rough * (1.0 - 1e-9)) {
            step = m * power;
            break;
        }
    }
    std::vector<double> ticks;
    const double tolerance = step * 1e-9;
    for (double k = std::ceil((lo - tolerance) / step); k * step <= hi + tolerance; k += 1.0) {
        const double t = k * step;
        ticks.push_back(std::abs(t) < tolerance ? 0.0 : t);  // no "-0"
    }
    return ticks;
}

}  // namespace ensil::gl

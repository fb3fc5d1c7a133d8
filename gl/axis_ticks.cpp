#include "gl/axis_ticks.h"

#include <algorithm>
#include <array>
#include <cctype>
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

namespace {

// The standard pressure levels (WMO mandatory levels and the usual model levels), the main
// ones first.
constexpr std::array kMainLevels{1000.0, 850.0, 700.0, 500.0, 300.0, 200.0,
                                 100.0,  50.0,  10.0,  5.0,   1.0};
constexpr std::array kOtherLevels{925.0, 600.0, 400.0, 250.0, 150.0, 70.0,
                                  30.0,  20.0,  7.0,   3.0,   2.0};
constexpr double kKilometreAbove = 10000.0;  // metres: heights beyond are labelled in km

}  // namespace

AxisLabelling labellingFor(const data::Axis& axis) {
    const double lo = axis.minValue();
    const double hi = axis.maxValue();
    AxisLabelling labelling;
    labelling.units = axis.units;
    if (const double hPa = data::hectopascalsPer(axis.units); hPa > 0.0) {
        labelling.shownPerUnit = hPa;
        labelling.units = "hPa";
        const double tolerance = 1e-9 * (hi - lo);
        for (const auto* levels : {&kMainLevels, &kOtherLevels}) {
            for (const double level : *levels) {
                const double value = level / hPa;
                if (value >= lo - tolerance && value <= hi + tolerance) {
                    labelling.ticks.push_back(value);
                }
            }
        }
        // A narrow range (990 to 1000 hPa) holds too few standard levels to read it by.
        if (labelling.ticks.size() < 2) {
            labelling.ticks.clear();
            for (const double t : niceTicks(lo * hPa, hi * hPa)) labelling.ticks.push_back(t / hPa);
        }
        return labelling;
    }
    const bool metres = data::metresPer(axis.units) == 1.0;
    if (metres && std::max(std::abs(lo), std::abs(hi)) > kKilometreAbove) {
        labelling.shownPerUnit = 0.001;
        labelling.units = "km";
        for (const double t : niceTicks(lo / 1000.0, hi / 1000.0)) {
            labelling.ticks.push_back(t * 1000.0);
        }
        return labelling;
    }
    labelling.ticks = niceTicks(lo, hi);
    return labelling;
}

}  // namespace ensil::gl

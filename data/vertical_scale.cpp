#include "data/vertical_scale.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>

#include "data/ascii_case.h"

namespace ensil::data {
namespace {

// The mean Earth radius's degree, for a degree of latitude (and of longitude as the map draws
// it: the box gives a degree of either the same width).
constexpr double kMetresPerDegree = 6371008.8 * 3.14159265358979323846 / 180.0;

bool isDegreeUnit(const std::string& units) {
    const std::string u = asciiLower(units);
    return u.starts_with("degree") || u == "deg";
}

// ISO 2533's layers: base height (m), base pressure (hPa), base temperature (K), lapse rate
// (K/m, positive cooling upward).
constexpr double kGasConstant = 287.05287;  // J/(kg K), dry air
constexpr double kGravity = 9.80665;        // m/s^2

}  // namespace

double standardAtmosphereHeight(double hPa) {
    struct Layer {
        double height, pressure, temperature, lapse;
    };
    constexpr Layer kLayers[] = {{0.0, 1013.25, 288.15, 0.0065},
                                 {11000.0, 226.32, 216.65, 0.0},
                                 {20000.0, 54.7489, 216.65, -0.001}};
    const Layer* layer = &kLayers[0];
    for (const Layer& l : kLayers) {
        if (hPa <= l.pressure) layer = &l;
    }
    if (layer->lapse == 0.0) {
        return layer->height -
               kGasConstant * layer->temperature / kGravity * std::log(hPa / layer->pressure);
    }
    const double exponent = kGasConstant * layer->lapse / kGravity;
    return layer->height +
           layer->temperature / layer->lapse * (1.0 - std::pow(hPa / layer->pressure, exponent));
}

std::optional<VerticalScale> verticalScaleOf(const Grid& grid, const DisplayFrame& frame) {
    const Axis& x = grid.x();
    const Axis& y = grid.y();
    const Axis& z = grid.z();
    if (x.size() < 2 || y.size() < 2 || z.size() < 2) return std::nullopt;
    // Metres per display unit along the horizontal: the longer axis spans 1 (display_frame.h).
    const double longest = std::max(x.maxValue() - x.minValue(), y.maxValue() - y.minValue());
    double metresPerUnit = 0.0;
    if (isDegreeUnit(x.units) && isDegreeUnit(y.units)) {
        metresPerUnit = longest * kMetresPerDegree;
    } else if (metresPer(x.units) > 0.0 && metresPer(x.units) == metresPer(y.units)) {
        metresPerUnit = longest * metresPer(x.units);
    }
    VerticalScale scale;
    double trueHeight = 0.0;
    if (const double hPa = hectopascalsPer(z.units); hPa > 0.0 && z.minValue() > 0.0) {
        trueHeight = standardAtmosphereHeight(z.minValue() * hPa) -
                     standardAtmosphereHeight(z.maxValue() * hPa);
        scale.standardAtmosphere = true;
    } else if (const double m = metresPer(z.units); m > 0.0) {
        trueHeight = (z.maxValue() - z.minValue()) * m;
    }
    if (!(metresPerUnit > 0.0) || !(trueHeight > 0.0)) return std::nullopt;
    const double drawnHeight = frame.boxMax().z - frame.boxMin().z;
    scale.factor = drawnHeight * metresPerUnit / trueHeight;
    return scale;
}

}  // namespace ensil::data

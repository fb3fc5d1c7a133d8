#include "data/number_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ensil::data {

std::string readableNumber(double value, int significant) {
    significant = std::max(1, significant);
    if (std::isnan(value)) return "NaN";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    char buffer[64];
    const double magnitude = std::fabs(value);
    if (magnitude != 0.0 && (magnitude < 1e-3 || magnitude >= 1e6)) {
        std::snprintf(buffer, sizeof buffer, "%.*g", significant, value);
        return buffer;
    }
    // Digits before the point, from the value as rounded to its significant digits (9999.7 with
    // 4 digits is 10000, five digits).
    const int before =
        magnitude == 0.0 ? 1 : static_cast<int>(std::floor(std::log10(magnitude))) + 1;
    const int decimals = std::max(0, significant - before);
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
    std::string text = buffer;
    if (text.find('.') != std::string::npos) {
        while (text.back() == '0') text.pop_back();
        if (text.back() == '.') text.pop_back();
    }
    if (text == "-0") text = "0";
    // Thousands separators in an integer part of five digits or more (1000 hPa stays 1000).
    const std::size_t start = text.front() == '-' ? 1 : 0;
    const std::size_t point = std::min(text.find('.'), text.size());
    if (point - start >= 5) {
        for (std::size_t i = point; i > start + 3; i -= 3) text.insert(i - 3, ",");
    }
    return text;
}

}  // namespace ensil::data

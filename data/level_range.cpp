#include "data/level_range.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "data/ascii_case.h"
#include "data/error.h"
#include "data/number_text.h"
#include "data/unit_conversion.h"

namespace ensil::data {
namespace {

constexpr const char* kForm = "give it as FROM:TO with optional units, e.g. 1000:100hPa or 0:12km";

[[noreturn]] void refuse(const std::string& text, const std::string& why) {
    throw Error(ErrorKind::InvalidArgument,
                "the level range '" + text + "' " + why + ": " + std::string(kForm));
}

// A number at the start of `s` (after spaces); sets `rest` to what follows it.
std::optional<double> leadingNumber(const std::string& s, std::string& rest) {
    const std::string t = asciiTrimmed(s);
    double value = 0.0;
    const auto [end, error] = std::from_chars(t.data(), t.data() + t.size(), value);
    if (error != std::errc() || !std::isfinite(value)) return std::nullopt;
    rest = asciiTrimmed(std::string(end, t.data() + t.size()));
    return value;
}

// The shortest text that reads back as the same double ("85000", "0.5"): no thousands separators,
// so that levelRangeText's text parses again.
std::string shortest(double value) {
    char buffer[32];
    const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
    return error == std::errc() ? std::string(buffer, end) : std::to_string(value);
}

}  // namespace

LevelRange parseLevelRange(const std::string& text) {
    const auto colon = text.find(':');
    if (colon == std::string::npos) refuse(text, "has no ':' between its two ends");
    std::string afterFrom;
    std::string units;
    const std::optional<double> from = leadingNumber(text.substr(0, colon), afterFrom);
    const std::optional<double> to = leadingNumber(text.substr(colon + 1), units);
    if (!from || !to) refuse(text, "does not start each end with a number");
    // Units once, after the second end; the same units after both are allowed too.
    if (!afterFrom.empty() && afterFrom != units) {
        refuse(text, "gives its ends in different units ('" + afterFrom + "' and '" + units + "')");
    }
    if (!units.empty() && !isKnownUnit(units)) {
        refuse(text, "names units UDUNITS-2 does not know ('" + units + "')");
    }
    return {*from, *to, units};
}

std::string levelRangeText(const LevelRange& range) {
    return shortest(range.from) + ":" + shortest(range.to) +
           (range.units.empty() ? "" : " " + range.units);
}

LayerSpan layersWithin(const Axis& z, const LevelRange& range, const std::string& source) {
    // What a refusal names (only then written out).
    const auto axis = [&] {
        return "the vertical axis '" + z.name + "' of " + source + " (from " +
               readableNumber(z.front(), 9) + " to " + readableNumber(z.back(), 9) +
               (z.units.empty() ? "" : " " + z.units) + ", " + std::to_string(z.size()) +
               " levels)";
    };
    double from = range.from;
    double to = range.to;
    if (!range.units.empty() && range.units != z.units) {
        const std::optional<double> f = convertUnits(range.from, range.units, z.units);
        const std::optional<double> t = convertUnits(range.to, range.units, z.units);
        if (!f || !t) {
            throw Error(ErrorKind::InvalidArgument,
                        "levels " + levelRangeText(range) + " cannot be compared with " + axis() +
                            (z.units.empty() || !isKnownUnit(z.units)
                                 ? ", whose units UDUNITS-2 does not know: give the range in its "
                                   "own values, without units"
                                 : ": '" + range.units + "' and '" + z.units +
                                       "' measure different things"));
        }
        from = *f;
        to = *t;
    }
    const double lo = std::min(from, to);
    const double hi = std::max(from, to);
    // A range typed from the values shown ("850" for 85000 Pa) meets the stored ones within
    // rounding.
    const double slack = 1e-9 * std::max({std::abs(lo), std::abs(hi), 1.0});
    std::optional<std::size_t> first;
    std::size_t count = 0;
    for (std::size_t k = 0; k < z.size(); ++k) {
        if (z.values[k] < lo - slack || z.values[k] > hi + slack) continue;
        if (!first) first = k;
        ++count;
    }
    if (count < 2) {
        throw Error(ErrorKind::InvalidArgument, "levels " + levelRangeText(range) + " hold " +
                                                    std::to_string(count) +
                                                    (count == 1 ? " level" : " levels") + " of " +
                                                    axis() + "; a volume needs at least 2");
    }
    return {*first, count};  // the axis is monotonic, so the levels within are contiguous
}

}  // namespace ensil::data

#include "engine/picture_title.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdio>
#include <functional>
#include <vector>

#include "data/number_text.h"
#include "data/units_text.h"
#include "gl/axis_ticks.h"

namespace ensil::engine {
namespace {

// An isovalue with as many digits as it needs and no more: 260, 0.0035, 23,690.
std::string formatValue(float value) { return data::readableNumber(static_cast<double>(value)); }

// The same in a file name: no thousands separators ("z_57575..."), exponents as printf writes.
std::string fileValue(float value) {
    std::array<char, 32> text{};
    std::snprintf(text.data(), text.size(), "%.6g", static_cast<double>(value));
    return text.data();
}

// "time = 0 of 4 (2017-01-01T00:00)" -> "time 2017-01-01T00:00"; without a coordinate value,
// "time 1 of 4" (counted from one, as people count).
std::string shortFixedDimension(const std::string& line) {
    const auto equals = line.find(" = ");
    if (equals == std::string::npos) return line;
    const std::string name = line.substr(0, equals);
    const auto open = line.find(" (", equals);
    if (open != std::string::npos && line.back() == ')') {
        return name + " " + line.substr(open + 2, line.size() - open - 3);
    }
    const std::string rest = line.substr(equals + 3);
    const auto of = rest.find(" of ");
    if (of == std::string::npos) return name + " " + rest;
    try {
        return name + " " + std::to_string(std::stoul(rest.substr(0, of)) + 1) + rest.substr(of);
    } catch (const std::exception&) {
        return name + " " + rest;
    }
}

}  // namespace

std::string unitsInBrackets(const data::Ensemble& e) {
    return e.units.empty() ? "" : " [" + data::readableUnits(e.units) + "]";
}

namespace {
// " m s⁻¹", after a value; nothing without units.
std::string unitsAfterValue(const data::Ensemble& e) {
    return e.units.empty() ? "" : " " + data::readableUnits(e.units);
}
}  // namespace

std::function<std::string(float)> pictureTitleOf(const data::Ensemble& e) {
    std::string head = e.variable;
    // "t (Temperature)"; a long name with parentheses of its own follows a colon instead, so
    // that they never nest: "wind_speed: Wind speed (ensil demo jet streams)".
    if (!e.longName.empty() && e.longName != e.variable) {
        head += e.longName.find_first_of("()") == std::string::npos ? " (" + e.longName + ")"
                                                                    : ": " + e.longName;
    }
    head += unitsInBrackets(e);
    const std::string separator = " \u00b7 ";
    head += separator + "isovalue ";
    std::string tail = unitsAfterValue(e);
    for (const std::string& fixed : e.fixedDimensions) {
        tail += separator + shortFixedDimension(fixed);
    }
    tail += separator + std::to_string(e.memberCount()) +
            (e.memberCount() == 1 ? " member" : " members");
    if (!e.memberDimension.empty()) tail += " along " + e.memberDimension;
    return [head = std::move(head), tail = std::move(tail)](float isovalue) {
        return head + formatValue(isovalue) + tail;
    };
}

std::string pictureTitle(const data::Ensemble& e, float isovalue) {
    return pictureTitleOf(e)(isovalue);
}

std::string floorCaption(const data::Ensemble& e) {
    return "floor: column maximum of the mean " + e.variable + unitsInBrackets(e);
}

std::string floorCaption(const data::Ensemble& e, int level) {
    const data::Axis& z = e.grid.z();
    const auto k = static_cast<std::size_t>(std::clamp(level, 0, static_cast<int>(z.size()) - 1));
    const gl::AxisLabelling labelling = gl::labellingFor(z);
    const std::string value = data::readableNumber(z.values[k] * labelling.shownPerUnit);
    return "floor: mean " + e.variable + " at " + value + " " +
           (labelling.units.empty() ? z.name : labelling.units) + unitsInBrackets(e);
}

std::string exceedanceText(const data::Ensemble& e, float isovalue) {
    return "P(" + e.variable + " > " + formatValue(isovalue) + unitsAfterValue(e) + ")";
}

std::string sectionQuantity(const data::Ensemble& e, gl::SectionField field, int member,
                            float isovalue) {
    switch (field) {
        case gl::SectionField::None:
            return {};
        case gl::SectionField::Member: {
            const bool known = member >= 0 && static_cast<std::size_t>(member) < e.memberCount();
            return (known ? e.members[static_cast<std::size_t>(member)].name : "member") + ": " +
                   e.variable;
        }
        case gl::SectionField::Mean:
            return "mean " + e.variable;
        case gl::SectionField::StandardDeviation:
            return "standard deviation of " + e.variable;
        case gl::SectionField::Probability:
            return exceedanceText(e, isovalue);
    }
    return {};
}

std::string pictureFileStem(const data::Ensemble& e, float isovalue) {
    std::string stem = e.variable + "_" + fileValue(isovalue) + e.units;
    for (const std::string& fixed : e.fixedDimensions) stem += "_" + shortFixedDimension(fixed);
    std::string clean;
    for (const char c : stem) {
        const auto u = static_cast<unsigned char>(c);
        if (std::isalnum(u) != 0 || c == '.' || c == '-' || c == '_') {
            clean += c;
        } else if (c == ' ' || c == ':' || c == '/') {
            if (!clean.empty() && clean.back() != '-' && clean.back() != '_') clean += '-';
        }
    }
    return clean.empty() ? "ensil" : clean;
}

}  // namespace ensil::engine

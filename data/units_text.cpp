#include "data/units_text.h"

#include <cctype>
#include <vector>

namespace ensil::data {
namespace {

// The superscript of a digit or of a minus sign, in UTF-8.
const char* superscript(char c) {
    static constexpr const char* kDigits[] = {"\u2070", "\u00b9", "\u00b2", "\u00b3", "\u2074",
                                              "\u2075", "\u2076", "\u2077", "\u2078", "\u2079"};
    return c == '-' ? "\u207b" : kDigits[c - '0'];
}

bool isSymbolChar(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0 || c == '%'; }
bool isDigit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

// One factor, a symbol with an optional exponent ("m", "s^-2", "s-1", "m2"), typeset onto
// `out`; false when the token is something else.
bool typesetFactor(std::string_view token, std::string& out) {
    std::size_t symbolEnd = 0;
    while (symbolEnd < token.size() && isSymbolChar(token[symbolEnd])) ++symbolEnd;
    if (symbolEnd == 0) return false;
    std::string_view exponent = token.substr(symbolEnd);
    if (exponent.starts_with('^')) exponent.remove_prefix(1);
    const bool negative = exponent.starts_with('-');
    if (negative || exponent.starts_with('+')) exponent.remove_prefix(1);
    if (exponent.empty() && symbolEnd < token.size()) return false;  // "s^", "s-"
    for (const char c : exponent) {
        if (!isDigit(c)) return false;
    }
    out.append(token.substr(0, symbolEnd));
    if (!negative && exponent == "1") return true;  // "m1" is "m"
    if (negative) out += superscript('-');
    for (const char c : exponent) out += superscript(c);
    return true;
}

}  // namespace

std::string readableUnits(std::string_view units) {
    // UDUNITS writes a power as "**" or "^" and a product with spaces, '.' or '*'.
    std::string powers;
    for (std::size_t i = 0; i < units.size(); ++i) {
        if (units.substr(i).starts_with("**")) {
            powers += '^';
            ++i;
        } else {
            powers += units[i];
        }
    }
    std::string out;
    std::size_t at = 0;
    while (at <= powers.size()) {
        const std::size_t end = std::min(powers.find_first_of(" .*", at), powers.size());
        const std::string_view token = std::string_view(powers).substr(at, end - at);
        if (!token.empty()) {
            if (!out.empty()) out += ' ';
            if (!typesetFactor(token, out)) return std::string(units);
        }
        at = end + 1;
    }
    return out;
}

}  // namespace ensil::data

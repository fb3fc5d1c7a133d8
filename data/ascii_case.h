// Lower case for names and units as files write them (ASCII: "degrees_East", "HPA"), without
// the locale. Pure; any thread.
#pragma once

#include <algorithm>
#include <cctype>
#include <string>

namespace ensil::data {

inline std::string asciiLower(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return text;
}

}  // namespace ensil::data

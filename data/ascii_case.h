// Names, units and values as files and users write them: lower case (ASCII: "degrees_East",
// "HPA") without the locale, and text without the spaces and tabs around it. Pure; any thread.
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

// `text` without the spaces and tabs at its ends ("" when it holds nothing else).
inline std::string asciiTrimmed(const std::string& text) {
    const auto first = text.find_first_not_of(" \t");
    if (first == std::string::npos) return {};
    return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

}  // namespace ensil::data

// Every scalar setting of a session, defined once: its name, kind, range, unit and help text,
// and the names it goes by in a project file, on the command line and in the remembered
// settings. Project validation (project_file.h), the command line (setting_options.h), the
// remembered settings (remembered_settings.h) and the panels' ranges are all derived from this
// table, so they cannot disagree. Defaults are those of a default-made SessionState.
// Modelled on F3D's single options schema and Inviwo's ordinal properties. Any thread.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "session/session_state.h"

namespace ensil::session {

enum class SettingKind {
    Number,   // a finite real number in [minimum, maximum]
    Integer,  // a whole number in [minimum, maximum]
    Flag,     // true or false (1 or 0)
    Choice,   // one of `choices`, held as its index
    Colour,   // an RGB colour, held as 0xRRGGBB
};

struct Setting {
    std::string_view id;  // how code names it: setting("thickness")
    SettingKind kind;
    std::string_view projectKey;     // dotted path in the project file; empty: not saved
    std::string_view option;         // command-line option without "--"; empty: none
    std::string_view rememberedKey;  // QSettings key; empty: not remembered between runs
    std::string_view label;          // as the panels show it
    std::string_view unit;           // shown after values; empty when unit-free
    std::string_view help;           // one sentence: panels' tool tips, --help
    double minimum = 0.0;
    double maximum = 0.0;
    int decimals = 0;  // how panels show it
    double step = 1.0;
    std::span<const std::string_view> choices;  // Choice only
    double (*get)(const SessionState&);
    void (*set)(SessionState&, double);

    [[nodiscard]] double defaultValue() const { return get(SessionState{}); }
    // Empty when `value` is allowed; otherwise why not ("must lie between 0.0001 and 0.5").
    [[nodiscard]] std::string problemWith(double value) const;
    // The value as a user writes it: a choice's name, "true"/"false", "#rrggbb", or the number.
    [[nodiscard]] std::string format(double value) const;
    // The allowed values, as problemWith() and --help name them.
    [[nodiscard]] std::string allowed() const;
};

// All settings, in the order panels and --help list them.
std::span<const Setting> settingTable();
// The setting with this id; throws std::logic_error for an unknown id (a programming error).
const Setting& setting(std::string_view id);

// Colour packing shared by the Colour settings.
double packColour(const glm::vec3& rgb);
glm::vec3 unpackColour(double packed);

}  // namespace ensil::session

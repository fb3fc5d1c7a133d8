// The command line's view of the setting table: one option per setting that has an option name
// (a flag as --NAME and --no-NAME), its help text, default and allowed values from the table,
// and typed, checked parsing: a non-number, NaN, infinity, a fraction where a whole number
// belongs or a value out of range is refused naming the option, the value and what is allowed.
// Also the checked parsers for command-line values that are not session settings (an image
// size, a frame count). Main thread.
#pragma once

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QString>
#include <QStringList>
#include <initializer_list>
#include <optional>
#include <string_view>
#include <vector>

#include "session/session_state.h"
#include "session/setting_table.h"

namespace ensil::session {

class SettingOptions {
public:
    // The options of these settings (each must have an option name).
    SettingOptions(std::initializer_list<std::string_view> ids);

    void addTo(QCommandLineParser& parser) const;
    // Writes the given options' values into `state`. On a bad value returns false and sets
    // `problem` ("--thickness -5 is refused: it must be a number from 0.0001 to 0.5").
    bool applyTo(const QCommandLineParser& parser, SessionState& state, QString& problem) const;
    // The options the user gave, as typed ("--thickness").
    [[nodiscard]] QStringList given(const QCommandLineParser& parser) const;

private:
    struct Entry {
        const Setting* setting;
        QCommandLineOption option;
        std::optional<QCommandLineOption> negation;  // --no-NAME, for flags
    };
    std::vector<Entry> m_entries;
};

// A value typed for `setting` (a number, a choice's name, true/false, #rrggbb), checked against
// its range; nullopt with `problem` set when it is not allowed.
std::optional<double> parseSettingValue(const Setting& setting, const QString& text,
                                        QString& problem);
// A finite number in [minimum, maximum] (whole when `whole`), given as option `name`.
std::optional<double> parseBoundedNumber(const QString& name, const QString& text, double minimum,
                                         double maximum, bool whole, QString& problem);
// "WxH" with both from 1 to kMaxImageSide; no overflow, no wrap-around.
inline constexpr int kMaxImageSide = 16384;
std::optional<std::pair<int, int>> parseImageSize(const QString& name, const QString& text,
                                                  QString& problem);

}  // namespace ensil::session

#include "session/remembered_settings.h"

#include <QColor>
#include <QVariant>
#include <optional>

#include "session/setting_table.h"

namespace ensil::session {
namespace {
QString keyOf(const Setting& s) {
    return QString::fromLatin1(s.rememberedKey.data(),
                               static_cast<qsizetype>(s.rememberedKey.size()));
}

std::optional<double> read(const Setting& s, const QVariant& v) {
    double value = 0.0;
    bool ok = false;
    switch (s.kind) {
        case SettingKind::Flag: {
            const QString text = v.toString();
            if (text != QLatin1String("true") && text != QLatin1String("false")) return {};
            return text == QLatin1String("true") ? 1.0 : 0.0;
        }
        case SettingKind::Choice: {
            const QString text = v.toString();
            for (std::size_t i = 0; i < s.choices.size(); ++i) {
                if (text == QLatin1String(s.choices[i].data(),
                                          static_cast<qsizetype>(s.choices[i].size()))) {
                    return static_cast<double>(i);
                }
            }
            value = v.toDouble(&ok);  // earlier versions stored the index
            break;
        }
        case SettingKind::Colour: {
            // Earlier versions stored a QColor; this one its name.
            const QColor colour = v.canConvert<QColor>() ? v.value<QColor>() : QColor();
            if (!colour.isValid()) return {};
            value = packColour({colour.redF(), colour.greenF(), colour.blueF()});
            ok = true;
            break;
        }
        case SettingKind::Number:
        case SettingKind::Integer:
            value = v.toDouble(&ok);
            break;
    }
    if (!ok || !s.problemWith(value).empty()) return {};
    return value;
}
}  // namespace

void restoreRemembered(const QSettings& settings, SessionState& state) {
    for (const Setting& s : settingTable()) {
        if (s.rememberedKey.empty() || !settings.contains(keyOf(s))) continue;
        if (const auto value = read(s, settings.value(keyOf(s)))) s.set(state, *value);
    }
}

void remember(QSettings& settings, const SessionState& state) {
    for (const Setting& s : settingTable()) {
        if (s.rememberedKey.empty()) continue;
        const double value = s.get(state);
        switch (s.kind) {
            case SettingKind::Flag:
                settings.setValue(keyOf(s), value != 0.0);
                break;
            case SettingKind::Choice:
            case SettingKind::Colour:
                settings.setValue(keyOf(s), QString::fromStdString(s.format(value)));
                break;
            case SettingKind::Number:
            case SettingKind::Integer:
                settings.setValue(keyOf(s), value);
                break;
        }
    }
}

}  // namespace ensil::session

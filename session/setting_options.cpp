#include "session/setting_options.h"

#include <QColor>
#include <QRegularExpression>
#include <cmath>

namespace ensil::session {
namespace {
QString qs(std::string_view text) {
    return QString::fromUtf8(text.data(), static_cast<qsizetype>(text.size()));
}

QString valueName(const Setting& s) {
    switch (s.kind) {
        case SettingKind::Integer:
            return QStringLiteral("N");
        case SettingKind::Choice:
            return QStringLiteral("NAME");
        case SettingKind::Colour:
            return QStringLiteral("#RRGGBB");
        case SettingKind::Number:
        case SettingKind::Flag:
            break;
    }
    return QStringLiteral("X");
}

QString refusal(const QString& name, const QString& text, const std::string& why) {
    return QStringLiteral("%1 '%2' is refused: it %3").arg(name, text, QString::fromStdString(why));
}
}  // namespace

std::optional<double> parseSettingValue(const Setting& s, const QString& text, QString& problem) {
    const QString name = QStringLiteral("--") + qs(s.option);
    const QString trimmed = text.trimmed();
    double value = std::nan("");
    switch (s.kind) {
        case SettingKind::Choice:
            for (std::size_t i = 0; i < s.choices.size(); ++i) {
                if (trimmed.compare(qs(s.choices[i]), Qt::CaseInsensitive) == 0) {
                    value = static_cast<double>(i);
                }
            }
            break;
        case SettingKind::Flag:
            if (trimmed == QLatin1String("true")) value = 1.0;
            if (trimmed == QLatin1String("false")) value = 0.0;
            break;
        case SettingKind::Colour: {
            const QColor colour(trimmed);
            if (colour.isValid()) {
                value = packColour({colour.redF(), colour.greenF(), colour.blueF()});
            }
            break;
        }
        case SettingKind::Number:
        case SettingKind::Integer: {
            bool ok = false;
            value = trimmed.toDouble(&ok);
            if (!ok) value = std::nan("");
            break;
        }
    }
    if (const std::string why = s.problemWith(value); !why.empty()) {
        problem = refusal(name, text, why);
        return std::nullopt;
    }
    return value;
}

std::optional<double> parseBoundedNumber(const QString& name, const QString& text, double minimum,
                                         double maximum, bool whole, QString& problem) {
    bool ok = false;
    const double value = text.trimmed().toDouble(&ok);
    const bool allowed = ok && std::isfinite(value) && value >= minimum && value <= maximum &&
                         (!whole || value == std::floor(value));
    if (allowed) return value;
    problem =
        refusal(name, text,
                QStringLiteral("must be %1 from %2 to %3")
                    .arg(whole ? QStringLiteral("a whole number") : QStringLiteral("a number"))
                    .arg(minimum)
                    .arg(maximum)
                    .toStdString());
    return std::nullopt;
}

std::optional<std::pair<int, int>> parseImageSize(const QString& name, const QString& text,
                                                  QString& problem) {
    static const QRegularExpression pattern(QStringLiteral("^(\\d{1,9})[xX](\\d{1,9})$"));
    const QRegularExpressionMatch match = pattern.match(text.trimmed());
    if (match.hasMatch()) {
        const int w = match.captured(1).toInt();
        const int h = match.captured(2).toInt();
        if (w >= 1 && h >= 1 && w <= kMaxImageSide && h <= kMaxImageSide) return std::pair{w, h};
    }
    problem = refusal(name, text,
                      QStringLiteral("must be WIDTHxHEIGHT in pixels, each from 1 to %1, such as "
                                     "1600x1000")
                          .arg(kMaxImageSide)
                          .toStdString());
    return std::nullopt;
}

SettingOptions::SettingOptions(std::initializer_list<std::string_view> ids) {
    for (const std::string_view id : ids) {
        const Setting& s = setting(id);
        const QString name = qs(s.option);
        const QString defaultText = QString::fromStdString(s.format(s.defaultValue()));
        if (s.kind == SettingKind::Flag) {
            m_entries.push_back(
                {&s,
                 QCommandLineOption(
                     name, QStringLiteral("%1 (the default: %2).")
                               .arg(qs(s.help), s.defaultValue() != 0.0 ? QStringLiteral("on")
                                                                        : QStringLiteral("off"))),
                 QCommandLineOption(QStringLiteral("no-") + name,
                                    QStringLiteral("The opposite of --%1.").arg(name))});
            continue;
        }
        m_entries.push_back({&s,
                             QCommandLineOption(name,
                                                QStringLiteral("%1 (default %2; %3).")
                                                    .arg(qs(s.help), defaultText,
                                                         QString::fromStdString(s.allowed())),
                                                valueName(s), defaultText),
                             std::nullopt});
    }
}

void SettingOptions::addTo(QCommandLineParser& parser) const {
    for (const Entry& e : m_entries) {
        parser.addOption(e.option);
        if (e.negation) parser.addOption(*e.negation);
    }
}

bool SettingOptions::applyTo(const QCommandLineParser& parser, SessionState& state,
                             QString& problem) const {
    for (const Entry& e : m_entries) {
        if (e.negation) {
            const bool on = parser.isSet(e.option);
            const bool off = parser.isSet(*e.negation);
            if (on && off) {
                problem = QStringLiteral("--%1 and --%2 contradict each other: give one")
                              .arg(e.option.names().front(), e.negation->names().front());
                return false;
            }
            if (on || off) e.setting->set(state, on ? 1.0 : 0.0);
            continue;
        }
        if (!parser.isSet(e.option)) continue;
        const auto value = parseSettingValue(*e.setting, parser.value(e.option), problem);
        if (!value) return false;
        e.setting->set(state, *value);
    }
    return true;
}

QStringList SettingOptions::given(const QCommandLineParser& parser) const {
    QStringList names;
    for (const Entry& e : m_entries) {
        if (parser.isSet(e.option)) names << QStringLiteral("--") + e.option.names().front();
        if (e.negation && parser.isSet(*e.negation)) {
            names << QStringLiteral("--") + e.negation->names().front();
        }
    }
    return names;
}

}  // namespace ensil::session

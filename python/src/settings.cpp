#include "python/src/settings.h"

#include <QString>
#include <cmath>

#include "python/src/errors.h"
#include "session/setting_options.h"

namespace py = pybind11;

namespace ensil::python {

const session::Setting& settingNamed(std::string_view id) {
    std::string names;
    for (const session::Setting& s : session::settingTable()) {
        if (s.id == id) return s;
        names += (names.empty() ? "" : ", ") + std::string(s.id);
    }
    throw ArgumentError("there is no setting '" + std::string(id) + "'; the settings are " + names);
}

double settingFromPython(const session::Setting& setting, const py::handle& value,
                         const std::string& argument) {
    std::string text;
    if (py::isinstance<py::bool_>(value)) {
        text = value.cast<bool>() ? "true" : "false";
    } else if (py::isinstance<py::str>(value)) {
        text = value.cast<std::string>();
    } else {
        // Numbers as Python writes them (repr keeps every digit of a float), so the parser
        // sees what was given; anything else is refused by it as not a number.
        text = py::repr(value).cast<std::string>();
    }
    QString problem;
    const auto parsed = session::parseSettingValue(setting, QString::fromStdString(text), problem);
    if (!parsed) {
        std::string message = problem.toStdString();
        // The parser names the option; Python names the argument it came as, a setting without
        // an option goes by its id.
        const std::string option = "--" + std::string(setting.option);
        if (!argument.empty() && !setting.option.empty() && message.rfind(option, 0) == 0) {
            message.replace(0, option.size(), argument);
        } else if (setting.option.empty() && message.rfind("--", 0) == 0) {
            message.replace(0, 2, setting.id);
        }
        throw ArgumentError(message);
    }
    return *parsed;
}

py::object settingToPython(const session::Setting& setting, double value) {
    switch (setting.kind) {
        case session::SettingKind::Number:
            return py::float_(value);
        case session::SettingKind::Integer:
            return py::int_(static_cast<long long>(std::llround(value)));
        case session::SettingKind::Flag:
            return py::bool_(value != 0.0);
        case session::SettingKind::Choice:
        case session::SettingKind::Colour:
            break;
    }
    return py::str(setting.format(value));
}

double boundedNumber(const char* option, double given, double minimum, double maximum) {
    QString problem;
    const auto value =
        session::parseBoundedNumber(QString::fromLatin1(option), QString::number(given, 'g', 17),
                                    minimum, maximum, false, problem);
    if (!value) throw ArgumentError(problem.toStdString());
    return *value;
}

}  // namespace ensil::python

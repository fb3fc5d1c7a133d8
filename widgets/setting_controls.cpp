#include "widgets/setting_controls.h"

#include "session/setting_table.h"

namespace ensil::ui {

QString settingHelp(std::string_view settingId) {
    const std::string_view help = session::setting(settingId).help;
    return QString::fromUtf8(help.data(), static_cast<qsizetype>(help.size()));
}

void shapeBySetting(QDoubleSpinBox& box, std::string_view settingId) {
    const session::Setting& s = session::setting(settingId);
    box.setDecimals(s.decimals);
    box.setRange(s.minimum, s.maximum);
    box.setSingleStep(s.step);
    box.setToolTip(settingHelp(settingId));
}

void shapeBySetting(QSpinBox& box, std::string_view settingId) {
    const session::Setting& s = session::setting(settingId);
    box.setRange(static_cast<int>(s.minimum), static_cast<int>(s.maximum));
    box.setSingleStep(static_cast<int>(s.step));
    box.setToolTip(settingHelp(settingId));
}

}  // namespace ensil::ui

// Panel controls shaped by the setting table: a spin box takes its setting's range, decimals,
// step, unit and tool tip from session/setting_table.h, so a panel holds exactly the
// values a project or the command line may hold. GUI thread.
#pragma once

#include <QDoubleSpinBox>
#include <QSpinBox>
#include <string_view>

namespace ensil::ui {

void shapeBySetting(QDoubleSpinBox& box, std::string_view settingId);
void shapeBySetting(QSpinBox& box, std::string_view settingId);
// The setting's help text, for tool tips.
QString settingHelp(std::string_view settingId);

}  // namespace ensil::ui

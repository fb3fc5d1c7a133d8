// Panel controls shaped by the setting table: a spin box takes its setting's range, decimals,
// step, unit and tool tip from session/setting_table.h, so a panel holds exactly the
// values a project or the command line may hold. SettingControl makes the whole control of a
// row by its kind, so a panel is a list of setting ids (a new setting is one table row plus its
// use). GUI thread.
#pragma once

#include <QColor>
#include <QDoubleSpinBox>
#include <QObject>
#include <QSpinBox>
#include <QStringList>
#include <string_view>

#include "session/setting_table.h"

namespace ensil::ui {

void shapeBySetting(QDoubleSpinBox& box, std::string_view settingId);
void shapeBySetting(QSpinBox& box, std::string_view settingId);
// The setting's help text, for tool tips.
QString settingHelp(std::string_view settingId);
// The setting's label, as panels show it.
QString settingLabel(std::string_view settingId);

// The control of one setting: a check box for a Flag (a checkable group box when `group`), a
// spin box for a Number or an Integer, a combo box for a Choice (its items `choiceLabels`, in
// the table's order; the table's names when none are given) and a colour button for a Colour.
// The widget's object name is the setting's id, the name projects and the command line use.
class SettingControl : public QObject {
    Q_OBJECT
public:
    struct Options {
        QStringList choiceLabels;
        bool group = false;  // a Flag heading a checkable group box
    };
    SettingControl(std::string_view id, QWidget* parent, Options options);
    SettingControl(std::string_view id, QWidget* parent) : SettingControl(id, parent, Options{}) {}

    [[nodiscard]] const session::Setting& setting() const { return *m_setting; }
    [[nodiscard]] QWidget* widget() const { return m_widget; }
    // Whether the widget carries its own label (a check box, a group box).
    [[nodiscard]] bool labelsItself() const;
    // Shows `value` (the setting's, as the table holds it) without emitting edited(). A Number
    // beyond the box's range widens it, so a value is shown as it is, never clamped.
    void showValue(double value);
    [[nodiscard]] double value() const;
    // Writes the control's value into `state` through the table.
    void applyTo(session::SessionState& state) const { m_setting->set(state, value()); }

signals:
    void edited();  // the user changed the value

private:
    void chooseColour();
    void showColour();

    const session::Setting* m_setting;
    QWidget* m_widget = nullptr;
    QColor m_colour;
};

}  // namespace ensil::ui

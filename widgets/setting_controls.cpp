#include "widgets/setting_controls.h"

#include <QCheckBox>
#include <QColorDialog>
#include <QComboBox>
#include <QGroupBox>
#include <QPixmap>
#include <QSignalBlocker>
#include <QToolButton>
#include <algorithm>

namespace ensil::ui {
namespace {
QString text(std::string_view s) {
    return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size()));
}
}  // namespace

QString settingHelp(std::string_view settingId) { return text(session::setting(settingId).help); }

QString settingLabel(std::string_view settingId) { return text(session::setting(settingId).label); }

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

SettingControl::SettingControl(std::string_view id, QWidget* parent, Options options)
    : QObject(parent), m_setting(&session::setting(id)) {
    const session::Setting& s = *m_setting;
    switch (s.kind) {
        case session::SettingKind::Flag:
            if (options.group) {
                auto* box = new QGroupBox(text(s.label), parent);
                box->setCheckable(true);
                connect(box, &QGroupBox::toggled, this, &SettingControl::edited);
                m_widget = box;
            } else {
                auto* box = new QCheckBox(text(s.label), parent);
                connect(box, &QCheckBox::toggled, this, &SettingControl::edited);
                m_widget = box;
            }
            break;
        case session::SettingKind::Number: {
            auto* box = new QDoubleSpinBox(parent);
            shapeBySetting(*box, id);
            connect(box, &QDoubleSpinBox::valueChanged, this, &SettingControl::edited);
            m_widget = box;
            break;
        }
        case session::SettingKind::Integer: {
            auto* box = new QSpinBox(parent);
            shapeBySetting(*box, id);
            connect(box, &QSpinBox::valueChanged, this, &SettingControl::edited);
            m_widget = box;
            break;
        }
        case session::SettingKind::Choice: {
            auto* box = new QComboBox(parent);
            for (std::size_t i = 0; i < s.choices.size(); ++i) {
                box->addItem(i < static_cast<std::size_t>(options.choiceLabels.size())
                                 ? options.choiceLabels[static_cast<qsizetype>(i)]
                                 : text(s.choices[i]));
            }
            connect(box, &QComboBox::currentIndexChanged, this, &SettingControl::edited);
            m_widget = box;
            break;
        }
        case session::SettingKind::Colour: {
            auto* button = new QToolButton(parent);
            button->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
            connect(button, &QToolButton::clicked, this, &SettingControl::chooseColour);
            m_widget = button;
            break;
        }
    }
    m_widget->setObjectName(text(id));
    m_widget->setToolTip(settingHelp(id));
    showValue(s.defaultValue());
}

bool SettingControl::labelsItself() const { return m_setting->kind == session::SettingKind::Flag; }

void SettingControl::showValue(double value) {
    const QSignalBlocker block(m_widget);
    if (auto* check = qobject_cast<QCheckBox*>(m_widget)) {
        check->setChecked(value != 0.0);
    } else if (auto* group = qobject_cast<QGroupBox*>(m_widget)) {
        group->setChecked(value != 0.0);
    } else if (auto* number = qobject_cast<QDoubleSpinBox*>(m_widget)) {
        number->setRange(std::min(number->minimum(), value), std::max(number->maximum(), value));
        number->setValue(value);
    } else if (auto* whole = qobject_cast<QSpinBox*>(m_widget)) {
        whole->setValue(static_cast<int>(value));
    } else if (auto* choice = qobject_cast<QComboBox*>(m_widget)) {
        choice->setCurrentIndex(static_cast<int>(value));
    } else {
        const glm::vec3 rgb = session::unpackColour(value);
        m_colour = QColor::fromRgbF(rgb.r, rgb.g, rgb.b);
        showColour();
    }
}

double SettingControl::value() const {
    if (auto* check = qobject_cast<QCheckBox*>(m_widget)) return check->isChecked() ? 1.0 : 0.0;
    if (auto* group = qobject_cast<QGroupBox*>(m_widget)) return group->isChecked() ? 1.0 : 0.0;
    if (auto* number = qobject_cast<QDoubleSpinBox*>(m_widget)) return number->value();
    if (auto* whole = qobject_cast<QSpinBox*>(m_widget)) return whole->value();
    if (auto* choice = qobject_cast<QComboBox*>(m_widget)) return choice->currentIndex();
    return session::packColour({static_cast<float>(m_colour.redF()),
                                static_cast<float>(m_colour.greenF()),
                                static_cast<float>(m_colour.blueF())});
}

void SettingControl::chooseColour() {
    const QColor chosen = QColorDialog::getColor(m_colour, m_widget, text(m_setting->label));
    if (!chosen.isValid() || chosen == m_colour) return;
    m_colour = chosen;
    showColour();
    emit edited();
}

void SettingControl::showColour() {
    auto* button = qobject_cast<QToolButton*>(m_widget);
    QPixmap swatch(32, 16);
    swatch.fill(m_colour);
    button->setIcon(QIcon(swatch));
    button->setIconSize(swatch.size());
    button->setText(m_colour.name());
}

}  // namespace ensil::ui

#include "widgets/section_colours_button.h"

#include <QActionGroup>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QMenu>
#include <QPushButton>
#include <tuple>

#include "data/number_text.h"
#include "session/session_model.h"
#include "session/setting_table.h"
#include "widgets/setting_controls.h"

namespace ensil::ui {

SectionColoursButton::SectionColoursButton(session::SessionModel* model,
                                           std::function<std::optional<ShownRange>()> shownRange,
                                           QWidget* parent)
    : QToolButton(parent), m_model(model), m_shownRange(std::move(shownRange)) {
    setObjectName(QStringLiteral("sectionColours"));
    setText(tr("Colours"));
    setToolTip(settingHelp("sections_colour_map"));
    setPopupMode(QToolButton::InstantPopup);
    auto* menu = new QMenu(this);
    auto* maps = new QActionGroup(menu);
    // In session::SectionsColourMap's order.
    const QStringList mapNames{tr("Automatic (by the Fill)"), tr("Viridis"), tr("Greys"),
                               tr("RdBu (Diverging)"), tr("YlGnBu")};
    for (int i = 0; i < mapNames.size(); ++i) {
        QAction* a = menu->addAction(mapNames[i]);
        a->setCheckable(true);
        a->setData(i);
        maps->addAction(a);
        connect(a, &QAction::triggered, this, [this, i] {
            m_model->update([i](session::SessionState& st) {
                st.sectionsColours.map = static_cast<session::SectionsColourMap>(i);
            });
            emit edited();
        });
    }
    menu->addSeparator();
    m_fixedRange = menu->addAction(tr("Fixed Range..."), this, [this] {
        if (m_model->state().sectionsColours.fixedRange) {
            setFixedRange(std::nullopt);
        } else {
            askFixedRange();
        }
    });
    m_fixedRange->setCheckable(true);
    setMenu(menu);
    showSession();
}

void SectionColoursButton::showSession() {
    const session::SectionsColours& colours = m_model->state().sectionsColours;
    for (QAction* a : menu()->actions()) {
        if (a->isCheckable() && a != m_fixedRange) {
            a->setChecked(a->data().toInt() == static_cast<int>(colours.map));
        }
    }
    m_fixedRange->setChecked(colours.fixedRange);
    m_fixedRange->setText(
        colours.fixedRange
            ? tr("Fixed Range %1 to %2 (Click for Automatic)")
                  .arg(QString::fromStdString(data::readableNumber(colours.minimum, 6)),
                       QString::fromStdString(data::readableNumber(colours.maximum, 6)))
            : tr("Fixed Range..."));
}

void SectionColoursButton::setFixedRange(std::optional<std::pair<double, double>> range) {
    m_model->update([&range](session::SessionState& st) {
        st.sectionsColours.fixedRange = range.has_value();
        if (range) std::tie(st.sectionsColours.minimum, st.sectionsColours.maximum) = *range;
    });
    emit edited();
}

// Asks for the range, starting from the one the sections show now.
void SectionColoursButton::askFixedRange() {
    const std::optional<ShownRange> shown = m_shownRange ? m_shownRange() : std::nullopt;
    const session::SectionsColours& colours = m_model->state().sectionsColours;
    QDialog dialog(this);
    dialog.setWindowTitle(tr("Fixed Colour Range"));
    auto* form = new QFormLayout(&dialog);
    const auto spin = [&](const char* id, double value) {
        auto* box = new QDoubleSpinBox(&dialog);
        shapeBySetting(*box, id);
        box->setValue(value);
        if (shown && !shown->units.isEmpty()) box->setSuffix(QLatin1Char(' ') + shown->units);
        form->addRow(settingLabel(id), box);
        return box;
    };
    QDoubleSpinBox* from = spin("sections_range_min", shown ? shown->minimum : colours.minimum);
    QDoubleSpinBox* to = spin("sections_range_max", shown ? shown->maximum : colours.maximum);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, &dialog);
    form->addRow(buttons);
    const auto checkOrder = [&] {
        buttons->button(QDialogButtonBox::Ok)->setEnabled(from->value() < to->value());
    };
    connect(from, &QDoubleSpinBox::valueChanged, &dialog, checkOrder);
    connect(to, &QDoubleSpinBox::valueChanged, &dialog, checkOrder);
    connect(buttons, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
    checkOrder();
    if (dialog.exec() == QDialog::Accepted) {
        setFixedRange(std::pair{from->value(), to->value()});
    } else {
        showSession();  // the action's check mark back as the session has it
    }
}

}  // namespace ensil::ui

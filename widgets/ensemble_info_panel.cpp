#include "widgets/ensemble_info_panel.h"

#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QVBoxLayout>

namespace ensil::ui {

EnsembleInfoPanel::EnsembleInfoPanel(QWidget* parent)
    : QWidget(parent), m_message(new QLabel(this)), m_form(new QFormLayout) {
    auto* layout = new QVBoxLayout(this);
    m_message->setWordWrap(true);
    // Wide enough for axis descriptions without wrapping every line, whatever is shown now.
    setMinimumWidth(280);
    layout->addWidget(m_message);
    layout->addLayout(m_form);
    layout->addStretch(1);
    m_form->setLabelAlignment(Qt::AlignRight);
}

void EnsembleInfoPanel::showMessage(const QString& message) {
    while (m_form->rowCount() > 0) m_form->removeRow(0);
    m_variableChoice = nullptr;  // deleted with its row
    m_showingFacts = false;
    m_message->setText(message);
    m_message->setVisible(true);
}

void EnsembleInfoPanel::showFacts(const engine::EnsembleFacts& facts) {
    m_facts = facts;
    showRows();
}

void EnsembleInfoPanel::setVariableChoices(const QStringList& names) {
    m_variables = names;
    if (m_showingFacts) showRows();
}

void EnsembleInfoPanel::showRows() {
    const engine::EnsembleFacts& facts = m_facts;
    showMessage(QString());
    m_message->setVisible(false);
    m_showingFacts = true;
    const auto row = [this](const QString& label, const QString& value) {
        auto* field = new QLabel(value, this);
        field->setTextInteractionFlags(Qt::TextSelectableByMouse);
        field->setWordWrap(true);
        m_form->addRow(label, field);
    };
    row(tr("Source"), facts.source);
    if (m_variables.size() >= 2 && m_variables.contains(facts.variableName)) {
        m_variableChoice = new QComboBox(this);
        // Each item's data is the variable's name; the one shown reads as the facts say it,
        // with its long name.
        for (const QString& name : m_variables) {
            m_variableChoice->addItem(name == facts.variableName ? facts.variable : name, name);
        }
        m_variableChoice->setCurrentIndex(m_variableChoice->findData(facts.variableName));
        m_variableChoice->setToolTip(tr("Another variable of the files opens in its place."));
        // Only a user's pick: filling the list says nothing.
        connect(m_variableChoice, &QComboBox::activated, this, [this](int index) {
            const QString name = m_variableChoice->itemData(index).toString();
            if (name != m_facts.variableName) emit variableChosen(name);
        });
        m_form->addRow(tr("&Variable"), m_variableChoice);
    } else {
        row(tr("Variable"), facts.variable);
    }
    row(tr("Units"), facts.units);
    row(tr("Members"), tr("%1 (dimension '%2')").arg(facts.members).arg(facts.memberDimension));
    row(tr("Grid"), facts.gridSize);
    for (const QString& axis : facts.axes) row(tr("Axis"), axis);
    row(tr("Values"), facts.valueRange);
    row(tr("Missing"), QString::number(facts.missing));
    row(tr("Memory"), tr("%1 MiB").arg(facts.megabytes, 0, 'f', 1));
    if (!facts.warning.isEmpty()) row(tr("Note"), facts.warning);
}

QString EnsembleInfoPanel::text() const {
    QStringList lines;
    if (m_message->isVisibleTo(this) && !m_message->text().isEmpty()) lines << m_message->text();
    for (int r = 0; r < m_form->rowCount(); ++r) {
        auto* label = m_form->itemAt(r, QFormLayout::LabelRole);
        auto* field = m_form->itemAt(r, QFormLayout::FieldRole);
        const auto textOf = [](QLayoutItem* item) {
            if (item == nullptr) return QString();
            if (auto* box = qobject_cast<QComboBox*>(item->widget())) return box->currentText();
            return qobject_cast<QLabel*>(item->widget())->text();
        };
        const QString labelText = textOf(label).remove(QLatin1Char('&'));  // a shortcut's mark
        const QString fieldText = textOf(field);
        lines << labelText + QStringLiteral(": ") + fieldText;
    }
    return lines.join(QLatin1Char('\n'));
}

}  // namespace ensil::ui

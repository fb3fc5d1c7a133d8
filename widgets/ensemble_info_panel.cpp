#include "widgets/ensemble_info_panel.h"

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
    m_message->setText(message);
    m_message->setVisible(true);
}

void EnsembleInfoPanel::showFacts(const engine::EnsembleFacts& facts) {
    showMessage(QString());
    m_message->setVisible(false);
    const auto row = [this](const QString& label, const QString& value) {
        auto* field = new QLabel(value, this);
        field->setTextInteractionFlags(Qt::TextSelectableByMouse);
        field->setWordWrap(true);
        m_form->addRow(label, field);
    };
    row(tr("Source"), facts.source);
    row(tr("Variable"), facts.variable);
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
        const auto labelText = label ? qobject_cast<QLabel*>(label->widget())->text() : QString();
        const auto fieldText = field ? qobject_cast<QLabel*>(field->widget())->text() : QString();
        lines << labelText + QStringLiteral(": ") + fieldText;
    }
    return lines.join(QLatin1Char('\n'));
}

}  // namespace ensil::ui

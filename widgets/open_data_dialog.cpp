#include "widgets/open_data_dialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QTreeWidget>
#include <QVBoxLayout>
#include <algorithm>

#include "data/error.h"
#include "data/level_range.h"
#include "data/region.h"

namespace ensil::ui {
namespace {
enum Column { kName, kDimensions, kUnits, kDescription, kColumns };

QString filesText(const QStringList& paths) {
    if (paths.size() == 1) return QFileInfo(paths.front()).fileName();
    return QObject::tr("%1 files in %2 (one member per file, or members in each file)")
        .arg(paths.size())
        .arg(QFileInfo(paths.front()).absolutePath());
}
}  // namespace

OpenDataDialog::OpenDataDialog(QStringList paths, QWidget* parent)
    : QDialog(parent),
      m_paths(std::move(paths)),
      m_variables(new QTreeWidget(this)),
      m_memberDimension(new QComboBox(this)),
      m_timeIndex(new QSpinBox(this)),
      m_levels(new QLineEdit(this)),
      m_region(new QLineEdit(this)),
      m_details(new QLabel(this)),
      m_error(new QLabel(this)),
      m_buttons(new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this)) {
    setObjectName(QStringLiteral("openDataDialog"));
    setWindowTitle(tr("Open Ensemble Data"));
    resize(760, 460);

    m_variables->setColumnCount(kColumns);
    m_variables->setHeaderLabels(
        {tr("Variable"), tr("Dimensions"), tr("Units"), tr("Description")});
    m_variables->setRootIsDecorated(false);
    m_variables->setAllColumnsShowFocus(true);
    m_variables->header()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_variables->header()->setStretchLastSection(true);
    m_memberDimension->setToolTip(
        tr("The dimension whose indices are the ensemble members. ensil finds it from the "
           "file's metadata; choose another one (forecast times, months) to use it instead."));
    m_timeIndex->setKeyboardTracking(false);
    m_timeIndex->setToolTip(
        tr("Index taken along every other non-spatial dimension, such as time"));
    m_levels->setObjectName(QStringLiteral("openDataLevels"));
    m_levels->setPlaceholderText(tr("every level; or e.g. 1000:100hPa, 0:12km"));
    m_levels->setClearButtonEnabled(true);
    m_levels->setToolTip(
        tr("Keep only the vertical levels between two values, ends included, in any units "
           "that convert to the vertical axis's (hPa, Pa, millibars, km, m), or in its own "
           "units without any: the troposphere of a box reaching 10 hPa, say."));
    m_region->setObjectName(QStringLiteral("openDataRegion"));
    m_region->setPlaceholderText(tr("the whole grid; or LON0,LON1,LAT0,LAT1, e.g. -10,40,35,72"));
    m_region->setClearButtonEnabled(true);
    m_region->setToolTip(
        tr("Keep only the grid columns and rows within these longitudes and latitudes, in "
           "degrees, edges included: -10,40,35,72 is Europe. LON0 greater than LON1 crosses the "
           "date line or the 0/360 seam (350,20,35,70). Needs a regular longitude-latitude "
           "grid; the file is read only there."));
    m_details->setObjectName(QStringLiteral("openDataDetails"));
    m_details->setWordWrap(true);
    m_details->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_error->setObjectName(QStringLiteral("openDataError"));
    m_error->setWordWrap(true);
    m_error->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_error->setStyleSheet(QStringLiteral("color: #b00020;"));
    m_error->setVisible(false);

    auto* form = new QFormLayout;
    form->addRow(tr("Member dimension:"), m_memberDimension);
    form->addRow(tr("Time index:"), m_timeIndex);
    form->addRow(tr("&Levels:"), m_levels);
    form->addRow(tr("&Region:"), m_region);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(new QLabel(filesText(m_paths), this));
    layout->addWidget(m_variables, 1);
    layout->addLayout(form);
    layout->addWidget(m_details);
    layout->addWidget(m_error);
    layout->addWidget(m_buttons);

    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_variables, &QTreeWidget::currentItemChanged, this, [this](QTreeWidgetItem* item) {
        if (item == nullptr || item->text(kName) == m_variable) return;
        m_variable = item->text(kName);
        requestProbe();
    });
    connect(m_memberDimension, &QComboBox::currentIndexChanged, this, [this] { requestProbe(); });
    connect(m_timeIndex, &QSpinBox::valueChanged, this, [this] { requestProbe(); });
    connect(m_levels, &QLineEdit::editingFinished, this, [this] { requestProbe(); });
    connect(m_region, &QLineEdit::editingFinished, this, [this] { requestProbe(); });
    setProbing(false);
}

data::DataSelection OpenDataDialog::selection() const {
    data::DataSelection s;
    for (const QString& p : m_paths) s.paths.push_back(p.toStdString());
    s.variable = m_variable.toStdString();
    s.memberDimension = m_memberDimension->currentData().toString().toStdString();
    s.timeIndex = static_cast<std::size_t>(std::max(0, m_timeIndex->value()));
    if (const QString levels = m_levels->text().trimmed(); !levels.isEmpty()) {
        try {
            s.levels = data::parseLevelRange(levels.toStdString());
        } catch (const data::Error&) {
            // levelsError() says why; the dialog cannot be accepted meanwhile.
        }
    }
    if (const QString region = m_region->text().trimmed(); !region.isEmpty()) {
        try {
            s.region = data::parseRegion(region.toStdString());
        } catch (const data::Error&) {
            // regionError() says why; the dialog cannot be accepted meanwhile.
        }
    }
    return s;
}

namespace {
// What `parse` (data::parseLevelRange, data::parseRegion) says of a field's text; empty when the
// text is empty (the whole file) or parses.
template <typename Parse>
QString parseError(const QLineEdit& field, Parse parse) {
    const QString text = field.text().trimmed();
    if (text.isEmpty()) return {};
    try {
        (void)parse(text.toStdString());
    } catch (const data::Error& e) {
        return QString::fromUtf8(e.what());
    }
    return {};
}
}  // namespace

QString OpenDataDialog::levelsError() const { return parseError(*m_levels, data::parseLevelRange); }

QString OpenDataDialog::regionError() const { return parseError(*m_region, data::parseRegion); }

void OpenDataDialog::requestProbe() {
    // A level range or region that does not parse is said at once; the headers are read for
    // the rest.
    QString why = levelsError();
    if (why.isEmpty()) why = regionError();
    if (!why.isEmpty()) {
        ++m_request;  // an answer on its way is for other choices
        m_error->setText(why);
        m_error->setVisible(true);
        setProbing(false);
        return;
    }
    setProbing(true);
    emit probeRequested(selection(), ++m_request);
}

void OpenDataDialog::showProbe(const engine::DataProbe& probe, int request) {
    if (request != m_request) return;  // the user changed a choice meanwhile
    m_variable = probe.variable;
    fillVariables(probe);
    fillMemberDimensions(probe);
    fillDetails(probe);
    m_error->setText(probe.error);
    m_error->setVisible(!probe.error.isEmpty());
    setProbing(false);
    emit probeShown();
}

void OpenDataDialog::fillVariables(const engine::DataProbe& probe) {
    const QSignalBlocker block(m_variables);
    m_variables->clear();
    m_usableVariable = false;
    for (const engine::ProbedVariable& v : probe.variables) {
        QString description = v.longName;
        if (!v.usable) {
            description += (description.isEmpty() ? QString() : QStringLiteral(" - ")) +
                           tr("not usable: %1").arg(v.whyNotUsable);
        }
        auto* item = new QTreeWidgetItem(m_variables, {v.name, v.dimensions, v.units, description});
        item->setToolTip(kDescription, description);
        if (!v.usable) {
            item->setFlags(item->flags() & ~(Qt::ItemIsEnabled | Qt::ItemIsSelectable));
        }
        if (v.name == probe.variable) {
            m_variables->setCurrentItem(item);
            m_usableVariable = v.usable;
        }
    }
}

void OpenDataDialog::fillMemberDimensions(const engine::DataProbe& probe) {
    const QSignalBlocker block(m_memberDimension);
    const QString requested = m_memberDimension->currentData().toString();
    m_memberDimension->clear();
    // The first entry lets the reader decide; its label says what it decided.
    QString automatic;
    if (!requested.isEmpty()) {
        automatic = tr("Automatic");
    } else if (!probe.memberDimension.isEmpty()) {
        automatic = tr("%1 (found: %2)").arg(probe.memberDimension, probe.memberDimensionReason);
    } else if (m_paths.size() > 1) {
        automatic = tr("One member per file");
    } else {
        automatic = tr("Choose the dimension that holds the members...");
    }
    m_memberDimension->addItem(automatic, QString());
    for (const QString& choice : probe.memberDimensionChoices) {
        if (requested.isEmpty() && choice == probe.memberDimension) continue;
        m_memberDimension->addItem(choice, choice);
    }
    m_memberDimension->setCurrentIndex(std::max(0, m_memberDimension->findData(requested)));
}

void OpenDataDialog::fillDetails(const engine::DataProbe& probe) {
    {
        const QSignalBlocker block(m_timeIndex);
        m_timeIndex->setRange(0, std::max(0, probe.timeSteps - 1));
        m_timeIndex->setEnabled(probe.timeSteps > 1);
    }
    if (probe.members == 0) {
        m_details->setText(probe.format);
        return;
    }
    QStringList lines;
    lines << tr("%1: %2 members of %3 on a %4 grid")
                 .arg(probe.format)
                 .arg(probe.members)
                 .arg(probe.variable, probe.grid);
    if (!probe.levels.isEmpty()) lines << tr("Levels: %1").arg(probe.levels);
    if (!probe.region.isEmpty()) lines << tr("Region: %1").arg(probe.region);
    for (const QString& fixed : probe.fixedDimensions) lines << tr("Fixed: %1").arg(fixed);
    if (!probe.size.isEmpty()) lines << tr("Size: %1").arg(probe.size);
    m_details->setText(lines.join(QLatin1Char('\n')));
}

void OpenDataDialog::setProbing(bool probing) {
    m_probing = probing;
    if (probing) m_details->setText(tr("Reading the file headers..."));
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(canAccept());
}

QString OpenDataDialog::errorText() const { return m_error->text(); }

bool OpenDataDialog::canAccept() const {
    return !m_probing && m_error->text().isEmpty() && m_usableVariable && levelsError().isEmpty() &&
           regionError().isEmpty();
}

}  // namespace ensil::ui

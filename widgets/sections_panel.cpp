#include "widgets/sections_panel.h"

#include <QComboBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMessageBox>
#include <QSettings>
#include <QSplitter>
#include <QToolButton>
#include <QVBoxLayout>
#include <cmath>

#include "data/error.h"
#include "engine/section_painter.h"
#include "engine/section_place.h"
#include "gl/view_overlay.h"
#include "widgets/section_canvas.h"
#include "workbench/member_selection.h"

namespace ensil::ui {
namespace {

constexpr int kExportWidth = 1400;

enum CrossKind { AlongLatitude, AlongLongitude, AlongPath };

QString levelText(const engine::SectionPlace& place) {
    if (place.levelUnits == "index") return QStringLiteral("index:%1").arg(place.level);
    return gl::formatTick(place.level) +
           (place.levelUnits.empty() ? QString()
                                     : QLatin1Char(' ') + QString::fromStdString(place.levelUnits));
}

QString pathText(const engine::SectionPlace& place) {
    const auto n = [](double v) { return gl::formatTick(std::round(v * 100.0) / 100.0); };
    return QStringLiteral("%1,%2:%3,%4")
        .arg(n(place.from.x), n(place.from.y), n(place.to.x), n(place.to.y));
}

// The selection's first member, else -1.
int firstSelected(const workbench::MemberSelection& selection) {
    const QList<int> selected = selection.selectedMembers();
    return selected.isEmpty() ? -1 : selected.front();
}

}  // namespace

SectionsPanel::SectionsPanel(workbench::MemberSelection* selection, QWidget* parent)
    : QWidget(parent), m_selection(selection) {
    m_level = new QLineEdit(this);
    m_level->setObjectName(QStringLiteral("sectionLevel"));
    m_level->setPlaceholderText(tr("500 hPa"));
    m_level->setToolTip(
        tr("The map's level: 500 hPa, 5 km, 1500 m, index:3 or a number in the "
           "vertical axis's units"));
    m_crossKind = new QComboBox(this);
    m_crossKind->addItem(tr("along latitude"));
    m_crossKind->addItem(tr("along longitude"));
    m_crossKind->addItem(tr("along path"));
    m_cross = new QLineEdit(this);
    m_cross->setObjectName(QStringLiteral("sectionCrossPlace"));
    m_cross->setToolTip(
        tr("A latitude (45N, 30S), a longitude (10E, 75W), or a path between two "
           "points as LON,LAT:LON,LAT (-10,50:20,40)"));
    m_fill = new QComboBox(this);
    m_fill->setObjectName(QStringLiteral("sectionFill"));
    m_fill->addItem(tr("Mean"), static_cast<int>(engine::SectionFill::Mean));
    m_fill->addItem(tr("Spread (standard deviation)"),
                    static_cast<int>(engine::SectionFill::Spread));
    m_fill->addItem(tr("Probability above the isovalue"),
                    static_cast<int>(engine::SectionFill::Probability));
    m_fill->addItem(tr("Selected member"), static_cast<int>(engine::SectionFill::Member));
    m_fill->addItem(tr("Selected member minus the mean"),
                    static_cast<int>(engine::SectionFill::Anomaly));
    m_fill->addItem(tr("None"), static_cast<int>(engine::SectionFill::None));
    m_fill->setCurrentIndex(QSettings().value(QStringLiteral("sections/fill"), 0).toInt());
    m_export = new QToolButton(this);
    m_export->setText(tr("Export"));
    m_export->setPopupMode(QToolButton::InstantPopup);
    auto* exportMenu = new QMenu(m_export);
    exportMenu->addAction(tr("Map as Figure..."), this, [this] { exportWithDialog(true); });
    exportMenu->addAction(tr("Cross-Section as Figure..."), this,
                          [this] { exportWithDialog(false); });
    m_export->setMenu(exportMenu);
    m_hint = new QLabel(this);
    m_hint->setWordWrap(true);
    m_hint->hide();

    // Two short rows, and combo boxes that do not grow to their longest entry: the dock must not
    // widen the window beneath the user's size.
    m_fill->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_fill->setMinimumContentsLength(12);
    m_crossKind->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_crossKind->setMinimumContentsLength(10);
    for (QLineEdit* edit : {m_level, m_cross}) edit->setMinimumWidth(60);
    auto* mapRow = new QHBoxLayout;
    mapRow->addWidget(new QLabel(tr("Map at"), this));
    mapRow->addWidget(m_level, 1);
    mapRow->addWidget(new QLabel(tr("Fill"), this));
    mapRow->addWidget(m_fill, 1);
    mapRow->addWidget(m_export);
    auto* crossRow = new QHBoxLayout;
    crossRow->addWidget(new QLabel(tr("Cross-section"), this));
    crossRow->addWidget(m_crossKind);
    crossRow->addWidget(m_cross, 1);
    m_mapCanvas = new SectionCanvas(this);
    m_crossCanvas = new SectionCanvas(this);
    for (SectionCanvas* canvas : {m_mapCanvas, m_crossCanvas}) {
        canvas->setMessage(tr("Open data to see its sections"));
        connect(canvas, &SectionCanvas::memberClicked, this,
                [this](int member, Qt::KeyboardModifiers modifiers) {
                    m_selection->click(member < 0 ? QList<int>{} : QList<int>{member}, modifiers);
                });
        connect(canvas, &SectionCanvas::memberHovered, m_selection,
                &workbench::MemberSelection::setHovered);
    }
    m_splitter = new QSplitter(this);
    m_splitter->addWidget(m_mapCanvas);
    m_splitter->addWidget(m_crossCanvas);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(mapRow);
    layout->addLayout(crossRow);
    layout->addWidget(m_hint);
    layout->addWidget(m_splitter, 1);

    connect(m_level, &QLineEdit::editingFinished, this, [this] { build(true); });
    connect(m_cross, &QLineEdit::editingFinished, this, [this] { build(false); });
    connect(m_crossKind, &QComboBox::activated, this, [this](int kind) {
        // A place of the new kind: the middle of the data, which the user then edits.
        m_cross->setText(kind == AlongLatitude    ? QStringLiteral("45N")
                         : kind == AlongLongitude ? QStringLiteral("0E")
                                                  : m_cross->text());
        build(false);
    });
    connect(m_fill, &QComboBox::currentIndexChanged, this, [this](int index) {
        QSettings().setValue(QStringLiteral("sections/fill"), index);
        rebuild();
    });
    connect(m_selection, &workbench::MemberSelection::selectionChanged, this, [this] {
        showEmphasis();
        // A member's fill follows the selection.
        const auto fill = static_cast<engine::SectionFill>(m_fill->currentData().toInt());
        if (fill == engine::SectionFill::Member || fill == engine::SectionFill::Anomaly) rebuild();
    });
    for (auto signal : {&workbench::MemberSelection::visibilityChanged,
                        &workbench::MemberSelection::membersReset}) {
        connect(m_selection, signal, this, &SectionsPanel::showEmphasis);
    }
    connect(m_selection, &workbench::MemberSelection::hoverChanged, this,
            &SectionsPanel::showEmphasis);
    connect(m_selection, &workbench::MemberSelection::clustersChanged, this,
            &SectionsPanel::recolour);
}

SectionsPanel::~SectionsPanel() = default;

void SectionsPanel::showData(std::shared_ptr<const data::Ensemble> ensemble, float isovalue) {
    if (!ensemble) return;
    const bool sameKind = m_ensemble && m_ensemble->variable == ensemble->variable &&
                          m_ensemble->grid.sameShapeAndCoordinates(ensemble->grid);
    if (ensemble == m_ensemble && isovalue == m_isovalue) return;
    m_ensemble = std::move(ensemble);
    m_isovalue = isovalue;
    if (!sameKind) m_placesChosen = false;
    rebuild();
}

void SectionsPanel::rebuild() {
    if (!m_ensemble) return;
    if (!isVisible()) {
        m_dirty = true;
        return;
    }
    m_dirty = false;
    if (!m_placesChosen) {
        // Where the members' contours are: found in the background, then both sections built.
        const auto ensemble = m_ensemble;
        const float isovalue = m_isovalue;
        m_defaultsJob.start(
            [ensemble, isovalue](const std::stop_token&, const data::Progress&) {
                return engine::defaultSections(*ensemble, isovalue);
            },
            [this](engine::DefaultSections defaults) {
                m_placesChosen = true;
                m_level->setText(levelText(defaults.map));
                const engine::SectionPlace& cross = defaults.crossSection;
                m_crossKind->setCurrentIndex(
                    cross.kind == engine::SectionKind::Latitude    ? AlongLatitude
                    : cross.kind == engine::SectionKind::Longitude ? AlongLongitude
                                                                   : AlongPath);
                m_cross->setText(
                    cross.kind == engine::SectionKind::Latitude
                        ? QString::fromStdString(engine::degreesText(cross.latitude, true))
                    : cross.kind == engine::SectionKind::Longitude
                        ? QString::fromStdString(engine::degreesText(cross.longitude, false))
                        : pathText(cross));
                rebuild();
            },
            [](const std::exception_ptr&, bool) {});
        return;
    }
    build(true);
    build(false);
}

engine::SectionRequest SectionsPanel::request(bool map, QString* problem) const {
    engine::SectionRequest r;
    std::string why;
    std::optional<engine::SectionPlace> place;
    const std::string text = (map ? m_level : m_cross)->text().toStdString();
    if (map) {
        place = engine::parseLevel(text, why);
    } else if (m_crossKind->currentIndex() == AlongLatitude) {
        place = engine::parseLatitude(text, why);
    } else if (m_crossKind->currentIndex() == AlongLongitude) {
        place = engine::parseLongitude(text, why);
    } else {
        place = engine::parsePath(text, why);
    }
    if (!place) {
        *problem = QString::fromStdString(why);
        return r;
    }
    r.place = *place;
    r.isovalue = m_isovalue;
    r.fill = static_cast<engine::SectionFill>(m_fill->currentData().toInt());
    if (r.fill == engine::SectionFill::Member || r.fill == engine::SectionFill::Anomaly) {
        r.member = firstSelected(*m_selection);
        if (r.member < 0) r.fill = engine::SectionFill::None;
    }
    for (const gl::MemberAppearance& look : m_selection->appearance()) {
        r.memberColours.push_back(look.color);
    }
    r.clusterNumbers = m_selection->memberClusterNumbers();
    return r;
}

void SectionsPanel::build(bool map) {
    if (!m_ensemble || !m_placesChosen) return;
    if (!isVisible()) {
        m_dirty = true;
        return;
    }
    SectionCanvas* canvas = map ? m_mapCanvas : m_crossCanvas;
    QLineEdit* edit = map ? m_level : m_cross;
    QString problem;
    engine::SectionRequest r = request(map, &problem);
    edit->setStyleSheet(problem.isEmpty() ? QString() : QStringLiteral("color: #c0392b"));
    if (!problem.isEmpty()) {
        canvas->setMessage(problem);
        emit sectionBuilt();
        return;
    }
    const auto fill = static_cast<engine::SectionFill>(m_fill->currentData().toInt());
    const bool wantsMember =
        fill == engine::SectionFill::Member || fill == engine::SectionFill::Anomaly;
    m_hint->setVisible(wantsMember && r.member < 0);
    m_hint->setText(tr("Select a member (click its contour) to fill the sections with it."));
    const auto ensemble = m_ensemble;
    auto& job = map ? m_mapJob : m_crossJob;
    job.start([ensemble, r](const std::stop_token&,
                            const data::Progress&) { return engine::buildSection(*ensemble, r); },
              [this, canvas](engine::SectionView view) {
                  canvas->setView(std::make_shared<const engine::SectionView>(std::move(view)));
                  showEmphasis();
                  emit sectionBuilt();
              },
              [this, canvas](const std::exception_ptr& error, bool cancelled) {
                  if (cancelled || !error) return;
                  try {
                      std::rethrow_exception(error);
                  } catch (const std::exception& e) {
                      canvas->setMessage(QString::fromUtf8(e.what()));
                  }
                  emit sectionBuilt();
              });
}

void SectionsPanel::showEmphasis() {
    engine::SectionEmphasis emphasis;
    for (const int m : m_selection->selectedMembers()) {
        emphasis.selected.push_back(static_cast<std::size_t>(m));
    }
    emphasis.hovered = m_selection->hovered();
    for (int m = 0; m < m_selection->memberCount(); ++m) {
        emphasis.hidden.push_back(!m_selection->isMemberVisible(m));
    }
    m_mapCanvas->setEmphasis(emphasis);
    m_crossCanvas->setEmphasis(std::move(emphasis));
}

void SectionsPanel::recolour() {
    std::vector<glm::vec3> colours;
    for (const gl::MemberAppearance& look : m_selection->appearance())
        colours.push_back(look.color);
    const std::vector<int> numbers = m_selection->memberClusterNumbers();
    for (SectionCanvas* canvas : {m_mapCanvas, m_crossCanvas}) {
        if (canvas->view() == nullptr) continue;
        auto view = std::make_shared<engine::SectionView>(*canvas->view());
        engine::colourSection(*view, colours, numbers);
        canvas->setView(std::move(view));
    }
}

bool SectionsPanel::exportSection(bool map, const QString& path, QString* error) {
    const SectionCanvas* canvas = map ? m_mapCanvas : m_crossCanvas;
    if (canvas->view() == nullptr) {
        *error = canvas->message().isEmpty() ? tr("There is no section to export yet.")
                                             : canvas->message();
        return false;
    }
    try {
        engine::writeSectionPicture(*canvas->view(), path,
                                    engine::sectionPictureSize(*canvas->view(), kExportWidth));
    } catch (const data::Error& e) {
        *error = QString::fromUtf8(e.what());
        return false;
    }
    return true;
}

void SectionsPanel::exportWithDialog(bool map) {
    QSettings settings;
    const QString folder = settings.value(QStringLiteral("sections/exportFolder")).toString();
    const QString name = map ? QStringLiteral("map.svg") : QStringLiteral("cross-section.svg");
    const QString path = QFileDialog::getSaveFileName(
        this, map ? tr("Export Map") : tr("Export Cross-Section"),
        folder.isEmpty() ? name : folder + QLatin1Char('/') + name,
        tr("SVG figures (*.svg);;PNG images (*.png);;PDF documents (*.pdf)"));
    if (path.isEmpty()) return;
    settings.setValue(QStringLiteral("sections/exportFolder"), QFileInfo(path).absolutePath());
    QString error;
    if (!exportSection(map, path, &error)) {
        QMessageBox::warning(this, tr("Section not exported"), error);
    }
}

void SectionsPanel::showEvent(QShowEvent* event) {
    QWidget::showEvent(event);
    if (m_dirty) rebuild();
}

void SectionsPanel::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    // Side by side in a wide dock (below the view), one above the other in a tall one.
    m_splitter->setOrientation(width() > 1.6 * height() ? Qt::Horizontal : Qt::Vertical);
}

}  // namespace ensil::ui

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
#include <QSignalBlocker>
#include <QSplitter>
#include <QToolButton>
#include <QVBoxLayout>
#include <cmath>

#include "data/error.h"
#include "engine/section_painter.h"
#include "engine/section_place.h"
#include "geo/map_projection.h"
#include "gl/view_overlay.h"
#include "preprocessing/inclusion_depth.h"
#include "session/session_model.h"
#include "widgets/section_canvas.h"
#include "widgets/section_colours_button.h"
#include "workbench/member_selection.h"

namespace ensil::ui {
namespace {

constexpr int kExportWidth = 1400;

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

// A cross-section's place as the edit shows it.
QString crossText(const engine::SectionPlace& place) {
    switch (place.kind) {
        case engine::SectionKind::Latitude:
            return QString::fromStdString(engine::degreesText(place.latitude, true));
        case engine::SectionKind::Longitude:
            return QString::fromStdString(engine::degreesText(place.longitude, false));
        default:
            return pathText(place);
    }
}

session::SectionPlaces::Cross crossKindOf(const engine::SectionPlace& place) {
    return place.kind == engine::SectionKind::Latitude    ? session::SectionPlaces::Cross::Latitude
           : place.kind == engine::SectionKind::Longitude ? session::SectionPlaces::Cross::Longitude
                                                          : session::SectionPlaces::Cross::Path;
}

// The contour boxplot of the isovalue on screen, from the members' depths; nullopt until they
// are known.
std::optional<engine::SectionBoxplot> boxplotOf(const workbench::MemberSelection& selection) {
    if (selection.medianMember() < 0) return std::nullopt;
    std::vector<double> depths;
    engine::SectionBoxplot boxplot;
    for (int m = 0; m < selection.memberCount(); ++m) {
        depths.push_back(selection.depth(m));
        if (std::isnan(depths.back())) return std::nullopt;
        if (selection.isOutlier(m)) boxplot.outliers.push_back(static_cast<std::size_t>(m));
    }
    boxplot.bandMembers = prep::bandMembersOf(depths);
    boxplot.median = selection.medianMember();
    return boxplot;
}

engine::SectionFill engineFill(session::SectionsFill fill) {
    switch (fill) {
        case session::SectionsFill::Mean:
            return engine::SectionFill::Mean;
        case session::SectionsFill::Spread:
            return engine::SectionFill::Spread;
        case session::SectionsFill::Probability:
            return engine::SectionFill::Probability;
        case session::SectionsFill::SelectedMember:
            return engine::SectionFill::Member;
        case session::SectionsFill::SelectedAnomaly:
            return engine::SectionFill::Anomaly;
        case session::SectionsFill::None:
            break;
    }
    return engine::SectionFill::None;
}

// Each member's colour as the 3D view draws it.
std::vector<glm::vec3> memberColours(const workbench::MemberSelection& selection) {
    std::vector<glm::vec3> colours;
    for (const gl::MemberAppearance& look : selection.appearance()) colours.push_back(look.color);
    return colours;
}

// The selection's first member, else -1.
int firstSelected(const workbench::MemberSelection& selection) {
    const QList<int> selected = selection.selectedMembers();
    return selected.isEmpty() ? -1 : selected.front();
}

}  // namespace

SectionsPanel::SectionsPanel(session::SessionModel* model, workbench::MemberSelection* selection,
                             QWidget* parent)
    : QWidget(parent), m_model(model), m_selection(selection) {
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
    // In session::SectionsFill's order.
    m_fill->addItems({tr("Mean"), tr("Spread (standard deviation)"),
                      tr("Probability above the isovalue"), tr("Selected member"),
                      tr("Selected member minus the mean"), tr("None")});
    // The fill's colour map and range, started from the range the map (or the cross-section)
    // shows.
    m_colours = new SectionColoursButton(
        model,
        [this]() -> std::optional<SectionColoursButton::ShownRange> {
            for (const SectionCanvas* canvas : {m_mapCanvas, m_crossCanvas}) {
                const engine::SectionView* view = canvas->view();
                if (view == nullptr || view->fill.empty()) continue;
                return SectionColoursButton::ShownRange{view->fillMinimum, view->fillMaximum,
                                                        QString::fromStdString(view->units)};
            }
            return std::nullopt;
        },
        this);
    connect(m_colours, &SectionColoursButton::edited, this, &SectionsPanel::placesEdited);
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
    mapRow->addWidget(m_colours);
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
    // A drag with the right button across the map places the cross-section along it.
    m_mapCanvas->setDrawsPaths(true);
    m_mapCanvas->setToolTip(tr("Drag with the right button to draw the cross-section's path"));
    connect(m_mapCanvas, &SectionCanvas::pathDrawn, this, &SectionsPanel::placePath);
    m_splitter = new QSplitter(this);
    m_splitter->addWidget(m_mapCanvas);
    m_splitter->addWidget(m_crossCanvas);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(mapRow);
    layout->addLayout(crossRow);
    layout->addWidget(m_hint);
    layout->addWidget(m_splitter, 1);

    // Every edit goes into the session (undo, projects); the session's change shows it here.
    connect(m_level, &QLineEdit::editingFinished, this, [this] {
        const std::string text = m_level->text().trimmed().toStdString();
        if (text == levelShown()) return;
        m_model->update([&](session::SessionState& st) { st.sections.level = text; });
        emit placesEdited();
    });
    connect(m_cross, &QLineEdit::editingFinished, this, [this] {
        const std::string text = m_cross->text().trimmed().toStdString();
        if (text == crossShown().second) return;
        const auto kind = static_cast<session::SectionPlaces::Cross>(m_crossKind->currentIndex());
        m_model->update([&](session::SessionState& st) {
            st.sections.crossKind = kind;
            st.sections.cross = text;
        });
        emit placesEdited();
    });
    connect(m_crossKind, &QComboBox::activated, this, [this](int index) {
        // A place of the new kind: the default one when it is of that kind, else one to edit.
        const auto kind = static_cast<session::SectionPlaces::Cross>(index);
        std::string text = kind == session::SectionPlaces::Cross::Latitude    ? "45N"
                           : kind == session::SectionPlaces::Cross::Longitude ? "0E"
                                                                              : "";
        if (m_defaults && crossKindOf(m_defaults->crossSection) == kind) {
            text = crossText(m_defaults->crossSection).toStdString();
        }
        if (text.empty()) text = m_cross->text().toStdString();
        m_model->update([&](session::SessionState& st) {
            st.sections.crossKind = kind;
            st.sections.cross = text;
        });
        emit placesEdited();
    });
    connect(m_fill, &QComboBox::activated, this, [this](int index) {
        m_model->update([index](session::SessionState& st) {
            st.sectionsFill = static_cast<session::SectionsFill>(index);
        });
        emit placesEdited();
    });
    connect(m_model, &session::SessionModel::changed, this, [this](session::SessionParts parts) {
        // Rendering > Contour boxplot draws the boxplot on the sections too, and the vertical
        // axis is drawn as the 3D view draws it.
        const gl::RenderSettings& render = m_model->state().render;
        if (!parts.testFlag(session::SessionPart::Sections) && render.showBand == m_boxplotDrawn &&
            render.verticalAxis == m_verticalAxisDrawn) {
            return;
        }
        showPlaces();
        rebuild();
    });
    connect(m_selection, &workbench::MemberSelection::selectionChanged, this, [this] {
        showEmphasis();
        // A member's fill follows the selection.
        const engine::SectionFill fill = engineFill(m_model->state().sectionsFill);
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
    showPlaces();
}

SectionsPanel::~SectionsPanel() = default;

void SectionsPanel::showData(std::shared_ptr<const data::Ensemble> ensemble, float isovalue) {
    if (!ensemble) return;
    const bool sameKind = m_ensemble && m_ensemble->variable == ensemble->variable &&
                          m_ensemble->grid.sameShapeAndCoordinates(ensemble->grid);
    if (ensemble == m_ensemble && isovalue == m_isovalue) return;
    m_ensemble = std::move(ensemble);
    m_isovalue = isovalue;
    if (!sameKind) m_defaults.reset();  // found again for these data
    rebuild();
}

std::string SectionsPanel::levelShown() const {
    const std::string& typed = m_model->state().sections.level;
    if (!typed.empty() || !m_defaults) return typed;
    return levelText(m_defaults->map).toStdString();
}

std::pair<int, std::string> SectionsPanel::crossShown() const {
    const session::SectionPlaces& places = m_model->state().sections;
    if (!places.cross.empty() || !m_defaults) {
        return {static_cast<int>(places.crossKind), places.cross};
    }
    return {static_cast<int>(crossKindOf(m_defaults->crossSection)),
            crossText(m_defaults->crossSection).toStdString()};
}

void SectionsPanel::showPlaces() {
    const QSignalBlocker blockLevel(m_level), blockKind(m_crossKind), blockCross(m_cross),
        blockFill(m_fill);
    m_level->setText(QString::fromStdString(levelShown()));
    const auto [kind, cross] = crossShown();
    m_crossKind->setCurrentIndex(kind);
    m_cross->setText(QString::fromStdString(cross));
    m_fill->setCurrentIndex(static_cast<int>(m_model->state().sectionsFill));
    m_colours->showSession();
}

void SectionsPanel::rebuild() {
    m_boxplotDrawn = m_model->state().render.showBand;
    m_verticalAxisDrawn = m_model->state().render.verticalAxis;
    if (!m_ensemble) return;
    if (!m_shown) {
        m_dirty = true;
        return;
    }
    m_dirty = false;
    const session::SectionPlaces& places = m_model->state().sections;
    if (!m_defaults && (places.level.empty() || places.cross.empty())) {
        // Where the members' contours are: found in the background, then both sections built.
        const auto ensemble = m_ensemble;
        const float isovalue = m_isovalue;
        m_defaultsPending = true;
        m_defaultsJob.start(
            [ensemble, isovalue](const std::stop_token&, const data::Progress&) {
                return engine::defaultSections(*ensemble, isovalue);
            },
            [this](engine::DefaultSections defaults) {
                m_defaultsPending = false;
                m_defaults = std::move(defaults);
                showPlaces();
                rebuild();
            },
            [this](const std::exception_ptr&, bool) { m_defaultsPending = false; });
        return;
    }
    showPlaces();
    build(true);
    build(false);
}

engine::SectionRequest SectionsPanel::request(bool map, QString* problem) const {
    engine::SectionRequest r;
    std::string why;
    const auto [kind, cross] = crossShown();
    // The dock's cross kinds (latitude, longitude, path) follow the map in SectionKind.
    const auto place =
        map ? engine::parseSectionPlace(engine::SectionKind::Map, levelShown(), why)
            : engine::parseSectionPlace(static_cast<engine::SectionKind>(kind + 1), cross, why);
    if (!place) {
        *problem = QString::fromStdString(why);
        return r;
    }
    r.place = *place;
    r.place.verticalAxis = m_model->state().render.verticalAxis;
    r.isovalue = m_isovalue;
    r.fill = engineFill(m_model->state().sectionsFill);
    if (r.fill == engine::SectionFill::Member || r.fill == engine::SectionFill::Anomaly) {
        r.member = firstSelected(*m_selection);
        if (r.member < 0) r.fill = engine::SectionFill::None;
    }
    r.memberColours = memberColours(*m_selection);
    r.clusterNumbers = m_selection->memberClusterNumbers();
    engine::applySectionColours(r, m_model->state().sectionsColours);
    if (m_model->state().render.showBand) r.boxplot = boxplotOf(*m_selection);
    return r;
}

void SectionsPanel::build(bool map) {
    if (!m_ensemble) return;
    if (!m_shown) {
        m_dirty = true;
        return;
    }
    SectionCanvas* canvas = map ? m_mapCanvas : m_crossCanvas;
    QLineEdit* edit = map ? m_level : m_cross;
    QString problem;
    engine::SectionRequest r = request(map, &problem);
    edit->setStyleSheet(problem.isEmpty() ? QString() : QStringLiteral("color: #c0392b"));
    if (!problem.isEmpty()) {
        (map ? m_mapJob : m_crossJob).cancel();  // a section of the place before is not shown
        (map ? m_mapPending : m_crossPending) = false;
        canvas->setMessage(problem);
        showOverlays();
        emit sectionBuilt();
        return;
    }
    const engine::SectionFill fill = engineFill(m_model->state().sectionsFill);
    const bool wantsMember =
        fill == engine::SectionFill::Member || fill == engine::SectionFill::Anomaly;
    m_hint->setVisible(wantsMember && r.member < 0);
    m_hint->setText(tr("Select a member (click its contour) to fill the sections with it."));
    const auto ensemble = m_ensemble;
    auto& job = map ? m_mapJob : m_crossJob;
    bool& pending = map ? m_mapPending : m_crossPending;
    pending = true;
    job.start([ensemble, r](const std::stop_token&,
                            const data::Progress&) { return engine::buildSection(*ensemble, r); },
              [this, canvas, &pending](engine::SectionView view) {
                  pending = false;
                  canvas->setView(std::make_shared<const engine::SectionView>(std::move(view)));
                  showEmphasis();
                  showOverlays();
                  emit sectionBuilt();
              },
              [this, canvas, &pending](const std::exception_ptr& error, bool cancelled) {
                  pending = false;
                  if (cancelled || !error) return;
                  try {
                      std::rethrow_exception(error);
                  } catch (const std::exception& e) {
                      canvas->setMessage(QString::fromUtf8(e.what()));
                  }
                  showOverlays();
                  emit sectionBuilt();
              });
}

void SectionsPanel::showOverlays() {
    // The cross-section's path on the map, and the map's level across the cross-section.
    const engine::SectionView* map = m_mapCanvas->view();
    const engine::SectionView* cross = m_crossCanvas->view();
    m_mapCanvas->setOverlay(cross != nullptr && !cross->pathOnMap.empty()
                                ? std::vector<engine::SectionLine>{{cross->pathOnMap, false}}
                                : std::vector<engine::SectionLine>{});
    m_crossCanvas->setOverlay(
        map != nullptr && map->levelHeight >= 0.0
            ? std::vector<engine::SectionLine>{{{{0.0, map->levelHeight}, {1.0, map->levelHeight}},
                                                false}}
            : std::vector<engine::SectionLine>{});
    emit guidesChanged();
}

std::vector<std::vector<glm::dvec3>> SectionsPanel::guides() const {
    std::vector<std::vector<glm::dvec3>> lines;
    if (!m_shown) return lines;
    if (const engine::SectionView* map = m_mapCanvas->view(); map && map->levelHeight >= 0.0) {
        const double z = map->levelHeight;
        lines.push_back({{0, 0, z}, {1, 0, z}, {1, 1, z}, {0, 1, z}, {0, 0, z}});
    }
    if (const engine::SectionView* cross = m_crossCanvas->view();
        cross && cross->pathOnMap.size() >= 2) {
        std::vector<glm::dvec3> bottom, top;
        for (const glm::dvec2& p : cross->pathOnMap) {
            bottom.emplace_back(p, 0.0);
            top.emplace_back(p, 1.0);
        }
        lines.push_back({bottom.front(), top.front()});
        lines.push_back({bottom.back(), top.back()});
        lines.push_back(std::move(bottom));
        lines.push_back(std::move(top));
    }
    return lines;
}

void SectionsPanel::placePath(glm::dvec2 from, glm::dvec2 to) {
    if (!m_ensemble) return;
    // The map's unit square is linear in the axes' coordinates (data::DisplayFrame).
    const data::Grid& grid = m_ensemble->grid;
    const auto coordinates = [&grid](glm::dvec2 unit) {
        return glm::dvec2(
            grid.x().minValue() + unit.x * (grid.x().maxValue() - grid.x().minValue()),
            grid.y().minValue() + unit.y * (grid.y().maxValue() - grid.y().minValue()));
    };
    std::vector<glm::dvec2> ends{coordinates(from), coordinates(to)};
    const geo::MapProjection projection =
        geo::MapProjection::forGrid(grid, m_ensemble->gridMapping);
    if (projection.hasGeography()) projection.toLonLat(ends);
    engine::SectionPlace place;
    place.kind = engine::SectionKind::Path;
    place.from = ends[0];
    place.to = ends[1];
    const std::string text = pathText(place).toStdString();
    m_model->update([&](session::SessionState& st) {
        st.sections.crossKind = session::SectionPlaces::Cross::Path;
        st.sections.cross = text;
    });
    emit placesEdited();
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
    const std::vector<glm::vec3> colours = memberColours(*m_selection);
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

void SectionsPanel::setShownToUser(bool shown) {
    if (shown == m_shown) return;
    m_shown = shown;
    if (m_shown && m_dirty) rebuild();
    emit guidesChanged();  // none while not shown
}

void SectionsPanel::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    // Side by side in a wide dock (below the view), one above the other in a tall one.
    m_splitter->setOrientation(width() > 1.6 * height() ? Qt::Horizontal : Qt::Vertical);
}

}  // namespace ensil::ui

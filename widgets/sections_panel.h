// The Sections dock: a map at a level and a cross-section along a latitude, a longitude or a
// path, side by side (one above the other in a tall dock), drawn from the data and isovalue on
// screen with every member's contour in its cluster's colour over a chosen fill (the mean, the
// spread, P(f > c), the selected member or its difference from the mean). The places are typed
// as a meteorologist says them ("500 hPa", "45N", "-10,50:20,40") and kept in the session (undo,
// projects); without any, the sections lie where the members' contours are
// (engine::defaultSections). The map shows the cross-section's path, the cross-section the map's
// level; a drag with the right button across the map draws a new path. Selection, visibility, hover
// and clusters follow the shared workbench::MemberSelection both ways; with Rendering > Contour
// boxplot on, the boxplot of its depths is drawn too. Sections are built in the
// background and only while the dock is shown. GUI thread only.
#pragma once

#include <QWidget>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "data/ensemble.h"
#include "engine/ensemble_section.h"
#include "workbench/background_job.h"

class QAction;
class QComboBox;
class QLabel;
class QLineEdit;
class QSplitter;
class QToolButton;

namespace ensil::workbench {
class MemberSelection;
}  // namespace ensil::workbench

namespace ensil::session {
class SessionModel;
}  // namespace ensil::session

namespace ensil::ui {

class SectionCanvas;
class SectionColoursButton;

class SectionsPanel : public QWidget {
    Q_OBJECT
public:
    // The places and fill are the session's (`model`): edits go there, and undo or a project
    // shows here. Both outlive the panel.
    SectionsPanel(session::SessionModel* model, workbench::MemberSelection* selection,
                  QWidget* parent = nullptr);
    ~SectionsPanel() override;

    // The data and isovalue whose contours are drawn. Other data (another variable or grid)
    // starts from the default places; another time step of the same keeps the user's.
    void showData(std::shared_ptr<const data::Ensemble> ensemble, float isovalue);
    // Whether the user sees the panel (its dock shown and, in a tab group, the current tab:
    // QDockWidget::visibilityChanged). Sections are made only while shown; a hidden panel
    // notes that they are due and makes them when shown again.
    void setShownToUser(bool shown);
    // Writes the map (or the cross-section) as a figure, PNG, SVG or PDF by the suffix, 1400
    // wide; false with `error` set when there is none or it cannot be written.
    bool exportSection(bool map, const QString& path, QString* error);

    [[nodiscard]] QLineEdit* levelEdit() const { return m_level; }
    [[nodiscard]] QComboBox* crossKindBox() const { return m_crossKind; }
    [[nodiscard]] QLineEdit* crossEdit() const { return m_cross; }
    [[nodiscard]] QComboBox* fillBox() const { return m_fill; }
    [[nodiscard]] SectionColoursButton* coloursButton() const { return m_colours; }
    [[nodiscard]] SectionCanvas* mapCanvas() const { return m_mapCanvas; }
    [[nodiscard]] SectionCanvas* crossCanvas() const { return m_crossCanvas; }
    // A section (or the default places) is being made: its result has not reached the screen.
    // Where the sections lie in the 3D view's box (its unit cube: x, y across the floor, z up):
    // the map's outline at its level, the cross-section's curtain; none while the dock is
    // hidden (gl::Renderer::setSectionGuides draws them).
    [[nodiscard]] std::vector<std::vector<glm::dvec3>> guides() const;
    [[nodiscard]] bool isBuilding() const {
        return m_mapPending || m_crossPending || m_defaultsPending;
    }

signals:
    void sectionBuilt();
    void placesEdited();   // the user changed a place or the fill (an undo step)
    void guidesChanged();  // guides() has changed  // a map or
                           // cross-section reached the screen (or said why not)

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    void rebuild();
    void build(bool map);
    // The places as shown: the session's, or where the contours are when it has none.
    [[nodiscard]] std::string levelShown() const;
    [[nodiscard]] std::pair<int, std::string> crossShown() const;  // kind, place
    void showPlaces();
    [[nodiscard]] engine::SectionRequest request(bool map, QString* problem) const;
    void showEmphasis();
    void showOverlays();
    // A path drawn on the map (its unit square) becomes the cross-section's.
    void placePath(glm::dvec2 from, glm::dvec2 to);
    void recolour();
    void exportWithDialog(bool map);

    session::SessionModel* m_model;
    workbench::MemberSelection* m_selection;
    std::shared_ptr<const data::Ensemble> m_ensemble;
    float m_isovalue = 0.0F;
    bool m_shown = false;
    bool m_dirty = false;         // data or places changed while the dock was hidden
    bool m_boxplotDrawn = false;  // Rendering > Contour boxplot when last built
    data::VerticalAxis m_verticalAxisDrawn = data::VerticalAxis::LogPressure;  // likewise
    bool m_mapPending = false;
    bool m_crossPending = false;
    bool m_defaultsPending = false;
    // Where the members' contours are in the data shown; none until found.
    std::optional<engine::DefaultSections> m_defaults;
    QLineEdit* m_level;
    QComboBox* m_crossKind;
    QLineEdit* m_cross;
    QComboBox* m_fill;
    SectionColoursButton* m_colours;
    QToolButton* m_export;
    QLabel* m_hint;
    QSplitter* m_splitter;
    SectionCanvas* m_mapCanvas;
    SectionCanvas* m_crossCanvas;
    workbench::BackgroundJob<engine::SectionView> m_mapJob{this};
    workbench::BackgroundJob<engine::SectionView> m_crossJob{this};
    workbench::BackgroundJob<engine::DefaultSections> m_defaultsJob{this};
};

}  // namespace ensil::ui

// What follows each isovalue's surfaces reaching the screen (workbench::IsovalueSession::
// finished), in one place and in this order: the status bar, the floor and the section (which
// show the new P(f > c) and isovalue), the Sections dock, the removal band's range, the animation's
// order, the time step now shown, a project's members waiting for their clusters, and the undo
// history of new data. Before, each was its own connection in another file, run in the order they
// were made.
#include <utility>

#include "app/main_window.h"
#include "session/session_history.h"
#include "session/session_model.h"
#include "widgets/animation_bar.h"
#include "widgets/sections_panel.h"
#include "workbench/isovalue_session.h"
#include "workbench/workbench.h"

namespace ensil::app {

void MainWindow::showBuiltSurfaces(const QString& summary) {
    setIdle(summary);
    showFloor(m_model->state().render);
    showSection();
    // The Sections dock's maps and cross-sections, at this isovalue (of this time step).
    if (const workbench::IsovalueResult* result = m_session->result();
        result && overview() != nullptr) {
        m_sections->showData(overview()->ensemble, result->meshes->isovalue);
    }
    // The removal thresholds range over the outlyingness of the meshes on screen.
    showOutlyingnessRange();
    // A new isovalue changes the animation's order: the next play computes it again.
    m_animation->setSequence({});
    showBuiltTimeStep();
    // A project's visibility and selection apply to its members once their clusters are known;
    // new data: what was done to the old data cannot be undone on it.
    m_workbench->surfacesShown();
}

}  // namespace ensil::app

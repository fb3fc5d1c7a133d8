// The cutting plane's filled cut face in the workbench (gl::SectionField, METHODS.md section
// 18): which field, for which member and isovalue. The volume is copied and uploaded only when
// one of those changes, not at every hover.
#include "app/main_window.h"
#include "engine/section_volume.h"
#include "session/session_model.h"
#include "widgets/silhouette_view.h"
#include "workbench/isovalue_session.h"
#include "workbench/member_selection.h"

namespace ensil::app {

void MainWindow::showSpread() {
    if (!m_overview) return;
    engine::SectionSources sources;
    sources.ensemble = m_overview->ensemble.get();
    sources.stddev = m_overview->columnMaxima.stddev.get();
    m_view->renderer().setSpreadVolume(
        engine::sectionVolumeFor(sources, gl::SectionField::StandardDeviation));
}

void MainWindow::showSection() {
    gl::Renderer& renderer = m_view->renderer();
    const gl::SectionField field = m_model->state().render.plane.fill;
    if (m_selection->hovered() >= 0) m_lastHoveredMember = m_selection->hovered();
    if (!m_overview || field == gl::SectionField::None) {
        if (m_shownSection != ShownSection{}) renderer.setSectionVolume({});
        m_shownSection = {};
        return;
    }
    // A member: the first selected (a deliberate choice), else the one last hovered.
    const QList<int> selected = m_selection->selectedMembers();
    const int member = !selected.isEmpty() ? selected.front() : m_lastHoveredMember;
    const workbench::IsovalueResult* shown = m_session->result();
    const data::FieldValues* exceedance =
        shown != nullptr && shown->exceedance ? shown->exceedance.get() : nullptr;
    const ShownSection wanted{field, field == gl::SectionField::Member ? member : -1,
                              field == gl::SectionField::Probability ? exceedance : nullptr,
                              m_overview.get()};
    if (wanted == m_shownSection) return;
    m_shownSection = wanted;
    engine::SectionSources sources;
    sources.ensemble = m_overview->ensemble.get();
    sources.mean = &m_overview->moments->mean;
    sources.stddev = m_overview->columnMaxima.stddev.get();
    sources.exceedance = exceedance;
    sources.isovalue = shown != nullptr && shown->meshes ? shown->meshes->isovalue : 0.0F;
    sources.valueMinimum = m_overview->statistics.minimum;
    sources.valueMaximum = m_overview->statistics.maximum;
    sources.member = member;
    renderer.setSectionVolume(engine::sectionVolumeFor(sources, field));
    m_view->update();
}

}  // namespace ensil::app

// The cutting plane's filled cut face in the workbench (gl::SectionField, METHODS.md section
// 18): which field, for which member and isovalue. The volume is copied and uploaded only when
// one of those changes, not at every hover.
#include "app/main_window.h"
#include "engine/session_scene.h"
#include "session/session_model.h"
#include "widgets/silhouette_view.h"
#include "workbench/isovalue_session.h"
#include "workbench/member_selection.h"

namespace ensil::app {

engine::SceneData MainWindow::sceneData() const {
    engine::SceneData scene;
    if (overview() == nullptr) return scene;
    scene.ensemble = overview()->ensemble.get();
    scene.mean = &overview()->moments->mean;
    scene.columnMaxima = &overview()->columnMaxima;
    scene.valueMinimum = overview()->statistics.minimum;
    scene.valueMaximum = overview()->statistics.maximum;
    // The isovalue whose surfaces are drawn (none before the first).
    if (const workbench::IsovalueResult* shown = m_session->result(); shown && shown->meshes) {
        scene.isovalue = shown->meshes->isovalue;
        scene.exceedance = shown->exceedance.get();
        scene.exceedanceColumnMaximum = &shown->exceedanceColumnMaximum;
    }
    return scene;
}

void MainWindow::showSpread() {
    if (overview() == nullptr) return;
    m_view->renderer().setSpreadVolume(
        engine::sceneSection(sceneData(), gl::SectionField::StandardDeviation, -1));
}

void MainWindow::showSection() {
    gl::Renderer& renderer = m_view->renderer();
    const gl::SectionField field = m_model->state().render.plane.fill;
    if (m_selection->hovered() >= 0) m_lastHoveredMember = m_selection->hovered();
    if (overview() == nullptr || field == gl::SectionField::None) {
        if (m_shownSection != ShownSection{}) renderer.setSectionVolume({});
        m_shownSection = {};
        return;
    }
    const int member = engine::sectionMember(m_model->state().selection, m_lastHoveredMember);
    const engine::SceneData scene = sceneData();
    const ShownSection wanted{field, field == gl::SectionField::Member ? member : -1,
                              field == gl::SectionField::Probability ? scene.exceedance : nullptr,
                              overview()};
    if (wanted == m_shownSection) return;
    m_shownSection = wanted;
    renderer.setSectionVolume(engine::sceneSection(scene, field, member));
    m_view->update();
}

}  // namespace ensil::app

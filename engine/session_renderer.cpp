#include "engine/session_renderer.h"

#include <QElapsedTimer>
#include <QOpenGLContext>
#include <QOpenGLFramebufferObject>
#include <QOpenGLFunctions>
#include <QPainter>
#include <algorithm>

#include "data/demo_ensemble.h"
#include "engine/isovalue_job.h"
#include "engine/picture_title.h"
#include "engine/preprocess_run.h"
#include "engine/session_scene.h"
#include "engine/time_series.h"
#include "gl/offscreen_context.h"
#include "gl/renderer.h"
#include "gl/surface_format.h"
#include "preprocessing/cluster_identity.h"
#include "preprocessing/column_maximum.h"
#include "preprocessing/default_isovalue.h"
#include "preprocessing/field_statistics.h"
#include "session/project_file.h"
#include "session/session_camera.h"

namespace ensil::engine {

std::string demoSourceKey(const data::DemoEnsembleParams& params) {
    return "demo members=" + std::to_string(params.members) + " grid=" + std::to_string(params.nx) +
           "x" + std::to_string(params.ny) + "x" + std::to_string(params.nz) +
           " seed=" + std::to_string(params.seed);
}

namespace {
data::Progress stageProgress(const RenderRequest& request, const std::string& stage) {
    if (!request.progress) return {};
    return [&request, stage](double fraction) { request.progress(stage, fraction); };
}
}  // namespace

RenderOutcome renderSession(const session::SessionState& state, const RenderRequest& request) {
    auto ensemble = std::make_shared<const data::Ensemble>(
        state.demo ? data::makeDemoEnsemble(state.demoParams).ensemble
                   : data::openEnsemble(state.data, {}, stageProgress(request, "reading")));
    return renderEnsemble(
        std::move(ensemble),
        state.demo ? demoSourceKey(state.demoParams) : data::sourceIdentity(state.data), state,
        request);
}

RenderOutcome renderEnsemble(std::shared_ptr<const data::Ensemble> read,
                             const std::string& sourceKey, const session::SessionState& state,
                             const RenderRequest& request) {
    // As the workbench does, so a project's member numbers mean the same members here.
    std::vector<std::string> withoutData;
    const std::shared_ptr<const data::Ensemble> kept =
        withoutMembersWithoutData(std::move(read), withoutData);
    const data::Ensemble& ensemble = *kept;
    const prep::FieldStatistics stats =
        prep::computeFieldStatistics(ensemble, prep::kIsovalueHistogramBins);
    const float iso = state.isovalue.value_or(prep::defaultIsovalue(ensemble, stats));
    if (iso <= stats.minimum || iso >= stats.maximum) {
        throw session::ProjectError("isovalue " + std::to_string(iso) + " is outside the values (" +
                                    std::to_string(stats.minimum) + " .. " +
                                    std::to_string(stats.maximum) + " " + ensemble.units + ")");
    }
    const int members = static_cast<int>(ensemble.memberCount());
    const int k = request.clustersGiven ? std::clamp(state.clusters, 1, members)
                                        : session::defaultClusters(members);
    const prep::EnsembleMoments moments = prep::computeEnsembleMoments(ensemble);
    IsovalueJobInput job;
    job.ensemble = &ensemble;
    job.moments = &moments;
    job.options.isovalue = iso;
    job.verticalExaggeration = state.verticalExaggeration;
    job.linkage = state.linkage;
    if (request.useCache && !sourceKey.empty()) job.cacheDirectory = defaultMeshCacheDirectory();
    job.sourceKey = sourceKey + data::membersWithoutDataKey(withoutData);
    IsovalueOutcome outcome = runIsovalueJob(job, {}, stageProgress(request, "preprocessing"));

    const gl::OffscreenContext context;
    QOpenGLFramebufferObject target(request.width, request.height,
                                    QOpenGLFramebufferObject::CombinedDepthStencil);
    gl::Renderer renderer;
    renderer.initialize();
    renderer.setViewSize(request.width, request.height);
    renderer.setGrid(ensemble.grid);
    const ColumnMaxima maxima = computeColumnMaxima(ensemble, moments.mean);
    SceneData scene;
    scene.ensemble = &ensemble;
    scene.mean = &moments.mean;
    scene.columnMaxima = &maxima;
    scene.valueMinimum = stats.minimum;
    scene.valueMaximum = stats.maximum;
    scene.isovalue = iso;
    scene.exceedance = outcome.exceedance.get();
    scene.exceedanceColumnMaximum = &outcome.exceedanceColumnMaximum;
    scene.floorRange = request.floorRange;
    scene.floorRangeNote = request.floorRangeNote;
    // As the workbench shows the session: every part of it (session_scene.h).
    showSession(renderer, state, scene, session::SessionParts::fromInt(~0));
    // No hover in a picture: a member section shows the first selected.
    renderer.setSectionVolume(
        sceneSection(scene, state.render.plane.fill, sectionMember(state.selection, -1)));
    renderer.setSpreadVolume(sceneSection(scene, gl::SectionField::StandardDeviation, -1));
    renderer.setMapLines(std::make_shared<const std::vector<geo::MapLine>>(
        geo::mapLinesFor(ensemble.grid, ensemble.gridMapping)));
    const std::size_t triangles = outcome.meshes.triangles;
    renderer.setMeshes(std::make_shared<data::MeshSet>(std::move(outcome.meshes)));
    // Coloured, hidden and selected as the workbench shows the session.
    const std::vector<int> labels = prep::clusterLabels(outcome.tree, k);
    std::vector<std::string> names;
    for (const data::Member& member : ensemble.members) names.push_back(member.name);
    // Numbered as the previous time step's clusters, else as the project saved them.
    std::vector<int> previous =
        previousIdentitiesByName(request.previousMembers, request.previousIdentities, names);
    if (request.previousMembers.empty() && state.memberClusters.size() == ensemble.memberCount()) {
        previous.clear();
        for (const int number : state.memberClusters) previous.push_back(number - 1);
    }
    const std::vector<int> identities = matchStepIdentities(outcome.tree, k, labels, previous);
    renderer.setAppearance(sceneAppearance(state, labels, identities, members));
    renderer.setTitle(QString::fromStdString(pictureTitle(ensemble, iso)));
    gl::Camera& camera = renderer.camera();
    session::placeCamera(state.camera, renderer);
    if (request.planeAcrossBox) {
        const glm::vec4 p = *request.planeAcrossBox;
        const gl::CuttingPlane given = renderer.settings().plane;
        renderer.settings().plane = gl::CuttingPlane::acrossBox(
            glm::vec3(p), p.w, renderer.frame().boxMin(), renderer.frame().boxMax());
        renderer.settings().plane.enabled = given.enabled;
        renderer.settings().plane.thickness = given.thickness;
        renderer.settings().plane.fill = given.fill;
    }

    auto* f = QOpenGLContext::currentContext()->functions();
    std::vector<double> times;
    renderer.setLineScale(static_cast<float>(gl::exportTextScale(request.height)));
    for (int i = 0; i < std::max(1, request.frames); ++i) {
        QElapsedTimer timer;
        timer.start();
        renderer.render(target.handle(), request.width, request.height);
        f->glFinish();  // count the GPU's work, not only the submission
        times.push_back(static_cast<double>(timer.nsecsElapsed()) * 1e-6);
    }
    std::sort(times.begin(), times.end());
    RenderOutcome result;
    result.image = target.toImage();
    // Labels are sized in points: at 96 dots per inch, as on the workbench's screen, whatever
    // the platform says (with no display server there is no real screen to ask).
    constexpr int kDotsPerMeter = 3780;  // 96 dpi
    result.image.setDotsPerMeterX(kDotsPerMeter);
    result.image.setDotsPerMeterY(kDotsPerMeter);
    if (state.render.showAxes || state.render.showLegend || state.render.showTitle) {
        // Larger pictures get larger text, as the view would show them zoomed.
        const double scale = gl::exportTextScale(request.height);
        QPainter painter(&result.image);
        painter.scale(scale, scale);
        gl::paintOverlay(painter, renderer.overlay(request.width, request.height), scale,
                         QSizeF(request.width / scale, request.height / scale));
    }
    result.drawn = state;
    result.drawn.isovalue = iso;
    result.drawn.clusters = k;
    result.drawn.render.plane = renderer.settings().plane;
    // The camera as it stood, fitted or not: the same picture again from a saved project.
    result.drawn.camera.azimuth = camera.azimuth();
    result.drawn.camera.elevation = camera.elevation();
    result.drawn.camera.placement =
        session::CameraState::Placement{camera.distance(), camera.target()};
    result.frameMs = times[times.size() / 2];
    result.gpuBytes = renderer.gpuBytes();
    result.triangles = triangles;
    result.members = ensemble.memberCount();
    result.variable = ensemble.variable;
    result.note = data::fewLevelsWarning(ensemble.grid).value_or("");
    result.verticalScale = data::verticalScaleOf(ensemble.grid, renderer.frame());
    result.glRenderer = reinterpret_cast<const char*>(f->glGetString(GL_RENDERER));
    result.withoutDisplay = gl::renderingWithoutDisplay();
    result.memberNames = std::move(names);
    result.memberIdentities = prep::memberIdentities(labels, identities);
    result.drawn.memberClusters.clear();
    for (const int identity : result.memberIdentities) {
        result.drawn.memberClusters.push_back(identity + 1);
    }
    renderer.releaseGpuResources();
    return result;
}

}  // namespace ensil::engine

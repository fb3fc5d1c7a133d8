#include "app/project_renderer.h"

#include <QElapsedTimer>
#include <QOpenGLContext>
#include <QOpenGLFramebufferObject>
#include <QOpenGLFunctions>
#include <QPainter>
#include <algorithm>

#include "app/isovalue_job.h"
#include "app/isovalue_session.h"
#include "app/project_members.h"
#include "data/demo_ensemble.h"
#include "gl/offscreen_context.h"
#include "gl/renderer.h"
#include "gl/surface_format.h"
#include "preprocessing/column_maximum.h"
#include "preprocessing/field_statistics.h"

namespace ensil::app {

std::string demoSourceKey(const data::DemoEnsembleParams& params) {
    return "demo members=" + std::to_string(params.members) + " grid=" + std::to_string(params.nx) +
           "x" + std::to_string(params.ny) + "x" + std::to_string(params.nz) +
           " seed=" + std::to_string(params.seed);
}

RenderOutcome renderProject(const Project& project, const RenderRequest& request) {
    const data::Ensemble ensemble = project.demo
                                        ? data::makeDemoEnsemble(project.demoParams).ensemble
                                        : data::openEnsemble(project.data);
    const prep::FieldStatistics stats = prep::computeFieldStatistics(ensemble, 0);
    const float iso =
        project.isovalue.value_or(defaultIsovalue(stats.histogram, stats.minimum, stats.maximum));
    if (iso <= stats.minimum || iso >= stats.maximum) {
        throw ProjectError("isovalue " + std::to_string(iso) + " is outside the values (" +
                           std::to_string(stats.minimum) + " .. " + std::to_string(stats.maximum) +
                           " " + ensemble.units + ")");
    }
    const int k = std::clamp(project.clusters, 1, static_cast<int>(ensemble.memberCount()));
    const prep::EnsembleMoments moments = prep::computeEnsembleMoments(ensemble);
    IsovalueJobInput job;
    job.ensemble = &ensemble;
    job.moments = &moments;
    job.options.isovalue = iso;
    job.verticalExaggeration = project.verticalExaggeration;
    job.linkage = prep::parseLinkage(project.linkage);
    if (request.useCache) job.cacheDirectory = defaultMeshCacheDirectory();
    job.sourceKey =
        project.demo ? demoSourceKey(project.demoParams) : data::sourceIdentity(project.data);
    IsovalueOutcome outcome = runIsovalueJob(job);

    const gl::OffscreenContext context;
    QOpenGLFramebufferObject target(request.width, request.height,
                                    QOpenGLFramebufferObject::CombinedDepthStencil);
    gl::Renderer renderer;
    renderer.initialize();
    renderer.setGrid(ensemble.grid);
    renderer.setVerticalExaggeration(project.verticalExaggeration);
    renderer.setFloorMap(
        gl::FloorMap::spanning(prep::computeColumnMaximum(ensemble.grid, moments.mean)));
    auto set = std::make_shared<data::MeshSet>();
    set->isovalue = iso;
    set->members = std::move(outcome.meshes.members);
    set->mean = std::move(outcome.meshes.mean);
    renderer.setMeshes(set);
    // Coloured, hidden and selected as the workbench shows the project.
    ui::MemberSelection members;
    members.setMembers({QStringList(static_cast<qsizetype>(ensemble.memberCount())), {}, {}});
    members.setTree(outcome.tree);
    members.setClusterCount(k);
    applyProjectMembers(project, members);
    renderer.setAppearance(members.appearance());
    renderer.settings() = project.render;
    renderer.setBackground({project.background, 1.0F});
    gl::Camera& camera = renderer.camera();
    if (project.camera) {
        camera.setAngles(project.camera->azimuth, project.camera->elevation);
        camera.setTarget(project.camera->target);
        camera.setDistance(project.camera->distance);
        camera.setProjection(project.camera->orthographic ? gl::Camera::Projection::Orthographic
                                                          : gl::Camera::Projection::Perspective);
    } else {
        camera.setAngles(request.azimuth, request.elevation);
    }
    if (request.planeAcrossBox) {
        const glm::vec4 p = *request.planeAcrossBox;
        const float thickness = renderer.settings().plane.thickness;
        renderer.settings().plane = gl::CuttingPlane::acrossBox(
            glm::vec3(p), p.w, renderer.frame().boxMin(), renderer.frame().boxMax());
        renderer.settings().plane.thickness = thickness;
    }

    auto* f = QOpenGLContext::currentContext()->functions();
    std::vector<double> times;
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
    if (request.labels) {
        QPainter painter(&result.image);
        gl::paintOverlay(painter, renderer.overlay(request.width, request.height), 1.0);
    }
    result.frameMs = times[times.size() / 2];
    result.gpuBytes = renderer.gpuBytes();
    result.triangles = outcome.meshes.triangles;
    result.members = ensemble.memberCount();
    result.isovalue = iso;
    result.glRenderer = reinterpret_cast<const char*>(f->glGetString(GL_RENDERER));
    result.withoutDisplay = gl::renderingWithoutDisplay();
    renderer.releaseGpuResources();
    return result;
}

}  // namespace ensil::app

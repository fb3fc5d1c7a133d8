// Frame times of the silhouette renderer on the paper-sized ensemble (50 members + mean, the
// demo at isovalue 30) at 1920 x 1200: the median of each mode and, in the same run, of opaque
// lit surfaces of the same meshes, with the ratios. Runs under a display server or, with none,
// through EGL's surfaceless platform.
//
//   ensil_render_benchmark [--frames N] [--size WxH]
#include <QElapsedTimer>
#include <QGuiApplication>
#include <QOpenGLContext>
#include <QOpenGLFramebufferObject>
#include <QOpenGLFunctions>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include "data/demo_ensemble.h"
#include "data/working_memory.h"
#include "gl/offscreen_context.h"
#include "gl/palette.h"
#include "gl/renderer.h"
#include "gl/surface_format.h"
#include "preprocessing/clustering.h"
#include "preprocessing/column_maximum.h"
#include "preprocessing/isosurface_pipeline.h"
#include "preprocessing/mesh_packing.h"
#include "preprocessing/similarity.h"
#include "timing.h"

using ensil::bench::median;

int main(int argc, char** argv) {
    ensil::data::keepWorkingMemoryForReuse();  // as ensil does (data/working_memory.h)
    int frames = 20, width = 1920, height = 1200;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--frames" && i + 1 < argc) frames = std::max(1, std::atoi(argv[++i]));
        if (a == "--size" && i + 1 < argc) std::sscanf(argv[++i], "%dx%d", &width, &height);
    }
    QSurfaceFormat::setDefaultFormat(ensil::gl::preferredSurfaceFormat(0));
    // With no display server, through EGL's surfaceless platform, like `ensil render`.
    if (const auto problem = ensil::gl::prepareOffscreenPlatform()) {
        std::fprintf(stderr, "no display server, and %s: run under xvfb-run -a\n",
                     problem->c_str());
        return 1;
    }
    QGuiApplication app(argc, argv);
    const auto demo = ensil::data::makeDemoEnsemble({});
    const ensil::data::Ensemble& e = demo.ensemble;
    const auto moments = ensil::prep::computeEnsembleMoments(e);
    ensil::prep::PipelineOptions options;
    options.isovalue = 30.0F;
    auto built = ensil::prep::buildIsovalueMeshes(e, moments,
                                                  ensil::data::DisplayFrame(e.grid, 1.0F), options);
    const auto tree = ensil::prep::clusterMembers(ensil::prep::computeDistanceMatrix(e, 30.0F));
    auto set = std::make_shared<ensil::data::MeshSet>();
    set->members = std::move(built.members);
    set->mean = std::move(built.mean);

    std::unique_ptr<ensil::gl::OffscreenContext> offscreen;
    try {
        offscreen = std::make_unique<ensil::gl::OffscreenContext>();
    } catch (const std::exception& error) {
        std::fprintf(stderr, "%s\n", error.what());
        return 1;
    }
    QOpenGLContext& context = offscreen->context();
    const char* renderer =
        reinterpret_cast<const char*>(context.functions()->glGetString(GL_RENDERER));
    QOpenGLFramebufferObject target(width, height, QOpenGLFramebufferObject::CombinedDepthStencil);
    ensil::gl::Renderer r;
    r.initialize();
    r.setGrid(e.grid);
    r.setFloorMap(
        ensil::gl::FloorMap::spanning(ensil::prep::computeColumnMaximum(e.grid, moments.mean)));
    r.setMeshes(set);
    r.setAppearance(ensil::gl::clusterAppearance(ensil::prep::clusterLabels(tree, 5)));

    const auto time = [&](ensil::gl::RenderMode mode) {
        r.settings().mode = mode;
        r.render(target.handle(), width, height);  // warm-up: uploads, shader variants
        context.functions()->glFinish();
        std::vector<double> ms;
        for (int i = 0; i < frames; ++i) {
            QElapsedTimer t;
            t.start();
            r.render(target.handle(), width, height);
            context.functions()->glFinish();
            ms.push_back(static_cast<double>(t.nsecsElapsed()) * 1e-6);
        }
        return median(ms);
    };
    const double opaque = time(ensil::gl::RenderMode::OpaqueSurfaces);
    const double shaded = time(ensil::gl::RenderMode::ShadedSilhouettes);
    const double spaghetti = time(ensil::gl::RenderMode::Spaghetti);
    const double surfaces = time(ensil::gl::RenderMode::Surfaces);
    // What the geometry shader's culling of triangles far from silhouettes saves.
    r.settings().silhouetteCulling = false;
    const double shadedUnculled = time(ensil::gl::RenderMode::ShadedSilhouettes);
    const double spaghettiUnculled = time(ensil::gl::RenderMode::Spaghetti);
    r.settings().silhouetteCulling = true;
    // A cutting plane through the middle, and the removal over the lower half of outlyingness.
    const auto& frame = r.frame();
    r.settings().plane = ensil::gl::CuttingPlane::acrossBox({0.0F, 1.0F, 0.0F}, 0.0F,
                                                            frame.boxMin(), frame.boxMax());
    const double shadedPlane = time(ensil::gl::RenderMode::ShadedSilhouettes);
    r.settings().plane.enabled = false;
    r.settings().removal = true;
    r.settings().removalMin = 0.0F;
    r.settings().removalMax = 0.5F * ensil::prep::maximumOutlyingness(*set);
    const double shadedRemoval = time(ensil::gl::RenderMode::ShadedSilhouettes);
    r.settings().removal = false;
    // While the camera moves, the view may draw the scene at half the resolution.
    r.setResolutionScale(0.5F);
    const double shadedMoving = time(ensil::gl::RenderMode::ShadedSilhouettes);
    r.setResolutionScale(1.0F);
    // Five members selected: drawn as solid surfaces over the silhouettes.
    auto look = ensil::gl::clusterAppearance(ensil::prep::clusterLabels(tree, 5));
    for (std::size_t m = 0; m < 5 && m < look.size(); ++m) look[m].selected = true;
    r.setAppearance(look);
    const double shadedSelection = time(ensil::gl::RenderMode::ShadedSilhouettes);
    // Picking under the cursor (hover, click) and brushing a quarter of the view, after a frame.
    std::vector<double> picks, brushes;
    for (int i = 0; i < frames; ++i) {
        QElapsedTimer t;
        t.start();
        (void)r.pick(width / 2, height / 2);
        context.functions()->glFinish();
        picks.push_back(static_cast<double>(t.nsecsElapsed()) * 1e-6);
        t.start();
        (void)r.membersIn(width / 4, height / 4, 3 * width / 4, 3 * height / 4);
        brushes.push_back(static_cast<double>(t.nsecsElapsed()) * 1e-6);
    }
    std::printf("renderer: %s\n", renderer);
    std::printf(
        "scene: %zu meshes, %zu triangles, %.2f MiB on the GPU, %d x %d, median of %d frames\n",
        e.memberCount() + 1, built.triangles, static_cast<double>(r.gpuBytes()) / (1024.0 * 1024.0),
        width, height, frames);
    std::printf("  opaque lit surfaces (reference) %8.2f ms\n", opaque);
    std::printf("  shaded silhouettes              %8.2f ms  (%.2fx the reference; goal <= 1.5x)\n",
                shaded, shaded / opaque);
    const struct {
        const char* what;
        double ms;
    } rows[] = {{"3D spaghetti plot", spaghetti},
                {"semi-transparent surfaces", surfaces},
                {"shaded, culling + clipping off", shadedUnculled},
                {"spaghetti, culling + clipping off", spaghettiUnculled},
                {"shaded with a cutting plane", shadedPlane},
                {"shaded with removal", shadedRemoval},
                {"shaded at half resolution", shadedMoving},
                {"shaded, 5 members selected", shadedSelection}};
    for (const auto& row : rows) {
        std::printf("  %-31s %8.2f ms  (%.2fx)\n", row.what, row.ms, row.ms / opaque);
    }
    std::printf("  pick under the cursor (7 x 7)   %8.2f ms\n", median(picks));
    std::printf("  brush a quarter of the view     %8.2f ms\n", median(brushes));
    r.releaseGpuResources();
    return 0;
}

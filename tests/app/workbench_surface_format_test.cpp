#include "workbench/workbench_surface_format.h"

#include <gtest/gtest.h>

#include <QTest>
#include <cstdlib>

#include "data/demo_ensemble.h"
#include "gl/palette.h"
#include "preprocessing/ensemble_moments.h"
#include "preprocessing/isosurface_pipeline.h"
#include "widgets/silhouette_view.h"

using namespace ensil;

namespace {
// The demo's silhouettes drawn by a view whose framebuffer has `samples` samples a pixel.
QImage drawDemo(const data::Ensemble& e, const std::shared_ptr<const data::MeshSet>& meshes,
                int samples) {
    ui::SilhouetteView view;
    QSurfaceFormat format = workbench::workbenchSurfaceFormat();
    format.setSamples(samples);
    view.setFormat(format);
    view.resize(400, 300);
    view.renderer().setGrid(e.grid);
    view.renderer().setMeshes(meshes);
    view.renderer().setAppearance(gl::clusterAppearance({0, 1, 2, 0}));
    // The labels and legend are painted over the frame by QPainter, whose antialiasing does
    // use the window's samples; the claim here is about the renderer's own pixels.
    view.renderer().settings().showAxes = false;
    view.renderer().settings().showLegend = false;
    view.show();
    if (!QTest::qWaitForWindowExposed(&view) || !view.glError().isEmpty()) return {};
    return view.grabFramebuffer();
}
}  // namespace

// The workbench window is single-sampled because gl::Renderer draws into its own
// single-sampled targets and copies them to the window in one full-screen pass: multisampling
// the view's framebuffer must then change no pixel. Should the renderer ever draw edges into
// the window's framebuffer itself, this fails, and the window should be multisampled again.
TEST(WorkbenchSurfaceFormat, MultisamplingTheViewWouldChangeNoPixel) {
    EXPECT_EQ(workbench::workbenchSurfaceFormat().samples(), 0);
    EXPECT_EQ(workbench::workbenchSurfaceFormat().profile(), QSurfaceFormat::CoreProfile);
    const auto demo = data::makeDemoEnsemble({.members = 4, .nx = 48, .ny = 24, .nz = 8});
    const data::Ensemble& e = demo.ensemble;
    const auto moments = prep::computeEnsembleMoments(e);
    prep::PipelineOptions options;
    options.isovalue = 30.0F;
    auto built = prep::buildIsovalueMeshes(e, moments, data::DisplayFrame(e.grid, 1.0F), options);
    auto meshes = std::make_shared<data::MeshSet>();
    meshes->isovalue = options.isovalue;
    meshes->members = std::move(built.members);
    meshes->mean = std::move(built.mean);

    const QImage single = drawDemo(e, meshes, 0);
    const QImage multi = drawDemo(e, meshes, 4);
    ASSERT_FALSE(single.isNull());
    ASSERT_EQ(single.size(), multi.size());
    int differing = 0;
    int background = 0;
    const QRgb corner = single.pixel(0, 0);
    for (int y = 0; y < single.height(); ++y) {
        for (int x = 0; x < single.width(); ++x) {
            const QRgb a = single.pixel(x, y);
            const QRgb b = multi.pixel(x, y);
            if (a == corner) ++background;
            if (std::abs(qRed(a) - qRed(b)) > 1 || std::abs(qGreen(a) - qGreen(b)) > 1 ||
                std::abs(qBlue(a) - qBlue(b)) > 1) {
                ++differing;
            }
        }
    }
    single.save(QStringLiteral(ENSIL_TEST_OUTPUT_DIR "/workbench_single_sampled.png"));
    // The box, the floor and the silhouettes cover a few per cent of the view at least.
    EXPECT_LT(background, single.width() * single.height() * 97 / 100) << "the scene was drawn";
    EXPECT_EQ(differing, 0);
}

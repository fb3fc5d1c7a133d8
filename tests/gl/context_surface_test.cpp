// The context surface the settings choose (mean, median member, P = 0.5) and the contour
// boxplot's band, drawn by the renderer: three concentric spheres of radius 6, 7 and 12 seen
// head-on, the members hidden, the context solid, so the gray disc's size tells which surface
// was drawn (mean radius 8.33, median and P = 0.5 radius 7).
#include <gtest/gtest.h>

#include "preprocessing/context_surfaces.h"
#include "tests/gl/sphere_scene.h"

using namespace ensil;

namespace {
int nonBackgroundPixels(const QImage& image) {
    int n = 0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            if (QColor(image.pixel(x, y)).lightness() > 40) ++n;
        }
    }
    return n;
}
}  // namespace

using ContextSurfaceTest = test::SphereSceneTest;

TEST_F(ContextSurfaceTest, TheChosenContextIsDrawnAndTheBandAddsItsEnvelope) {
    const glm::vec3 c(15.5F);
    const data::Ensemble e = test::spheres({c, c, c}, {-2.0F, -1.0F, 4.0F});
    show(e, {gl::clusterColor(0), gl::clusterColor(1), gl::clusterColor(2)});
    auto meshes = test::meshesOf(e);
    prep::PipelineOptions options;
    options.isovalue = 8.0F;
    prep::addContextSurfaces(
        *meshes, prep::buildContextSurfaces(e, data::DisplayFrame(e.grid, 1.0F), options));
    m_renderer.setMeshes(meshes);
    m_renderer.setAppearance({{gl::clusterColor(0), false, false},
                              {gl::clusterColor(1), false, false},
                              {gl::clusterColor(2), false, false}});
    gl::RenderSettings& s = m_renderer.settings();
    s.showMean = true;
    s.meanOpacity = 1.0F;  // solid: the disc's area is the surface's
    s.showRims = false;

    s.context = gl::ContextSurface::Mean;
    const int mean = nonBackgroundPixels(draw());
    s.context = gl::ContextSurface::Median;
    const QImage medianImage = draw();
    const int median = nonBackgroundPixels(medianImage);
    s.context = gl::ContextSurface::Probability;
    const int probability = nonBackgroundPixels(draw());
    ASSERT_GT(mean, 1000);
    // (7 / 8.33)^2 = 0.71 of the mean's disc for both: P = 0.5 is the surface of the members'
    // median, here member 1's values.
    EXPECT_NEAR(static_cast<double>(median) / mean, 0.71, 0.06);
    EXPECT_NEAR(static_cast<double>(probability) / mean, 0.71, 0.06);

    // The band's outer surface (radius 6, inside the gray disc of radius 7) is drawn over it
    // translucently: the disc changes colour, its size does not.
    s.context = gl::ContextSurface::Median;
    s.showBand = true;
    const QImage banded = draw();
    EXPECT_GT(test::differingFraction(medianImage, banded, 8), 0.05);
    const gl::ViewOverlay overlay = m_renderer.overlay(kWidth, kHeight);
    bool bandEntry = false, medianEntry = false;
    for (const gl::LegendEntry& entry : overlay.legend) {
        bandEntry = bandEntry || entry.text == QStringLiteral("50 % band");
        medianEntry = medianEntry || entry.text == QStringLiteral("Median member");
    }
    EXPECT_TRUE(bandEntry);
    EXPECT_TRUE(medianEntry);
}

// Rendering the isosurfaces of analytic ensembles: spheres give exact expectations for where
// silhouettes must and must not be. The meshes come from the real preprocessing pipeline.
#include "tests/gl/sphere_scene.h"

using namespace ensil;
using test::channelDistance;
using test::spheres;
using SilhouetteTest = test::SphereSceneTest;

TEST_F(SilhouetteTest, ShadedSilhouetteOutlinesTheRimAndLeavesTheFaceEmpty) {
    const glm::vec3 centre{15.5F, 15.5F, 15.5F};
    show(spheres({centre}), {{1.0F, 0.5F, 0.0F}});
    m_renderer.settings().showMean = false;
    m_renderer.settings().thickness = 0.1F;
    const QImage image = draw();
    // Facing the viewer, the surface is no silhouette: background.
    const QPoint middle = project(display(centre));
    EXPECT_LE(channelDistance(image.pixelColor(middle), {0, 0, 0}), 3)
        << image.pixelColor(middle).name().toStdString();
    // On the rim (8 cells to the side, perpendicular to the view), the member's colour.
    const QPoint rim = project(display(centre + glm::vec3(7.9F, 0, 0)));
    int best = 255;
    for (int dx = -3; dx <= 3; ++dx)
        best = std::min(best,
                        channelDistance(image.pixelColor(rim + QPoint(dx, 0)), {1.0F, 0.5F, 0.0F}));
    EXPECT_LE(best, 40) << "no silhouette at the rim";
}

TEST_F(SilhouetteTest, TheMeanAtFullOpacityIsASolidGraySurface) {
    show(spheres({{13, 15.5F, 15.5F}, {18, 15.5F, 15.5F}}), {{1, 0, 0}, {0, 0, 1}});
    m_renderer.settings().showMean = true;
    m_renderer.settings().meanOpacity = 1.0F;
    const QImage image = draw();
    const QColor middle = image.pixelColor(project(display({15.5F, 15.5F, 15.5F})));
    EXPECT_EQ(middle.red(), middle.green()) << "gray";
    EXPECT_EQ(middle.green(), middle.blue()) << "gray";
    EXPECT_GT(middle.red(), 120) << "lit, facing the headlight";
}

TEST_F(SilhouetteTest, ByDefaultTheMeanIsTranslucentContextThatDoesNotHideTheMembers) {
    // A member silhouette (the rim of a small sphere) behind a big mean: a solid mean hides
    // it, the default translucent one lets it through, tinted but still the member's colour.
    const glm::vec3 centre{15.5F, 15.5F, 15.5F};
    show(spheres({centre, centre}, {-5, 0}), {{1, 0, 0}, {0, 0, 1}});
    m_renderer.setAppearance({{{1, 0, 0}, true, false, 0}, {{0, 0, 1}, false, false, 1}});
    m_renderer.settings().thickness = 0.1F;
    ASSERT_LT(m_renderer.settings().meanOpacity, 1.0F) << "the default";
    // Where the small member's rim lies on screen, seen through the mean.
    const QPoint rim = project(display({centre.x + 2.9F, centre.y, centre.z}));
    m_renderer.settings().showMean = false;
    const QColor alone = draw().pixelColor(rim);
    ASSERT_GT(alone.red(), alone.blue() + 60) << "the member's rim, red";
    m_renderer.settings().showMean = true;
    const QColor throughTranslucent = draw().pixelColor(rim);
    EXPECT_GT(throughTranslucent.red(), throughTranslucent.blue() + 30)
        << "still red through the translucent mean";
    m_renderer.settings().meanOpacity = 1.0F;
    const QColor behindSolid = draw().pixelColor(rim);
    EXPECT_EQ(behindSolid.red(), behindSolid.blue()) << "hidden: the solid mean's gray";
}

TEST_F(SilhouetteTest, TheImageDoesNotDependOnTheOrderMembersAreDrawnIn) {
    // Three overlapping spheres in three colours, drawn in two orders.
    const std::vector<glm::vec3> centres{{12, 15.5F, 15.5F}, {16, 14, 16}, {19, 17, 15}};
    const std::vector<glm::vec3> colours{{1, 0.2F, 0.2F}, {0.2F, 1, 0.2F}, {0.2F, 0.3F, 1}};
    show(spheres(centres), colours);
    m_renderer.settings().showMean = false;
    const QImage forward = draw();
    show(spheres({centres[2], centres[1], centres[0]}), {colours[2], colours[1], colours[0]});
    m_renderer.settings().showMean = false;
    const QImage backward = draw();
    // Floating-point sums in another order may differ in the last bit: allow 2/255.
    EXPECT_LE(test::differingFraction(forward, backward, 2), 0.0) << "order-dependent pixels";
    EXPECT_GT(test::differingFraction(forward, QImage(forward.size(), forward.format()), 2), 0.01)
        << "the scene is not empty";
}

TEST_F(SilhouetteTest, SpaghettiIsOpaqueAndSurfacesAreFaint) {
    const glm::vec3 centre{15.5F, 15.5F, 15.5F};
    show(spheres({centre}), {{0.0F, 1.0F, 0.0F}});
    m_renderer.settings().showMean = false;
    m_renderer.settings().thickness = 0.1F;
    m_renderer.settings().mode = gl::RenderMode::Spaghetti;
    QImage image = draw();
    const QPoint rim = project(display(centre + glm::vec3(7.9F, 0, 0)));
    bool opaque = false;
    for (int dx = -3; dx <= 3; ++dx)
        opaque = opaque || image.pixelColor(rim + QPoint(dx, 0)) == QColor(0, 255, 0);
    EXPECT_TRUE(opaque) << "spaghetti lines are the member's colour, fully opaque";

    m_renderer.settings().mode = gl::RenderMode::Surfaces;
    m_renderer.settings().surfaceAlpha = 0.25F;
    image = draw();
    const QColor middle = image.pixelColor(project(display(centre)));
    EXPECT_GT(middle.green(), 20) << "the face is drawn";
    EXPECT_LT(middle.green(), 180) << "but translucent";
}

TEST_F(SilhouetteTest, OpaqueSurfacesFillTheFaceWithTheLitColour) {
    const glm::vec3 centre{15.5F, 15.5F, 15.5F};
    show(spheres({centre}), {{0.0F, 0.0F, 1.0F}});
    m_renderer.settings().showMean = false;
    m_renderer.settings().mode = gl::RenderMode::OpaqueSurfaces;
    const QColor middle = draw().pixelColor(project(display(centre)));
    // Facing the headlight: 0.3 + 0.7 * |n.v|, nearly full blue.
    EXPECT_EQ(middle.red(), 0);
    EXPECT_EQ(middle.green(), 0);
    EXPECT_GT(middle.blue(), 230);
}

TEST_F(SilhouetteTest, RemovalHidesMembersWhereTheyAgree) {
    // Two identical spheres: outlyingness is zero everywhere, so removal with o*_min > 0 hides
    // them completely.
    show(spheres({{15.5F, 15.5F, 15.5F}, {15.5F, 15.5F, 15.5F}}), {{1, 1, 0}, {1, 1, 0}});
    m_renderer.settings().showMean = false;
    m_renderer.settings().thickness = 0.1F;
    const QImage before = draw();
    m_renderer.settings().removal = true;
    m_renderer.settings().removalMin = 0.5F;
    m_renderer.settings().removalMax = 1.0F;
    const QImage after = draw();
    m_renderer.setMeshes(nullptr);
    const QImage empty = draw();  // the box alone
    EXPECT_GT(test::differingFraction(before, empty, 8), 0.01) << "silhouettes were drawn";
    EXPECT_EQ(test::differingFraction(after, empty, 8), 0.0) << "and all of them removed";
}

TEST_F(SilhouetteTest, ShadedSilhouettesMatchBaseline) {
    show(spheres({{12, 15.5F, 15.5F}, {17, 15, 17}, {19, 17.5F, 13}}),
         {gl::clusterColor(0), gl::clusterColor(1), gl::clusterColor(2)});
    m_renderer.camera().setAngles(-60.0F, 25.0F);
    m_renderer.camera().fit(m_renderer.frame().center(), 0.5F);
    m_renderer.settings().thickness = 0.02F;  // the baseline's, whatever the default
    const test::ImageComparison result =
        test::compareWithBaseline(draw(), "silhouettes_three_spheres");
    EXPECT_TRUE(result.passed) << result.message.toStdString();
}

namespace {
// Along the row through the sphere's centre, from the right edge of the picture inwards: the
// outermost drawn pixel and how many drawn pixels follow it without a gap (the ring's width).
std::pair<int, int> ringOnTheRight(const QImage& image, QPoint centre) {
    int outer = -1, width = 0;
    for (int x = image.width() - 1; x > centre.x(); --x) {
        // The member is yellow-orange; the box's lines are gray.
        const QColor c = image.pixelColor(x, centre.y());
        const bool drawn = c.red() - c.blue() > 40;
        if (outer < 0) {
            if (drawn) outer = x, width = 1;
        } else if (drawn) {
            ++width;
        } else {
            break;
        }
    }
    return {outer, width};
}
}  // namespace

TEST_F(SilhouetteTest, TheRingLiesAtTheProjectedRadiusAndThickerTauWidensIt) {
    // A sphere of radius 8 seen head-on: its outline projects from the points 8 cells to its
    // side, perpendicular to the view.
    const glm::vec3 centre{15.5F, 15.5F, 15.5F};
    show(spheres({centre}), {{1.0F, 0.8F, 0.2F}});
    m_renderer.settings().showMean = false;
    m_renderer.settings().showAxes = false;
    const QPoint middle = project(display(centre));
    const QPoint rim = project(display(centre + glm::vec3(8.0F, 0, 0)));
    m_renderer.settings().thickness = 0.02F;
    const QImage thin = draw();
    m_renderer.settings().thickness = 0.08F;
    const QImage thick = draw();
    const auto [thinOuter, thinWidth] = ringOnTheRight(thin, middle);
    const auto [thickOuter, thickWidth] = ringOnTheRight(thick, middle);
    EXPECT_NEAR(thinOuter, rim.x(), 2) << "the ring's outer edge is the projected radius";
    EXPECT_NEAR(thickOuter, rim.x(), 2);
    EXPECT_GE(thinWidth, 1);
    EXPECT_GT(thickWidth, thinWidth + 1) << "thicker tau, wider ring";
    EXPECT_LT(thickWidth, (rim.x() - middle.x()) / 2) << "still a ring, not a disc";
    const QColor inside = thick.pixelColor(middle);
    EXPECT_LE(inside.red() - inside.blue(), 10) << "no silhouette in the middle";
}

TEST_F(SilhouetteTest, ManySelectedMembersAreSurfacesWithAThickerOpaqueRim) {
    // More selected members than are drawn solid: translucent surfaces, each with a rim at full
    // colour, wider than the silhouette the same member has unselected.
    const glm::vec3 centre{15.5F, 15.5F, 15.5F};
    const glm::vec3 colour{1.0F, 0.8F, 0.2F};
    const std::size_t count = gl::Renderer::kMaxSolidSelection + 1;
    show(spheres(std::vector<glm::vec3>(count, centre)), std::vector<glm::vec3>(count, colour));
    m_renderer.settings().showMean = false;
    m_renderer.settings().showAxes = false;
    m_renderer.settings().thickness = 0.02F;
    const QPoint middle = project(display(centre));
    const auto [plainOuter, plainWidth] = ringOnTheRight(draw(), middle);
    std::vector<gl::MemberAppearance> look(count, {colour, true, true});
    m_renderer.setAppearance(look);
    ASSERT_FALSE(m_renderer.selectionShown().solid);
    const QImage selected = draw();
    const auto [outer, width] = ringOnTheRight(selected, middle);
    EXPECT_NEAR(outer, plainOuter, 2);
    EXPECT_GE(width, plainWidth + 2) << "the selected rim is thicker";
    EXPECT_LE(channelDistance(selected.pixelColor(outer - 1, middle.y()), colour), 30)
        << "and opaque: " << selected.pixelColor(outer - 1, middle.y()).name().toStdString();
}

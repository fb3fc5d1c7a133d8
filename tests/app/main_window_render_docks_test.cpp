// The rendering and cutting plane docks drive the renderer of the main window's view.
#include <gtest/gtest.h>

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QSettings>
#include <QSignalSpy>
#include <QSlider>
#include <QTest>

#include "app/main_window.h"
#include "tests/app/workbench_helpers.h"
#include "tests/support/scoped_cache_home.h"
#include "tests/support/temp_dir.h"
#include "widgets/cutting_plane_panel.h"
#include "widgets/render_panel.h"
#include "widgets/silhouette_view.h"
#include "workbench/isovalue_session.h"
#include "workbench/member_selection.h"

using namespace ensil;

TEST(MainWindowRenderDocks, PanelsAndKeysChangeWhatTheViewDraws) {
    const test::ScopedCacheHome cache;
    app::MainWindow window;
    ASSERT_TRUE(test::showActiveWorkbench(window, {1000, 700}))
        << "shortcuts need an active window";
    ASSERT_TRUE(
        test::loadDemoAndWait(window, {.members = 6, .nx = 64, .ny = 32, .nz = 8, .seed = 4}));
    gl::Renderer& renderer = window.view()->renderer();

    // Keys 1 to 4 switch the mode, as the panel does.
    window.view()->setFocus();
    ASSERT_TRUE(test::pressKey(window, window.view(), Qt::Key_2));
    EXPECT_EQ(renderer.settings().mode, gl::RenderMode::Spaghetti);
    window.renderPanel()->setMode(gl::RenderMode::Surfaces);
    EXPECT_EQ(renderer.settings().mode, gl::RenderMode::Surfaces);

    // The removal range was taken from the meshes: its top is their largest outlyingness.
    auto* removalMax = window.renderPanel()->findChild<QDoubleSpinBox*>("removal_max");
    ASSERT_NE(removalMax, nullptr);
    EXPECT_GT(removalMax->maximum(), 0.0);
    EXPECT_EQ(removalMax->suffix(), QStringLiteral(" (m s\u207b\u00b9)\u00b2")) << "units squared";

    // A horizontal plane at the 500 hPa level, typed in hPa, lands at that level's height.
    ui::CuttingPlanePanel& plane = *window.cuttingPlanePanel();
    plane.setOrientation(ui::CuttingPlanePanel::AlongZ);
    plane.findChild<QDoubleSpinBox*>("dataValue")->setValue(500.0);
    ASSERT_TRUE(
        test::pressKey(window, window.view(), Qt::Key_P, Qt::ControlModifier | Qt::ShiftModifier));
    const data::DisplayFrame& frame = renderer.frame();
    const data::Grid& grid = window.overview()->ensemble->grid;
    const float z500 = frame.toDisplay({grid.x().front(), grid.y().front(), 500.0}).z;
    EXPECT_TRUE(renderer.settings().plane.enabled);
    EXPECT_NEAR(renderer.settings().plane.offset, z500, 0.002F);

    // Stretching the vertical keeps the plane at 500 hPa.
    window.renderPanel()->findChild<QDoubleSpinBox*>("vertical_exaggeration")->setValue(2.0);
    const float stretched =
        renderer.frame().toDisplay({grid.x().front(), grid.y().front(), 500.0}).z;
    EXPECT_NEAR(stretched, 2.0F * z500, 1e-4F);
    EXPECT_NEAR(renderer.settings().plane.offset, stretched, 0.004F);
    EXPECT_NEAR(plane.dataPosition(), 500.0, 2.0);
}

TEST(MainWindowRenderDocks, TheLastRenderingSettingsComeBackNextTime) {
    QSettings().remove(QStringLiteral("rendering"));
    {
        app::MainWindow window;
        window.renderPanel()->setMode(gl::RenderMode::Spaghetti);
        window.renderPanel()->findChild<QDoubleSpinBox*>("thickness")->setValue(0.02);
        window.close();  // what a user does; remembers the settings
    }
    app::MainWindow again;
    EXPECT_EQ(again.view()->renderer().settings().mode, gl::RenderMode::Spaghetti);
    EXPECT_FLOAT_EQ(again.view()->renderer().settings().thickness, 0.02F);
    session::SessionState shown;
    again.renderPanel()->applyTo(shown);
    EXPECT_EQ(shown.render.mode, gl::RenderMode::Spaghetti) << "the panel shows what is used";
    QSettings().remove(QStringLiteral("rendering"));
}

TEST(MainWindowRenderDocks, LowerResolutionWhileMovingIsAViewOptionRememberedNextTime) {
    QSettings().remove(QStringLiteral("view/adaptiveResolution"));
    const auto findOption = [](app::MainWindow& window) -> QAction* {
        for (QAction* action : window.findChildren<QAction*>()) {
            if (action->text() == QLatin1String("Lower Resolution While &Moving")) return action;
        }
        return nullptr;
    };
    {
        app::MainWindow window;
        QAction* option = findOption(window);
        ASSERT_NE(option, nullptr);
        EXPECT_TRUE(option->isChecked()) << "on by default";
        EXPECT_TRUE(window.view()->adaptiveResolution());
        option->setChecked(false);
        EXPECT_FALSE(window.view()->adaptiveResolution());
    }
    app::MainWindow again;
    QAction* option = findOption(again);
    ASSERT_NE(option, nullptr);
    EXPECT_FALSE(option->isChecked());
    EXPECT_FALSE(again.view()->adaptiveResolution());
    QSettings().remove(QStringLiteral("view/adaptiveResolution"));
}

TEST(MainWindowRenderDocks, DraggingThePlaneSliderDrawsLikeCameraMotion) {
    app::MainWindow window;
    auto* position = window.findChild<ui::CuttingPlanePanel*>()->findChild<QSlider*>();
    ASSERT_NE(position, nullptr);
    ui::SilhouetteView* view = window.view();
    EXPECT_FALSE(view->inMotion());
    position->setSliderDown(true);  // what a press on the handle does
    EXPECT_TRUE(view->inMotion());
    position->setSliderDown(false);
    EXPECT_FALSE(view->inMotion()) << "the frame after the drag is a still one";
}

TEST(MainWindowRenderDocks, TheCutFaceShowsTheFieldChosenInThePlanePanelAndTheMemberInFocus) {
    const test::ScopedCacheHome cache;
    app::MainWindow window;
    ASSERT_TRUE(test::showActiveWorkbench(window, {1000, 700}));
    ASSERT_TRUE(
        test::loadDemoAndWait(window, {.members = 6, .nx = 48, .ny = 24, .nz = 8, .seed = 4}));
    gl::Renderer& renderer = window.view()->renderer();
    ui::CuttingPlanePanel& plane = *window.cuttingPlanePanel();
    auto* fill = plane.findChild<QComboBox*>("fill");
    ASSERT_NE(fill, nullptr);
    EXPECT_FALSE(renderer.sectionShown());

    // Choosing a fill turns the cut on and fills the face, with its colour bar.
    fill->setCurrentIndex(static_cast<int>(gl::SectionField::StandardDeviation));
    QCoreApplication::processEvents();
    EXPECT_TRUE(renderer.settings().plane.enabled);
    ASSERT_TRUE(renderer.sectionShown());
    EXPECT_EQ(renderer.sectionVolume().caption(),
              QStringLiteral("section: standard deviation of wind_speed [m s\u207b\u00b9]"));

    // A member section shows the selected member, else the one last hovered.
    fill->setCurrentIndex(static_cast<int>(gl::SectionField::Member));
    QCoreApplication::processEvents();
    EXPECT_FALSE(renderer.sectionShown()) << "no member in focus yet";
    workbench::MemberSelection& selection = *window.memberSelection();
    selection.setHovered(2);
    selection.setHovered(-1);  // the cursor moves on, to the section
    const data::Ensemble& e = *window.overview()->ensemble;
    ASSERT_TRUE(renderer.sectionShown());
    EXPECT_EQ(renderer.sectionVolume().quantity,
              QString::fromStdString(e.members[2].name + ": wind_speed"));
    EXPECT_EQ(renderer.sectionVolume().values[100], e.members[2].values[100]);
    selection.click({4}, Qt::NoModifier);
    EXPECT_EQ(renderer.sectionVolume().quantity,
              QString::fromStdString(e.members[4].name + ": wind_speed"));

    // The probability of exceeding the isovalue shown.
    fill->setCurrentIndex(static_cast<int>(gl::SectionField::Probability));
    QCoreApplication::processEvents();
    EXPECT_TRUE(renderer.sectionVolume().quantity.startsWith("P(wind_speed > "));
}

TEST(MainWindowRenderDocks, TheContextSurfacesAreMadeOnlyWhileTheViewDrawsThem) {
    // The band's surfaces and P = 0.5 cost most of a summary's time and are drawn only on
    // request: the surfaces of a new isovalue come without them, and get them once the band is
    // switched on (kept with the result), and so does the next isovalue.
    const test::ScopedCacheHome cache;
    app::MainWindow window;
    ASSERT_TRUE(test::showWorkbench(window, {1000, 700}));
    ASSERT_TRUE(
        test::loadDemoAndWait(window, {.members = 8, .nx = 48, .ny = 40, .nz = 12, .seed = 3}));
    workbench::IsovalueSession& session = *window.isovalueSession();
    gl::Renderer& renderer = window.view()->renderer();
    ASSERT_NE(session.result(), nullptr);
    EXPECT_FALSE(session.result()->contextSurfaces);
    EXPECT_TRUE(renderer.meshes()->bandOuter.vertices.empty()) << "not made while not drawn";
    EXPECT_TRUE(renderer.meshes()->probability.vertices.empty());
    EXPECT_FALSE(session.result()->depth.empty()) << "the boxplot's figures always are";
    ASSERT_NE(session.result()->exceedance, nullptr);

    auto* band = window.renderPanel()->findChild<QCheckBox*>("band");
    ASSERT_NE(band, nullptr);
    band->setChecked(true);
    ASSERT_TRUE(QTest::qWaitFor([&] { return session.result()->contextSurfaces; }, 60000));
    const auto withBand = renderer.meshes();
    EXPECT_EQ(withBand, session.result()->meshes) << "drawn";
    EXPECT_FALSE(withBand->bandOuter.vertices.empty());
    EXPECT_FALSE(withBand->bandInner.vertices.empty());
    EXPECT_FALSE(withBand->probability.vertices.empty());
    // The same surfaces as a job that makes everything at once.
    engine::IsovalueJobInput input;
    input.ensemble = window.overview()->ensemble.get();
    input.moments = window.overview()->moments.get();
    input.options.isovalue = withBand->isovalue;
    const engine::IsovalueOutcome all = engine::runIsovalueJob(input);
    EXPECT_EQ(withBand->bandOuter.indices, all.meshes.bandOuter.indices);
    EXPECT_EQ(withBand->probability.indices, all.meshes.probability.indices);
    EXPECT_EQ(withBand->members.size(), all.meshes.members.size());

    // Another isovalue while the band is on: made with it.
    QSignalSpy built(&session, &workbench::IsovalueSession::finished);
    session.setIsovalue(withBand->isovalue * 1.1F, 1.0F);
    ASSERT_TRUE(built.wait(60000));
    EXPECT_TRUE(session.result()->contextSurfaces);
    EXPECT_FALSE(renderer.meshes()->bandOuter.vertices.empty());
}

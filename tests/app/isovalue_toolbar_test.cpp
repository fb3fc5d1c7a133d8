// The isovalue control in the workbench: it gets the loaded variable's histogram, and a value
// committed on it rebuilds the surfaces in the background while the previous ones stay shown.
#include <gtest/gtest.h>

#include <QSignalSpy>
#include <QSlider>
#include <QTest>

#include "app/isovalue_session.h"
#include "app/main_window.h"
#include "tests/support/scoped_cache_home.h"
#include "widgets/histogram_strip.h"
#include "widgets/isovalue_control.h"
#include "widgets/render_toolbar.h"
#include "widgets/silhouette_view.h"

using namespace ensil;
using ensil::ui::IsovalueControl;

TEST(IsovalueToolbar, ShowsTheHistogramAndKeepsTheLastSurfacesUntilTheNewOnesAreReady) {
    const test::ScopedCacheHome cache;
    app::MainWindow window;
    window.resize(1000, 700);
    window.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
    QSignalSpy loaded(&window, &app::MainWindow::ensembleLoaded);
    QSignalSpy built(window.isovalueSession(), &app::IsovalueSession::finished);
    window.loadDemo({.members = 6, .nx = 48, .ny = 24, .nz = 8, .seed = 4});
    ASSERT_TRUE(loaded.wait(30000));
    ui::IsovalueControl* control = window.renderToolbar()->isovalueControl();
    const auto& stats = window.overview()->statistics;
    EXPECT_EQ(control->histogram()->counts(), stats.histogram);
    EXPECT_DOUBLE_EQ(control->minimum(), stats.minimum);
    EXPECT_DOUBLE_EQ(control->maximum(), stats.maximum);
    ASSERT_TRUE(built.count() > 0 || built.wait(60000));
    const auto first = window.view()->renderer().meshes();
    ASSERT_NE(first, nullptr);

    // Dragging alone builds nothing; the release does, and until it is done the old surfaces
    // stay on screen.
    QSlider* slider = control->slider();
    built.clear();
    QSignalSpy started(window.isovalueSession(), &app::IsovalueSession::started);
    slider->setSliderDown(true);
    slider->setSliderPosition(IsovalueControl::kSliderSteps / 2);
    EXPECT_EQ(started.count(), 0);
    slider->setSliderDown(false);
    EXPECT_EQ(started.count(), 1);
    // The result comes back through the event loop, so it cannot have replaced the old one yet.
    EXPECT_EQ(window.view()->renderer().meshes(), first) << "the last result stays until then";
    ASSERT_TRUE(built.wait(60000));
    const auto second = window.view()->renderer().meshes();
    ASSERT_NE(second, first);
    EXPECT_NEAR(second->isovalue, control->value(), 1e-3);
    EXPECT_NEAR(control->value(), 0.5 * (stats.minimum + stats.maximum),
                (stats.maximum - stats.minimum) / 1000.0);
}

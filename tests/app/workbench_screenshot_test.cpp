// Screenshots of the whole workbench at 1600 x 1000, with the demo and with a real file: kept in
// test-output/ to be looked at, and checked for a drawn view. The window is grabbed with
// QWidget::grab and the 3D view's own frame (which has the labels and legend QWidget::grab
// leaves out) drawn over it; grabbing the screen instead would catch the windows of tests that
// run beside this one.
#include <gtest/gtest.h>

#include <QCheckBox>
#include <QPainter>
#include <QSignalSpy>
#include <QTest>

#include "app/main_window.h"
#include "tests/app/workbench_helpers.h"
#include "tests/support/image_compare.h"
#include "tests/support/scoped_cache_home.h"
#include "widgets/render_panel.h"
#include "widgets/silhouette_view.h"
#include "workbench/isovalue_session.h"

using namespace ensil;

namespace {
// Distinct colours in the view's part of the screenshot: a drawn scene has hundreds.
int coloursIn(const QImage& image, const QRect& area) {
    QSet<QRgb> colours;
    for (int y = area.top(); y <= area.bottom(); y += 3) {
        for (int x = area.left(); x <= area.right(); x += 3) colours.insert(image.pixel(x, y));
    }
    return static_cast<int>(colours.size());
}

QImage screenshot(app::MainWindow& window) {
    QImage shot = window.grab().toImage();
    QPainter painter(&shot);
    const QPoint at = window.view()->mapTo(&window, QPoint(0, 0));
    painter.drawImage(QRect(at, window.view()->size()), window.view()->grabFramebuffer());
    return shot;
}

// Checks that the view was drawn and keeps the screenshot as a test artifact.
void checkAndKeep(app::MainWindow& window, const QString& name) {
    const QImage shot = screenshot(window);
    ASSERT_EQ(shot.size(), QSize(1600, 1000));
    const QRect view(window.view()->mapTo(&window, QPoint(0, 0)), window.view()->size());
    EXPECT_GT(coloursIn(shot, view), 200);
    shot.save(test::testOutputDir() + "/" + name);
}
}  // namespace

TEST(WorkbenchScreenshot, TheDemo) {
    const test::ScopedCacheHome cache;
    app::MainWindow window;
    ASSERT_TRUE(test::showWorkbench(window, {1600, 1000}));
    ASSERT_TRUE(
        test::loadDemoAndWait(window, {.members = 30, .nx = 128, .ny = 64, .nz = 16, .seed = 1}));
    checkAndKeep(window, QStringLiteral("workbench_demo_1600x1000.png"));
}

TEST(WorkbenchScreenshot, Era5Temperature) {
    const test::ScopedCacheHome cache;
    app::MainWindow window;
    ASSERT_TRUE(test::showWorkbench(window, {1600, 1000}));
    QSignalSpy built(window.isovalueSession(), &workbench::IsovalueSession::finished);
    data::DataSelection selection;
    selection.paths = {ENSIL_SHARED_DATA_DIR "/era5_eda_members.nc"};
    selection.variable = "t";
    window.openFiles(selection);
    ASSERT_TRUE(built.wait(120000));
    checkAndKeep(window, QStringLiteral("workbench_era5_1600x1000.png"));
}

TEST(WorkbenchScreenshot, Era5TemperatureWithTheContourBoxplotsBand) {
    // The band's surfaces are made when it is switched on (not with every isovalue): once made,
    // the view draws them, a translucent envelope round the members.
    const test::ScopedCacheHome cache;
    app::MainWindow window;
    ASSERT_TRUE(test::showWorkbench(window, {1600, 1000}));
    workbench::IsovalueSession& session = *window.isovalueSession();
    QSignalSpy built(&session, &workbench::IsovalueSession::finished);
    data::DataSelection selection;
    selection.paths = {ENSIL_SHARED_DATA_DIR "/era5_eda_members.nc"};
    selection.variable = "t";
    window.openFiles(selection);
    ASSERT_TRUE(built.wait(120000));
    ASSERT_FALSE(session.result()->contextSurfaces);
    const QImage without = window.view()->grabFramebuffer();

    auto* band = window.renderPanel()->findChild<QCheckBox*>("band");
    ASSERT_NE(band, nullptr);
    band->setChecked(true);
    ASSERT_TRUE(QTest::qWaitFor([&] { return session.result()->contextSurfaces; }, 60000));
    ASSERT_FALSE(window.view()->renderer().meshes()->bandOuter.vertices.empty());
    const QImage with = window.view()->grabFramebuffer();
    ASSERT_EQ(with.size(), without.size());
    int changed = 0;
    for (int y = 0; y < with.height(); y += 2) {
        for (int x = 0; x < with.width(); x += 2)
            changed += with.pixel(x, y) != without.pixel(x, y);
    }
    EXPECT_GT(changed, with.width() * with.height() / 400) << "the band is drawn";
    checkAndKeep(window, QStringLiteral("workbench_era5_band_1600x1000.png"));
}

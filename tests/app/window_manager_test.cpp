// The workbench under a real window manager (tests/support/with-window-manager.sh runs this
// suite on a virtual display of its own with openbox): what only happens when a window
// manager, not the program, decides a window's size and state, such as maximising.
#include <gtest/gtest.h>

#include <QGuiApplication>
#include <QScreen>
#include <QSettings>
#include <QSignalSpy>
#include <QTest>

#include "app/main_window.h"
#include "tests/app/workbench_helpers.h"
#include "tests/support/scoped_cache_home.h"
#include "tests/support/temp_dir.h"
#include "workbench/member_selection.h"

using namespace ensil;

namespace {
constexpr data::DemoEnsembleParams kSmallDemo{.members = 6, .nx = 64, .ny = 32, .nz = 8, .seed = 5};
constexpr int kWaitMs = 120000;

// Whether the window manager has maximised the window: the state alone is what Qt asked for;
// the size is what the window manager did.
bool maximisedByTheWindowManager(const QWidget& window) {
    const QRect available = window.screen()->availableGeometry();
    return window.isMaximized() && window.width() >= available.width() - 50 &&
           window.height() >= available.height() - 100;
}
}  // namespace

// Issue 37: `ensil PROJECT.ensil` (a double-click on a project) crashed with SIGSEGV in
// QLayoutPrivate::doResize, every time, once the remembered settings held a maximised window
// and the project its layout block: the project's layout was restored into the shown window
// while the remembered one still waited for the window manager to maximise it.
TEST(WindowManager, AProjectOpensFromTheCommandLineOverAMaximisedRememberedWindow) {
    test::ScopedCacheHome cache;
    test::TempDir dir;
    const QString path = QString::fromStdString(dir.file("maximised.ensil"));
    {
        app::MainWindow window;
        window.showMaximized();
        ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
        ASSERT_TRUE(QTest::qWaitFor([&] { return maximisedByTheWindowManager(window); }, kWaitMs))
            << "the window manager did not maximise the window (is one running?): "
            << window.width() << " x " << window.height();
        ASSERT_TRUE(test::loadDemoAndWait(window, kSmallDemo));
        QString error;
        ASSERT_TRUE(window.saveProjectTo(path, &error)) << error.toStdString();
        window.close();  // remembers the maximised window and its layout, as on quitting
    }
    ASSERT_TRUE(QSettings().contains(QStringLiteral("window/state")));

    app::MainWindow window;
    QSignalSpy opened(&window, &app::MainWindow::projectOpened);
    data::DataSelection selection;
    selection.paths = {path.toStdString()};
    window.showAndOpen(selection);  // what main() does with `ensil maximised.ensil`
    ASSERT_TRUE(opened.count() > 0 || opened.wait(kWaitMs));
    EXPECT_TRUE(QTest::qWaitFor([&] { return maximisedByTheWindowManager(window); }, kWaitMs))
        << "the remembered maximised window comes back maximised: " << window.width() << " x "
        << window.height();
    EXPECT_EQ(window.memberSelection()->memberCount(), 6);
}

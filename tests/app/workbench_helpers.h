// What most workbench tests start with: the window shown at a size, and the demo loaded with its
// first isovalue's surfaces built.
#pragma once

#include <gtest/gtest.h>

#include <QApplication>
#include <QSignalSpy>
#include <QSize>
#include <QTest>

#include "app/main_window.h"
#include "data/demo_ensemble.h"
#include "tests/support/scoped_cache_home.h"
#include "workbench/isovalue_session.h"

namespace ensil::test {

// Shows the window at this size; false when it never reached the screen.
[[nodiscard]] inline bool showWorkbench(app::MainWindow& window, QSize size) {
    window.resize(size);
    window.show();
    return QTest::qWaitForWindowExposed(&window);
}

// Shows the window at this size and makes it the active one, which keyboard shortcuts need;
// false when it never became active.
[[nodiscard]] inline bool showActiveWorkbench(app::MainWindow& window, QSize size) {
    if (!showWorkbench(window, size)) return false;
    window.activateWindow();
    return QTest::qWaitForWindowActive(&window);
}

// Clicks a key on a widget of the window as a user would, the window made active again first
// when it is not: shortcuts reach only the active window, and a test running beside this one
// on the same virtual display may have taken that since (a key was then lost). False when the
// window never became active.
[[nodiscard]] inline bool pressKey(app::MainWindow& window, QWidget* target, Qt::Key key,
                                   Qt::KeyboardModifiers modifiers = Qt::NoModifier) {
    if (QApplication::activeWindow() != &window) {
        window.activateWindow();
        if (!QTest::qWaitForWindowActive(&window)) return false;
    }
    QTest::keyClick(target, key, modifiers);
    return true;
}

// Loads the demo and waits until its first surfaces are built; false when they never came.
[[nodiscard]] inline bool loadDemoAndWait(app::MainWindow& window,
                                          const data::DemoEnsembleParams& params,
                                          int timeoutMs = 120000) {
    QSignalSpy built(window.isovalueSession(), &workbench::IsovalueSession::finished);
    window.loadDemo(params);
    return built.count() > 0 || built.wait(timeoutMs);
}

// Opens a project and waits until it is applied (data loaded, surfaces built, members shown as
// saved); false when it was refused or never came.
[[nodiscard]] inline bool openProjectAndWait(app::MainWindow& window, const QString& path,
                                             int timeoutMs = 60000) {
    QSignalSpy opened(&window, &app::MainWindow::projectOpened);
    return window.openProject(path) && (opened.count() > 0 || opened.wait(timeoutMs));
}

// A test with the workbench shown and a small demo (6 members, 64 x 32 x 8) loaded, its mesh
// cache in a folder of its own.
class SmallDemoWorkbench : public ::testing::Test {
protected:
    static constexpr data::DemoEnsembleParams kSmallDemo{
        .members = 6, .nx = 64, .ny = 32, .nz = 8, .seed = 5};
    void SetUp() override {
        ASSERT_TRUE(showWorkbench(window, {900, 600}));
        ASSERT_TRUE(loadDemoAndWait(window, kSmallDemo));
    }
    ScopedCacheHome cache;
    app::MainWindow window;
};

}  // namespace ensil::test

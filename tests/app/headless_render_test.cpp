// `ensil render` on a machine with no display server at all, as on a batch node: the real
// executable, started without DISPLAY or WAYLAND_DISPLAY, draws through Mesa's EGL surfaceless
// platform, and its picture matches the one drawn under the test's X server; so does one
// started with a DISPLAY that does not answer. Also the messages and exit status when EGL cannot
// render without a display either, and when the workbench is started with no display.
#include <gtest/gtest.h>

#include <QImage>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QProcessEnvironment>
#include <map>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "engine/session_renderer.h"
#include "tests/support/image_compare.h"
#include "tests/support/temp_dir.h"

using namespace ensil;

namespace {
// This process's environment as on a machine with no display server.
QProcessEnvironment withoutDisplay() {
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    for (const char* variable : {"DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM"}) {
        environment.remove(QString::fromLatin1(variable));
    }
    return environment;
}

struct RenderRun {
    int exitCode = -1;
    QJsonObject json;
    QString errors;
};

// Runs `ensil render` on era5_eda_members.nc into `png`, with or without a display server.
RenderRun renderEra5(const QString& png, bool withDisplay, const QString& eglPlatform = {},
                     const QString& staleDisplay = {}) {
    QProcessEnvironment environment =
        withDisplay ? QProcessEnvironment::systemEnvironment() : withoutDisplay();
    if (!staleDisplay.isEmpty()) environment.insert(QStringLiteral("DISPLAY"), staleDisplay);
    if (!eglPlatform.isEmpty()) environment.insert(QStringLiteral("EGL_PLATFORM"), eglPlatform);
    const QString era5 = QStringLiteral(ENSIL_SHARED_DATA_DIR) + "/era5_eda_members.nc";
    QProcess process;
    process.setProcessEnvironment(environment);
    process.start(QStringLiteral(ENSIL_EXECUTABLE),
                  {"render", era5, "--var", "t", "--iso", "260", "--out", png, "--size", "320x240",
                   "--frames", "1", "--clusters", "3", "--no-cache", "--json"});
    RenderRun run;
    if (!process.waitForFinished(120000)) return run;
    run.exitCode = process.exitCode();
    run.json = QJsonDocument::fromJson(process.readAllStandardOutput()).object();
    run.errors = QString::fromLocal8Bit(process.readAllStandardError());
    return run;
}
}  // namespace

TEST(HeadlessRender, DrawsWithNoDisplayServerLikeUnderOne) {
    test::TempDir dir;
    const QString headlessPng = QString::fromStdString(dir.file("headless.png"));
    const QString displayPng = QString::fromStdString(dir.file("display.png"));
    const RenderRun headless = renderEra5(headlessPng, false);
    ASSERT_EQ(headless.exitCode, 0) << headless.errors.toStdString();
    EXPECT_EQ(headless.json["display"].toString(), QStringLiteral("none (EGL surfaceless)"));
    EXPECT_FALSE(headless.json["gl_renderer"].toString().isEmpty());
    EXPECT_FALSE(headless.errors.contains(QLatin1String("eglconvenience")))
        << "the stand-in framebuffer's complaint is dropped: " << headless.errors.toStdString();

    const RenderRun display = renderEra5(displayPng, true);
    ASSERT_EQ(display.exitCode, 0) << display.errors.toStdString();
    EXPECT_NE(display.json["display"].toString(), QStringLiteral("none (EGL surfaceless)"));

    const QImage withoutDisplay(headlessPng);
    const QImage withDisplay(displayPng);
    ASSERT_EQ(withoutDisplay.size(), QSize(320, 240));
    QImage background(withoutDisplay.size(), withoutDisplay.format());
    background.fill(withoutDisplay.pixel(0, withoutDisplay.height() / 2));
    EXPECT_GT(test::differingFraction(withoutDisplay, background, 8), 0.05)
        << "the picture holds the data, not only the background";
    EXPECT_LT(test::differingFraction(withoutDisplay, withDisplay, 8), 0.002)
        << "the same picture as under the display server";
    withoutDisplay.save(test::testOutputDir() + "/headless_render_era5.png");
}

TEST(HeadlessRender, ADisplayThatDoesNotAnswerIsPassedOverForEgl) {
    // A DISPLAY left behind by an ssh -X session that ended: nothing listens at :987.
    test::TempDir dir;
    const QString png = QString::fromStdString(dir.file("stale.png"));
    const RenderRun run = renderEra5(png, false, {}, QStringLiteral(":987"));
    ASSERT_EQ(run.exitCode, 0) << run.errors.toStdString();
    EXPECT_EQ(run.json["display"].toString(), QStringLiteral("none (EGL surfaceless)"));
    EXPECT_EQ(QImage(png).size(), QSize(320, 240));
}

TEST(HeadlessRender, SaysWhatToDoWhenEglCannotRenderWithoutADisplay) {
    test::TempDir dir;
    // EGL's X11 platform needs the display server that is not there.
    const RenderRun run = renderEra5(QString::fromStdString(dir.file("none.png")), false, "x11");
    EXPECT_EQ(run.exitCode, 4);
    EXPECT_TRUE(run.errors.contains(QLatin1String("no display server")))
        << run.errors.toStdString();
    EXPECT_TRUE(run.errors.contains(QLatin1String("xvfb-run -a ensil render")))
        << run.errors.toStdString();
}

TEST(HeadlessRender, TheWorkbenchSaysItNeedsADisplayServer) {
    for (const QString& display : {QString(), QStringLiteral(":987")}) {
        QProcessEnvironment environment = withoutDisplay();
        if (!display.isEmpty()) environment.insert(QStringLiteral("DISPLAY"), display);
        QProcess process;
        process.setProcessEnvironment(environment);
        process.start(QStringLiteral(ENSIL_EXECUTABLE), QStringList{});
        ASSERT_TRUE(process.waitForFinished(60000));
        const QString errors = QString::fromLocal8Bit(process.readAllStandardError());
        EXPECT_EQ(process.exitStatus(), QProcess::NormalExit) << "no abort inside Qt";
        EXPECT_EQ(process.exitCode(), 4);
        EXPECT_TRUE(errors.contains(QLatin1String("the workbench needs a display server")))
            << errors.toStdString();
        const QString reason = display.isEmpty()
                                   ? QStringLiteral("DISPLAY and WAYLAND_DISPLAY are empty")
                                   : QStringLiteral("':987' (DISPLAY) does not answer");
        EXPECT_TRUE(errors.contains(reason)) << errors.toStdString();
        EXPECT_TRUE(errors.contains(QLatin1String("xvfb-run -a ensil"))) << errors.toStdString();
    }
}

// `ensil render` shows how far it is from what renderSession reports: reading the files, then
// preprocessing the isovalue, each run through to the end.
TEST(HeadlessRender, ReportsReadingThenPreprocessingEachToTheEnd) {
    session::SessionState state;
    state.data.paths = {std::string(ENSIL_SHARED_DATA_DIR "/era5_eda_members.nc")};
    state.data.variable = "t";
    state.isovalue = 260.0F;
    state.clusters = 3;
    engine::RenderRequest request;
    request.width = 160;
    request.height = 120;
    request.useCache = false;
    std::mutex mutex;
    std::vector<std::pair<std::string, double>> reports;
    request.progress = [&](const std::string& stage, double fraction) {
        const std::lock_guard lock(mutex);
        reports.emplace_back(stage, fraction);
    };
    const engine::RenderOutcome outcome = engine::renderSession(state, request);
    ASSERT_FALSE(outcome.image.isNull());

    std::vector<std::string> stages;
    std::map<std::string, double> last;
    for (const auto& [stage, fraction] : reports) {
        if (stages.empty() || stages.back() != stage) stages.push_back(stage);
        EXPECT_GE(fraction, last[stage]) << stage << " went back";
        last[stage] = fraction;
    }
    EXPECT_EQ(stages, (std::vector<std::string>{"reading", "preprocessing"}));
    EXPECT_DOUBLE_EQ(last["reading"], 1.0);
    EXPECT_DOUBLE_EQ(last["preprocessing"], 1.0);
}

// Where XDG_RUNTIME_DIR is unset (containers, CI, cron), a command's stderr holds only what
// ensil says: no "QStandardPaths: XDG_RUNTIME_DIR not set" line from Qt at every start.
TEST(HeadlessRender, SaysNothingOfAMissingRuntimeFolder) {
    const test::TempDir dir;
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.remove(QStringLiteral("XDG_RUNTIME_DIR"));
    QProcess process;
    process.setProcessEnvironment(environment);
    process.start(QStringLiteral(ENSIL_EXECUTABLE),
                  {"render", "--demo", "--out", QString::fromStdString(dir.file("demo.png")),
                   "--size", "160x100", "--no-cache"});
    ASSERT_TRUE(process.waitForFinished(120000));
    const QString errors = QString::fromLocal8Bit(process.readAllStandardError());
    EXPECT_EQ(process.exitCode(), 0) << errors.toStdString();
    EXPECT_FALSE(errors.contains(QLatin1String("XDG_RUNTIME_DIR"))) << errors.toStdString();
}

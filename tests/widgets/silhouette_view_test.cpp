#include "widgets/silhouette_view.h"

#include <gtest/gtest.h>

#include <QApplication>
#include <QMouseEvent>
#include <QTest>
#include <QWheelEvent>

#include "data/demo_ensemble.h"

using namespace ensil;

namespace {
int countNear(const QImage& image, const QColor& colour, int tolerance) {
    int n = 0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const QColor c = image.pixelColor(x, y);
            if (std::abs(c.red() - colour.red()) <= tolerance &&
                std::abs(c.green() - colour.green()) <= tolerance &&
                std::abs(c.blue() - colour.blue()) <= tolerance) {
                ++n;
            }
        }
    }
    return n;
}

class ShownView : public ::testing::Test {
protected:
    void SetUp() override {
        m_view.resize(400, 300);
        const auto demo = data::makeDemoEnsemble({.members = 2, .nx = 16, .ny = 8, .nz = 4});
        m_view.renderer().setGrid(demo.ensemble.grid);
        m_view.show();
        ASSERT_TRUE(QTest::qWaitForWindowExposed(&m_view));
        ASSERT_TRUE(m_view.glError().isEmpty()) << m_view.glError().toStdString();
    }
    void drag(Qt::MouseButton button, QPoint from, QPoint to, Qt::KeyboardModifiers mods = {}) {
        QMouseEvent press(QEvent::MouseButtonPress, from, m_view.mapToGlobal(from), button, button,
                          mods);
        QApplication::sendEvent(&m_view, &press);
        QMouseEvent move(QEvent::MouseMove, to, m_view.mapToGlobal(to), Qt::NoButton, button, mods);
        QApplication::sendEvent(&m_view, &move);
        QMouseEvent release(QEvent::MouseButtonRelease, to, m_view.mapToGlobal(to), button, {},
                            mods);
        QApplication::sendEvent(&m_view, &release);
    }
    ui::SilhouetteView m_view;
};
}  // namespace

TEST_F(ShownView, DrawsTheDataBoxInTheWindow) {
    const QImage image = m_view.grabFramebuffer();
    ASSERT_FALSE(image.isNull());
    const QColor box = QColor::fromRgbF(gl::Renderer::kBoxColor.r, gl::Renderer::kBoxColor.g,
                                        gl::Renderer::kBoxColor.b);
    EXPECT_GT(countNear(image, box, 30), 200) << "the 12 box edges should cover some pixels";
    EXPECT_GT(countNear(image, QColor::fromRgbF(0.11F, 0.12F, 0.14F), 2),
              image.width() * image.height() / 2);
}

TEST_F(ShownView, LeftDragOrbitsShiftDragPansWheelZooms) {
    gl::Camera& cam = m_view.renderer().camera();
    const float azimuth = cam.azimuth();
    drag(Qt::LeftButton, {200, 150}, {250, 150});
    // 50 of the view's 400 pixels: an eighth of the 180 degrees a drag across it turns.
    EXPECT_NEAR(cam.azimuth(), azimuth - 22.5F, 1e-3);

    const glm::vec3 target = cam.target();
    drag(Qt::LeftButton, {200, 150}, {220, 170}, Qt::ShiftModifier);
    EXPECT_NE(cam.target(), target);
    EXPECT_NEAR(cam.azimuth(), azimuth - 22.5F, 1e-3) << "panning must not orbit";

    const float distance = cam.distance();
    QWheelEvent wheel(QPointF(200, 150), m_view.mapToGlobal(QPointF(200, 150)), QPoint(),
                      QPoint(0, 120), Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(&m_view, &wheel);
    EXPECT_NEAR(cam.distance(), distance / 1.12F, 1e-4);
}

TEST_F(ShownView, ResetCameraRestoresTheDefaultView) {
    gl::Camera& cam = m_view.renderer().camera();
    m_view.resetCamera();  // the default view for this window's shape
    const glm::vec3 eye = cam.eye();
    EXPECT_NEAR(cam.azimuth(), gl::Camera::kDefaultAzimuth, 1e-4);
    cam.orbit(100, 40);
    cam.zoom(3.0F);
    m_view.resetCamera();
    EXPECT_NEAR(cam.eye().x, eye.x, 1e-5);
    EXPECT_NEAR(cam.eye().y, eye.y, 1e-5);
    EXPECT_NEAR(cam.eye().z, eye.z, 1e-5);
}

TEST_F(ShownView, PaintsTheAxisLabelsOverTheFrame) {
    const QImage labelled = m_view.grabFramebuffer();
    m_view.renderer().settings().showAxes = false;
    const QImage plain = m_view.grabFramebuffer();
    // Text is light on the dark background: labelled has many more light pixels.
    const auto light = [](const QImage& image) {
        int n = 0;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x) n += image.pixelColor(x, y).lightness() > 160;
        return n;
    };
    EXPECT_GT(light(labelled), light(plain) + 100);
}

TEST(EmptyView, SaysWhatToDoUntilDataArrives) {
    ui::SilhouetteView view;
    view.resize(500, 300);
    view.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&view));
    const auto lightInTheMiddle = [&view] {
        const QImage image = view.grabFramebuffer();
        int n = 0;
        for (int y = image.height() / 3; y < 2 * image.height() / 3; ++y)
            for (int x = 0; x < image.width(); ++x) n += image.pixelColor(x, y).lightness() > 150;
        return n;
    };
    EXPECT_GT(lightInTheMiddle(), 300) << "the hint is written in the middle";
    view.setPlaceholderText(QStringLiteral(" "));
    EXPECT_EQ(lightInTheMiddle(), 0);
}

TEST_F(ShownView, MovingTheCameraOnASlowRendererLowersTheResolutionUntilItStops) {
    // Any frame is slower than a budget of a microsecond: motion must drop the resolution.
    m_view.setMotionFrameBudget(0.001);
    (void)m_view.grabFramebuffer();  // a still frame, timed
    EXPECT_EQ(m_view.renderer().resolutionScale(), 1.0F);

    const QPoint from(200, 150), to(240, 160);
    QMouseEvent press(QEvent::MouseButtonPress, from, m_view.mapToGlobal(from), Qt::LeftButton,
                      Qt::LeftButton, {});
    QApplication::sendEvent(&m_view, &press);
    QMouseEvent move(QEvent::MouseMove, to, m_view.mapToGlobal(to), Qt::NoButton, Qt::LeftButton,
                     {});
    QApplication::sendEvent(&m_view, &move);
    EXPECT_TRUE(m_view.inMotion());
    (void)m_view.grabFramebuffer();
    EXPECT_EQ(m_view.renderer().resolutionScale(), gl::Renderer::kMinimumResolutionScale);
    const glm::ivec2 full(m_view.width() * m_view.devicePixelRatioF(),
                          m_view.height() * m_view.devicePixelRatioF());
    EXPECT_LT(m_view.renderer().sceneSize().x, full.x);

    QMouseEvent release(QEvent::MouseButtonRelease, to, m_view.mapToGlobal(to), Qt::LeftButton, {},
                        {});
    QApplication::sendEvent(&m_view, &release);
    EXPECT_FALSE(m_view.inMotion());
    (void)m_view.grabFramebuffer();
    EXPECT_EQ(m_view.renderer().sceneSize(), full) << "the still frame is full resolution";

    // Wheel turns are motion too, until they pause.
    QWheelEvent wheel(QPointF(200, 150), m_view.mapToGlobal(QPointF(200, 150)), QPoint(),
                      QPoint(0, 120), Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(&m_view, &wheel);
    EXPECT_TRUE(m_view.inMotion());
    (void)m_view.grabFramebuffer();
    EXPECT_LT(m_view.renderer().resolutionScale(), 1.0F);
    EXPECT_TRUE(QTest::qWaitFor([&] { return !m_view.inMotion(); }, 2000));
    (void)m_view.grabFramebuffer();
    EXPECT_EQ(m_view.renderer().sceneSize(), full);
}

TEST_F(ShownView, MotionKeepsFullResolutionWhenFramesAreFastOrTheOptionIsOff) {
    m_view.setMotionFrameBudget(1e9);  // every frame is fast enough
    (void)m_view.grabFramebuffer();
    QMouseEvent press(QEvent::MouseButtonPress, QPoint(200, 150),
                      m_view.mapToGlobal(QPoint(200, 150)), Qt::LeftButton, Qt::LeftButton, {});
    QApplication::sendEvent(&m_view, &press);
    QMouseEvent move(QEvent::MouseMove, QPoint(230, 150), m_view.mapToGlobal(QPoint(230, 150)),
                     Qt::NoButton, Qt::LeftButton, {});
    QApplication::sendEvent(&m_view, &move);
    (void)m_view.grabFramebuffer();
    EXPECT_TRUE(m_view.inMotion());
    EXPECT_EQ(m_view.renderer().resolutionScale(), 1.0F);

    m_view.setMotionFrameBudget(0.001);
    m_view.setAdaptiveResolution(false);
    (void)m_view.grabFramebuffer();
    EXPECT_EQ(m_view.renderer().resolutionScale(), 1.0F) << "switched off by the user";
    m_view.setAdaptiveResolution(true);
    (void)m_view.grabFramebuffer();  // a motion frame at full resolution, timed: too slow
    (void)m_view.grabFramebuffer();
    EXPECT_LT(m_view.renderer().resolutionScale(), 1.0F) << "each slow frame steps down";
}

TEST_F(ShownView, MotionStartsWhereMotionFramesLeftItNotFinerThanAStillFrameSuggests) {
    // Motion frames too slow for the budget step the resolution down to the coarsest.
    m_view.setMotionFrameBudget(0.001);
    (void)m_view.grabFramebuffer();
    m_view.showPassingChange();
    (void)m_view.grabFramebuffer();
    ASSERT_EQ(m_view.renderer().resolutionScale(), gl::Renderer::kMinimumResolutionScale);
    ASSERT_TRUE(QTest::qWaitFor([&] { return !m_view.inMotion(); }, 2000));
    // A still frame that looks fast (as a software renderer's does, its time not shrinking
    // with its pixels) does not undo what motion measured: the next motion frame starts there.
    m_view.setMotionFrameBudget(1e9);
    (void)m_view.grabFramebuffer();
    m_view.showPassingChange();
    (void)m_view.grabFramebuffer();
    EXPECT_EQ(m_view.renderer().resolutionScale(), gl::Renderer::kMinimumResolutionScale);
    // Motion frames measured fast make it finer, one step at a time.
    (void)m_view.grabFramebuffer();
    EXPECT_GT(m_view.renderer().resolutionScale(), gl::Renderer::kMinimumResolutionScale);
}

TEST_F(ShownView, ADragAcrossTheWholeViewTurnsItHalfWayRound) {
    // A 240 px drag once turned the view about 100 degrees and pushed the box off screen.
    gl::Camera& cam = m_view.renderer().camera();
    const float azimuth = cam.azimuth();
    drag(Qt::LeftButton, {0, 150}, {m_view.width(), 150});
    EXPECT_NEAR(std::remainder(azimuth - cam.azimuth() - 180.0F, 360.0F), 0.0F, 1e-3);
}

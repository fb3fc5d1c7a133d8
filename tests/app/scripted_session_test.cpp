// A user's session, scripted with QTest on the real window under Xvfb: start on the demo, change
// the isovalue, cancel a preprocess, pick a member by clicking a pixel of its silhouette, play
// the animation, and take a screenshot, which is checked for content and kept as an artifact
// (test-output/scripted_session.png).
#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QSignalSpy>
#include <QTest>
#include <cmath>

#include "app/main_window.h"
#include "gl/palette.h"
#include "tests/app/workbench_helpers.h"
#include "tests/support/image_compare.h"
#include "tests/support/scoped_cache_home.h"
#include "tests/support/temp_dir.h"
#include "widgets/animation_bar.h"
#include "widgets/render_toolbar.h"
#include "widgets/silhouette_view.h"
#include "workbench/isovalue_session.h"
#include "workbench/member_selection.h"

using namespace ensil;

namespace {
// Types a value into the isovalue box and presses Enter, as a user would.
void typeIsovalue(app::MainWindow& window, double value) {
    QDoubleSpinBox* box = window.renderToolbar()->isovalueBox();
    box->setFocus();
    box->selectAll();
    QTest::keyClicks(box, QString::number(value, 'f', 1));
    QTest::keyClick(box, Qt::Key_Return);
}

// Whether the view's last frame was drawn at the view's full size, which picks draw at.
bool drewFullFrame(ui::SilhouetteView& view) {
    const qreal ratio = view.devicePixelRatioF();
    const glm::ivec2 full(static_cast<int>(std::lround(view.width() * ratio)),
                          static_cast<int>(std::lround(view.height() * ratio)));
    return view.renderer().resolutionScale() == 1.0F && view.renderer().sceneSize() == full;
}
}  // namespace

TEST(ScriptedSession, DemoIsovalueCancelPickAnimateScreenshot) {
    const test::ScopedCacheHome cache;
    app::MainWindow window;
    ASSERT_TRUE(test::showActiveWorkbench(window, {1400, 900}));
    workbench::IsovalueSession& session = *window.isovalueSession();
    QSignalSpy built(&session, &workbench::IsovalueSession::finished);
    QSignalSpy failed(&session, &workbench::IsovalueSession::failed);

    // Start on the demo.
    ASSERT_TRUE(
        test::loadDemoAndWait(window, {.members = 12, .nx = 96, .ny = 48, .nz = 12, .seed = 7}))
        << "the demo's surfaces were not built";
    const auto first = window.view()->renderer().meshes();

    // Change the isovalue: new surfaces at the typed value.
    built.clear();
    typeIsovalue(window, 25.0);
    ASSERT_TRUE(built.wait(120000));
    EXPECT_NEAR(window.view()->renderer().meshes()->isovalue, 25.0F, 0.05F);
    const auto atTwentyFive = window.view()->renderer().meshes();
    EXPECT_NE(atTwentyFive, first);

    // Start another and cancel it with Esc: the surfaces on screen stay.
    typeIsovalue(window, 35.0);
    ASSERT_TRUE(session.isRunning());
    ASSERT_TRUE(test::pressKey(window, &window, Qt::Key_Escape));
    QTRY_VERIFY_WITH_TIMEOUT(failed.count() >= 1, 30000);
    EXPECT_FALSE(session.isRunning());
    EXPECT_EQ(failed.last()[0].toString(), QStringLiteral("Isosurfaces cancelled"));
    EXPECT_EQ(window.view()->renderer().meshes(), atTwentyFive)
        << "cancelling keeps what was shown";

    // Pick a member by clicking a pixel of its silhouette: the first pixel along the view's
    // middle row that the id pass names.
    ui::SilhouetteView& view = *window.view();
    QApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
    QApplication::processEvents();
    ASSERT_TRUE(QTest::qWaitFor([&] { return drewFullFrame(view); }, 60000))
        << "the view was not drawn at its size";
    QPoint onSilhouette(-1, -1);
    int expected = -1;
    for (int y = view.height() / 3; y < 2 * view.height() / 3 && expected < 0; y += 7) {
        for (int x = 0; x < view.width() && expected < 0; x += 3) {
            const gl::PickResult hit = view.pickAt({x, y});
            if (hit.member >= 0) {
                onSilhouette = {x, y};
                expected = hit.member;
            }
        }
    }
    ASSERT_GE(expected, 0) << "no silhouette in the middle of the view";
    workbench::MemberSelection& selection = *window.memberSelection();
    QTest::mouseClick(&view, Qt::LeftButton, {}, onSilhouette);
    EXPECT_EQ(selection.selectedMembers(), QList<int>{expected});
    EXPECT_TRUE(view.renderer().appearances()[static_cast<std::size_t>(expected)].selected)
        << "the picked member is drawn solid";

    // Play the animation (the selection: the picked member), then all members.
    ui::AnimationBar& animation = *window.animationBar();
    animation.setFramesPerSecond(20.0);
    animation.setLoop(false);
    QSignalSpy shown(&animation, &ui::AnimationBar::memberShown);
    animation.playAction()->trigger();
    QTRY_VERIFY_WITH_TIMEOUT(!animation.isPlaying(), 5000);
    ASSERT_GE(shown.count(), 1);
    EXPECT_EQ(shown[0][0].toInt(), expected);
    EXPECT_EQ(view.renderer().animatedMember(), expected);
    ASSERT_TRUE(
        test::pressKey(window, &window, Qt::Key_Escape));  // nothing running: clears the selection
    EXPECT_TRUE(selection.selectedMembers().isEmpty());
    shown.clear();
    animation.playAction()->trigger();
    QTRY_VERIFY_WITH_TIMEOUT(!animation.isPlaying(), 10000);
    EXPECT_EQ(shown.count(), 12) << "every member once";

    // A screenshot at a size of its own, without the UI: the picture has the floor map, the
    // silhouettes in cluster colours and the legend.
    const test::TempDir dir;
    const QString path = QString::fromStdString(dir.file("shot.png"));
    QString error;
    ASSERT_TRUE(window.saveScreenshot(path, &error, QSize(1200, 750))) << error.toStdString();
    const QImage shot(path);
    ASSERT_EQ(shot.size(), QSize(1200, 750));
    int clusterPixels = 0;
    for (int y = 0; y < shot.height(); y += 2) {
        for (int x = 0; x < shot.width(); x += 2) {
            const QColor c = shot.pixelColor(x, y);
            for (int k = 0; k < 5; ++k) {
                const glm::vec3 e = gl::clusterColor(k);
                if (std::abs(c.redF() - e.r) < 0.06 && std::abs(c.greenF() - e.g) < 0.06 &&
                    std::abs(c.blueF() - e.b) < 0.06) {
                    ++clusterPixels;
                }
            }
        }
    }
    EXPECT_GT(clusterPixels, 300) << "silhouettes in cluster colours";
    EXPECT_TRUE(shot.save(test::testOutputDir() + "/scripted_session.png"));
}

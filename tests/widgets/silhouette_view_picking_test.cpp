// The view's mouse picking, end to end through Qt events: a click on a member's silhouette
// reports that member, a click on the background reports -1, a right-drag rubber band
// reports the members inside it, and a resting cursor highlights the member under it.
#include <gtest/gtest.h>

#include <QApplication>
#include <QMouseEvent>
#include <QSignalSpy>
#include <QTest>

#include "tests/gl/sphere_scene.h"
#include "tests/widgets/panel_fixtures.h"
#include "widgets/silhouette_view.h"

using namespace ensil;

namespace {
constexpr glm::vec3 kRed{1, 0.2F, 0.2F};
constexpr glm::vec3 kBlue{0.2F, 0.3F, 1};

class ViewPicking : public ::testing::Test {
protected:
    void SetUp() override {
        m_view.resize(480, 360);
        m_view.show();
        ASSERT_TRUE(QTest::qWaitForWindowExposed(&m_view));
        ASSERT_TRUE(m_view.glError().isEmpty()) << m_view.glError().toStdString();
        // Two spheres side by side (x = 9 and x = 22), seen along +y.
        const data::Ensemble e = test::spheres({{9, 15.5F, 15.5F}, {22, 15.5F, 15.5F}});
        gl::Renderer& r = m_view.renderer();
        r.setGrid(e.grid);
        r.camera().setAngles(-90.0F, 0.0F);
        r.camera().fit(r.frame().center(), 0.45F);
        r.setMeshes(test::meshesOf(e));
        r.setAppearance({{kRed, true, false, 0}, {kBlue, true, false, 1}});
        r.settings().showMean = false;
        m_view.setMemberNames({QStringLiteral("alpha"), QStringLiteral("beta")});
        m_view.update();
        // A frame must have been drawn at the widget's size before picks can be answered.
        (void)m_view.grabFramebuffer();
    }
    // Widget position of grid index (i, j, k).
    QPoint at(glm::vec3 index) {
        gl::Renderer& r = m_view.renderer();
        const glm::vec4 c = r.camera().viewProjection(float(m_view.width()) / m_view.height()) *
                            glm::vec4(r.frame().indexToDisplay(index), 1.0F);
        return {int((c.x / c.w * 0.5F + 0.5F) * m_view.width()),
                int((1.0F - (c.y / c.w * 0.5F + 0.5F)) * m_view.height())};
    }
    void send(QEvent::Type type, Qt::MouseButton button, Qt::MouseButtons buttons, QPoint p,
              Qt::KeyboardModifiers modifiers = {}) {
        QMouseEvent e(type, p, m_view.mapToGlobal(p), button, buttons, modifiers);
        QApplication::sendEvent(&m_view, &e);
    }
    ui::SilhouetteView m_view;
};
}  // namespace

TEST_F(ViewPicking, ClickingASilhouetteReportsItsMemberAndTheBackgroundReportsNone) {
    QSignalSpy clicked(&m_view, &ui::SilhouetteView::memberClicked);
    const QPoint leftRim = at({9 - 7.9F, 15.5F, 15.5F});
    const QPoint rightRim = at({22 + 7.9F, 15.5F, 15.5F});
    QTest::mouseClick(&m_view, Qt::LeftButton, Qt::ShiftModifier, rightRim);
    QTest::mouseClick(&m_view, Qt::LeftButton, {}, leftRim);
    QTest::mouseClick(&m_view, Qt::LeftButton, {}, QPoint(3, 3));
    ASSERT_EQ(clicked.count(), 3);
    EXPECT_EQ(clicked[0][0].toInt(), 1);
    EXPECT_EQ(clicked[0][1].value<Qt::KeyboardModifiers>(), Qt::ShiftModifier);
    EXPECT_EQ(clicked[1][0].toInt(), 0);
    EXPECT_EQ(clicked[2][0].toInt(), -1);
}

TEST_F(ViewPicking, ADragOrbitsAndIsNotAClick) {
    QSignalSpy clicked(&m_view, &ui::SilhouetteView::memberClicked);
    const QPoint rim = at({9 - 7.9F, 15.5F, 15.5F});
    send(QEvent::MouseButtonPress, Qt::LeftButton, Qt::LeftButton, rim);
    send(QEvent::MouseMove, Qt::NoButton, Qt::LeftButton, rim + QPoint(30, 0));
    send(QEvent::MouseButtonRelease, Qt::LeftButton, {}, rim + QPoint(30, 0));
    EXPECT_EQ(clicked.count(), 0);
}

TEST_F(ViewPicking, ARubberBandBrushesTheMembersInsideIt) {
    QSignalSpy brushed(&m_view, &ui::SilhouetteView::membersBrushed);
    // Around the left sphere only, then around both.
    const QPoint a = at({0.5F, 15.5F, 25}), b = at({12, 15.5F, 6});
    send(QEvent::MouseButtonPress, Qt::RightButton, Qt::RightButton, a);
    send(QEvent::MouseMove, Qt::NoButton, Qt::RightButton, b);
    send(QEvent::MouseButtonRelease, Qt::RightButton, {}, b, Qt::ControlModifier);
    const QPoint c = at({31, 15.5F, 6});
    send(QEvent::MouseButtonPress, Qt::RightButton, Qt::RightButton, a);
    send(QEvent::MouseMove, Qt::NoButton, Qt::RightButton, c);
    send(QEvent::MouseButtonRelease, Qt::RightButton, {}, c);
    ASSERT_EQ(brushed.count(), 2);
    EXPECT_EQ(brushed[0][0].value<QList<int>>(), QList<int>{0});
    EXPECT_EQ(brushed[0][1].value<Qt::KeyboardModifiers>(), Qt::ControlModifier);
    EXPECT_EQ(brushed[1][0].value<QList<int>>(), (QList<int>{0, 1}));
}

TEST_F(ViewPicking, ARestingCursorHighlightsTheMemberUnderIt) {
    QSignalSpy hovered(&m_view, &ui::SilhouetteView::memberHovered);
    const QPoint rim = at({22 + 7.9F, 15.5F, 15.5F});
    const QImage before = m_view.grabFramebuffer();
    test::moveMouse(&m_view, rim);  // not the display's real pointer: tests share the display
    ASSERT_TRUE(hovered.wait(2000));
    EXPECT_EQ(hovered.last()[0].toInt(), 1);
    EXPECT_EQ(m_view.renderer().highlightedMember(), 1);
    // The highlighted member is drawn lighter than before: its red and green rise.
    const QImage after = m_view.grabFramebuffer();
    int redBefore = 0, redAfter = 0;
    for (int dy = -3; dy <= 3; ++dy)
        for (int dx = -3; dx <= 3; ++dx) {
            redBefore += before.pixelColor(rim + QPoint(dx, dy)).red();
            redAfter += after.pixelColor(rim + QPoint(dx, dy)).red();
        }
    EXPECT_GT(redAfter, redBefore + 100) << "the hovered silhouette should be mixed toward white";

    test::moveMouse(&m_view, QPoint(3, 3));
    ASSERT_TRUE(hovered.wait(2000));
    EXPECT_EQ(hovered.last()[0].toInt(), -1);
    EXPECT_EQ(m_view.renderer().highlightedMember(), -1);
}

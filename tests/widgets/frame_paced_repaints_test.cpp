// The toolbar's repaints held back while the view follows a drag, and drawn with its frames.
#include "widgets/frame_paced_repaints.h"

#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QHBoxLayout>
#include <QOpenGLFunctions>
#include <QOpenGLWidget>
#include <QSignalSpy>
#include <QSlider>
#include <QTest>

using namespace ensil;
using namespace std::chrono_literals;

namespace {
class ClearedView : public QOpenGLWidget {
protected:
    void paintGL() override {
        context()->functions()->glClearColor(0.2F, 0.3F, 0.4F, 1.0F);
        context()->functions()->glClear(GL_COLOR_BUFFER_BIT);
    }
};

// Counts the paint events a widget receives.
class PaintCounter : public QObject {
public:
    int paints = 0;

protected:
    bool eventFilter(QObject*, QEvent* event) override {
        if (event->type() == QEvent::Paint) ++paints;
        return false;
    }
};

// A window of a view and a slider beside it, shown and composed once.
class PacedWindow : public ::testing::Test {
protected:
    void SetUp() override {
        auto* layout = new QHBoxLayout(&m_window);
        m_view = new ClearedView;
        m_view->setMinimumSize(200, 150);
        m_slider = new QSlider(Qt::Horizontal);
        m_slider->setRange(0, 100);
        layout->addWidget(m_view);
        layout->addWidget(m_slider);
        m_slider->installEventFilter(&m_sliderPaints);
        QSignalSpy composed(m_view, &QOpenGLWidget::frameSwapped);
        m_window.show();
        ASSERT_TRUE(QTest::qWaitForWindowExposed(&m_window));
        ASSERT_TRUE(composed.count() > 0 || composed.wait(10000));
    }
    // Moves the slider as a drag does, one event-loop turn a step, telling the pacing.
    void drag(ui::FramePacedRepaints& pacing, int from, int to) {
        for (int v = from; v <= to; ++v) {
            m_slider->setValue(v);
            pacing.changed();
            QCoreApplication::processEvents();
        }
    }

    QWidget m_window;
    ClearedView* m_view = nullptr;
    QSlider* m_slider = nullptr;
    PaintCounter m_sliderPaints;
};
}  // namespace

TEST_F(PacedWindow, WhilePacingTheWidgetRepaintsOnlyWithTheViewsFrames) {
    ui::FramePacedRepaints pacing(m_slider, m_view, 1h);
    QSignalSpy composed(m_view, &QOpenGLWidget::frameSwapped);
    pacing.begin();
    const int paintsBefore = m_sliderPaints.paints;
    // Counted in the slider's own paints: a composition left from showing the window (Xvfb
    // may expose it twice on a busy machine) can come at any time, and paints nothing of a
    // widget held back.
    drag(pacing, 1, 20);
    EXPECT_EQ(m_sliderPaints.paints, paintsBefore) << "twenty moves, no frame: nothing drawn";

    // The view's next frame: the slider, as it is now, is drawn in the same composition.
    m_view->update();
    pacing.frameComing();
    ASSERT_TRUE(composed.wait(10000));
    const int paintsWithTheFrame = m_sliderPaints.paints;
    EXPECT_GT(paintsWithTheFrame, paintsBefore);
    drag(pacing, 21, 30);
    EXPECT_EQ(m_sliderPaints.paints, paintsWithTheFrame) << "held back again after the frame";

    // The end of the drag draws what is left at once.
    const int paintsAtEnd = m_sliderPaints.paints;
    pacing.end();
    ASSERT_TRUE(composed.wait(10000));
    EXPECT_GT(m_sliderPaints.paints, paintsAtEnd);
    EXPECT_TRUE(m_slider->updatesEnabled());
    EXPECT_FALSE(pacing.isPacing());
}

TEST_F(PacedWindow, AChangeIsDrawnWithoutAFrameOnceTheLongestWaitHasPassed) {
    ui::FramePacedRepaints pacing(m_slider, m_view, 1ms);
    QSignalSpy composed(m_view, &QOpenGLWidget::frameSwapped);
    pacing.begin();
    const int paintsBefore = m_sliderPaints.paints;
    m_slider->setValue(50);
    pacing.changed();
    // Waited for on the slider's own paint: a composition left from showing the window (Xvfb
    // may expose it twice on a busy machine) can come before the wait is over.
    ASSERT_TRUE(QTest::qWaitFor([&] { return m_sliderPaints.paints > paintsBefore; }, 10000))
        << "a slow frame does not freeze the slider";
    ASSERT_TRUE(composed.count() > 0 || composed.wait(10000)) << "composed";
    EXPECT_FALSE(m_slider->updatesEnabled()) << "and it is held back again after that";
    pacing.end();
}

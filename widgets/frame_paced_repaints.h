// Repaints of the widgets around an OpenGL view, held back while the view follows a drag so that
// they are drawn with the view's next frame. With QOpenGLWidget, any repaint anywhere in the
// window makes the window compose itself whole (the view's texture and the other widgets) and
// swap: with software OpenGL (llvmpipe) under X, about as costly as a frame of the view.
// Scrubbing the isovalue moved the slider, the spin box and the histogram's marker at the
// pointer's 60 events a second: 177 compositions in a 4 s drag for 37 new pictures, and the
// previews, built on the same two cores, came 9 times a second; with the toolbar's repaints
// drawn with the view's frames, 16 (ensil_scrub_benchmark).
//
// Between begin() and end(), `paced` (with its children) repaints only when frameComing() says
// the view is about to draw a new frame (call it after the view's update(), in the same turn of
// the event loop, so that both are drawn in one composition), or `longestWait` after changed()
// first said that it has something new to show, so that it never looks frozen while a slow
// frame is built. Nothing changed, nothing is repainted. GUI thread only.
#pragma once

#include <QObject>
#include <QPointer>
#include <QTimer>
#include <chrono>

class QOpenGLWidget;
class QWidget;

namespace ensil::ui {

class FramePacedRepaints : public QObject {
    Q_OBJECT
public:
    FramePacedRepaints(QWidget* paced, QOpenGLWidget* view, std::chrono::milliseconds longestWait,
                       QObject* parent = nullptr);

    void begin();
    // `paced` has changed (it repaints with the next frame, or after longestWait at the latest).
    void changed();
    void frameComing();
    void end();
    [[nodiscard]] bool isPacing() const { return m_pacing; }

private:
    void holdBack();
    void letThrough();

    QPointer<QWidget> m_paced;
    QTimer m_longestWait;
    bool m_pacing = false;
};

}  // namespace ensil::ui

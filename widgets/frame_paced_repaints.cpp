#include "widgets/frame_paced_repaints.h"

#include <QOpenGLWidget>

namespace ensil::ui {

FramePacedRepaints::FramePacedRepaints(QWidget* paced, QOpenGLWidget* view,
                                       std::chrono::milliseconds longestWait, QObject* parent)
    : QObject(parent), m_paced(paced) {
    m_longestWait.setSingleShot(true);
    m_longestWait.setInterval(longestWait);
    connect(&m_longestWait, &QTimer::timeout, this, &FramePacedRepaints::letThrough);
    // Once the window has composed (the view's frame or a repaint let through), hold back again.
    connect(view, &QOpenGLWidget::frameSwapped, this, [this] {
        if (m_pacing) holdBack();
    });
}

void FramePacedRepaints::begin() {
    if (m_pacing) return;
    m_pacing = true;
    holdBack();
}

void FramePacedRepaints::changed() {
    if (m_pacing && !m_longestWait.isActive()) m_longestWait.start();
}

void FramePacedRepaints::frameComing() {
    if (m_pacing) letThrough();
}

void FramePacedRepaints::end() {
    if (!m_pacing) return;
    m_pacing = false;
    m_longestWait.stop();
    letThrough();
}

void FramePacedRepaints::holdBack() {
    m_longestWait.stop();
    if (m_paced) m_paced->setUpdatesEnabled(false);
}

void FramePacedRepaints::letThrough() {
    m_longestWait.stop();
    // Enabling updates repaints the widget whole, with whatever changed while held back.
    if (m_paced) m_paced->setUpdatesEnabled(true);
}

}  // namespace ensil::ui

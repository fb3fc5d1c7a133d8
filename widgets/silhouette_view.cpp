#include "widgets/silhouette_view.h"

#include <QMouseEvent>
#include <QOpenGLContext>
#include <QWheelEvent>
#include <cmath>

namespace ensil::ui {

SilhouetteView::SilhouetteView(QWidget* parent) : QOpenGLWidget(parent) {
    setFocusPolicy(Qt::StrongFocus);
    setMinimumSize(200, 150);
}

SilhouetteView::~SilhouetteView() {
    if (context() != nullptr) {
        // QOpenGLWidget's destructor destroys the context after this class is gone.
        disconnect(context(), nullptr, this, nullptr);
        makeCurrent();
        releaseGpu();
        doneCurrent();
    }
}

void SilhouetteView::releaseGpu() { m_renderer.releaseGpuResources(); }

void SilhouetteView::onContextAboutToBeDestroyed() {
    makeCurrent();
    releaseGpu();
    doneCurrent();
}

void SilhouetteView::initializeGL() {
    // initializeGL runs again for each new context (re-parenting); connect to each once.
    connect(context(), &QOpenGLContext::aboutToBeDestroyed, this,
            &SilhouetteView::onContextAboutToBeDestroyed, Qt::UniqueConnection);
    try {
        m_renderer.initialize();
        m_glError.clear();
    } catch (const std::exception& e) {
        m_glError = QString::fromStdString(e.what());
        emit renderingFailed(m_glError);
    }
}

void SilhouetteView::paintGL() {
    if (!m_renderer.isInitialized()) return;
    const qreal ratio = devicePixelRatioF();
    m_renderer.render(defaultFramebufferObject(), static_cast<int>(std::lround(width() * ratio)),
                      static_cast<int>(std::lround(height() * ratio)));
}

void SilhouetteView::resetCamera() {
    m_renderer.resetCamera();
    update();
}

void SilhouetteView::mousePressEvent(QMouseEvent* event) {
    m_lastMouse = event->position().toPoint();
    event->accept();
}

void SilhouetteView::mouseMoveEvent(QMouseEvent* event) {
    const QPoint pos = event->position().toPoint();
    const QPoint delta = pos - m_lastMouse;
    m_lastMouse = pos;
    const bool panning =
        (event->buttons() & Qt::MiddleButton) ||
        ((event->buttons() & Qt::LeftButton) && (event->modifiers() & Qt::ShiftModifier));
    if (panning) {
        m_renderer.camera().pan(static_cast<float>(delta.x()), static_cast<float>(delta.y()),
                                static_cast<float>(height()));
    } else if (event->buttons() & Qt::LeftButton) {
        m_renderer.camera().orbit(static_cast<float>(delta.x()), static_cast<float>(delta.y()));
    } else {
        return;
    }
    update();
}

void SilhouetteView::wheelEvent(QWheelEvent* event) {
    // One notch (120 units) zooms by 12 %.
    const double notches = event->angleDelta().y() / 120.0;
    m_renderer.camera().zoom(static_cast<float>(std::pow(1.12, notches)));
    update();
    event->accept();
}

}  // namespace ensil::ui

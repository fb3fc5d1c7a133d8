// The central 3D view: a thin QOpenGLWidget that owns a gl::Renderer and forwards to it.
// Mouse: left drag orbits, middle drag (or shift + left) pans, wheel zooms. GUI thread only.
// GPU resources are released when the widget's context is about to be destroyed, which also
// happens when the widget is re-parented (docking, fullscreen), not only in the destructor.
#pragma once

#include <QOpenGLWidget>
#include <QPoint>

#include "gl/renderer.h"

namespace ensil::ui {

class SilhouetteView : public QOpenGLWidget {
    Q_OBJECT
public:
    explicit SilhouetteView(QWidget* parent = nullptr);
    ~SilhouetteView() override;

    [[nodiscard]] gl::Renderer& renderer() { return m_renderer; }
    // The error from the last initialisation attempt, empty when rendering works.
    [[nodiscard]] QString glError() const { return m_glError; }

public slots:
    void resetCamera();

signals:
    // Emitted once when the view cannot render (no OpenGL 4.1 core, a shader that fails).
    void renderingFailed(const QString& message);

protected:
    void initializeGL() override;
    void paintGL() override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;

private slots:
    void onContextAboutToBeDestroyed();

private:
    void releaseGpu();

    gl::Renderer m_renderer;
    QPoint m_lastMouse;
    QString m_glError;
};

}  // namespace ensil::ui

// The central 3D view: a thin QOpenGLWidget that owns a gl::Renderer and forwards to it.
// Mouse: left drag orbits, middle drag (or shift + left drag) pans, wheel zooms; a left click
// (no drag) picks the member under the cursor, right drag draws a rubber band that brushes
// every member drawn inside it, and hovering highlights the member under the cursor with a
// tooltip. The view only reports what was picked (signals); what selection means is decided
// by the window. GUI thread only.
// GPU resources are released when the widget's context is about to be destroyed, which also
// happens when the widget is re-parented (docking, fullscreen), not only in the destructor.
#pragma once

#include <QImage>
#include <QList>
#include <QOpenGLWidget>
#include <QPoint>
#include <QStringList>
#include <QTimer>

#include "gl/renderer.h"

class QRubberBand;

namespace ensil::ui {

class SilhouetteView : public QOpenGLWidget {
    Q_OBJECT
public:
    // A press and release closer than this (in widget pixels) is a click, not a drag.
    static constexpr int kClickSlop = 4;

    explicit SilhouetteView(QWidget* parent = nullptr);
    ~SilhouetteView() override;

    [[nodiscard]] gl::Renderer& renderer() { return m_renderer; }
    // The error from the last initialisation attempt, empty when rendering works.
    [[nodiscard]] QString glError() const { return m_glError; }

    // What the view says while it has no data (what to do, or that data is loading); empty
    // restores the default hint.
    void setPlaceholderText(const QString& text) {
        m_placeholder = text.isEmpty() ? defaultPlaceholder() : text;
        update();
    }
    [[nodiscard]] static QString defaultPlaceholder() {
        return tr(
            "No ensemble loaded.\nFile > Open (Ctrl+O) reads NetCDF, HDF5 or VTK files;\n"
            "File > Open Demo Ensemble shows a generated one.");
    }

    // Names shown in the hover tooltip, by member index; "member N" where none is given.
    void setMemberNames(QStringList names) { m_memberNames = std::move(names); }

    // The picture of the view at any size, without the UI, labels and legend included; null
    // when OpenGL is not available.
    [[nodiscard]] QImage renderImage(const QSize& size);

    // The member drawn at (or within a few pixels of) a point in widget coordinates, with
    // its cluster; -1 for background. Draws an id pass, so it costs about one frame.
    [[nodiscard]] gl::PickResult pickAt(QPoint position);
    // Every member drawn inside a rectangle in widget coordinates.
    [[nodiscard]] QList<int> membersInside(const QRect& rectangle);

public slots:
    void resetCamera();

signals:
    // Emitted once when the view cannot render (no OpenGL 4.1 core, a shader that fails).
    void renderingFailed(const QString& message);
    // A click picked a member (-1: the background) with these keyboard modifiers.
    void memberClicked(int member, Qt::KeyboardModifiers modifiers);
    // The member under the resting cursor changed (-1: none).
    void memberHovered(int member);
    // A rubber band was drawn over these members (sorted, possibly empty).
    void membersBrushed(const QList<int>& members, Qt::KeyboardModifiers modifiers);

protected:
    void initializeGL() override;
    void paintGL() override;
    void resizeGL(int width, int height) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void leaveEvent(QEvent* event) override;

private slots:
    void onContextAboutToBeDestroyed();
    void pickHovered();

private:
    void releaseGpu();
    void setHovered(int member, QPoint position, int cluster);
    [[nodiscard]] QPoint toFramebuffer(QPoint position) const;

    gl::Renderer m_renderer;
    QPoint m_lastMouse;
    QPoint m_pressPosition;
    Qt::MouseButton m_pressButton = Qt::NoButton;
    bool m_dragged = false;
    QRubberBand* m_rubberBand = nullptr;
    // Hover picks are coalesced: one id pass per pause of the cursor, not one per motion event.
    QTimer m_hoverTimer;
    QPoint m_hoverPosition;
    int m_hovered = -1;
    QStringList m_memberNames;
    QString m_placeholder = defaultPlaceholder();
    QString m_glError;
};

}  // namespace ensil::ui

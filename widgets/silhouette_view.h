// The central 3D view: a thin QOpenGLWidget that owns a gl::Renderer and forwards to it.
// Mouse: left drag orbits, middle drag (or shift + left drag) pans, wheel zooms; a left click
// (no drag) picks the member under the cursor, right drag draws a rubber band that brushes
// every member drawn inside it, and hovering highlights the member under the cursor with a
// tooltip. The view only reports what was picked (signals); what selection means is decided
// by the window. While the camera moves on a renderer too slow for smooth motion, frames are
// drawn at a lower resolution (see setAdaptiveResolution); the frame after the motion is full
// resolution. GUI thread only.
// GPU resources are released when the widget's context is about to be destroyed, which also
// happens when the widget is re-parented (docking, fullscreen), not only in the destructor.
#pragma once

#include <QImage>
#include <QList>
#include <QOpenGLWidget>
#include <QPoint>
#include <QStringList>
#include <QTimer>
#include <cstddef>
#include <functional>

#include "gl/renderer.h"
#include "workbench/surface_display.h"

class QRubberBand;

namespace ensil::ui {

// The isovalue controller's display (workbench/surface_display.h): its surfaces go to the
// renderer.
class SilhouetteView : public QOpenGLWidget, public workbench::SurfaceDisplay {
    Q_OBJECT
public:
    // A press and release closer than this (in widget pixels) is a click, not a drag.
    static constexpr int kClickSlop = 4;
    // How far a left drag across the whole view turns the camera.
    static constexpr float kDragAcrossDegrees = 180.0F;

    explicit SilhouetteView(QWidget* parent = nullptr);
    ~SilhouetteView() override;

    [[nodiscard]] gl::Renderer& renderer() { return m_renderer; }
    void setSurfaces(std::shared_ptr<const data::MeshSet> meshes) override {
        m_renderer.setMeshes(std::move(meshes));
    }
    void setMotionSurfaces(std::shared_ptr<const data::MeshSet> meshes) override {
        m_renderer.setMotionMeshes(std::move(meshes));
    }
    [[nodiscard]] std::shared_ptr<const data::MeshSet> surfaces() const override {
        return m_renderer.meshes();
    }
    void requestRepaint() override { update(); }
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
            "No ensemble loaded.\nFile > Open (Ctrl+O) reads NetCDF, HDF5, VTK or GRIB files;\n"
            "File > Open Demo Ensemble shows a generated one.");
    }

    // Lower the resolution while the camera moves when a full frame takes longer than the
    // motion budget (default on, 33 ms: 30 frames a second).
    void setAdaptiveResolution(bool on);
    [[nodiscard]] bool adaptiveResolution() const { return m_adaptiveResolution; }
    void setMotionFrameBudget(double milliseconds) { m_motionBudgetMs = milliseconds; }
    // Whether the picture is in motion now: the camera moves (a drag, or wheel turns in quick
    // succession), or a control is being dragged (beginInteraction).
    [[nodiscard]] bool inMotion() const { return m_moving; }
    // The frames this view has drawn (paintGL with a renderer), for tests and benchmarks: a
    // window composed again around an unchanged view does not count.
    [[nodiscard]] std::size_t framesDrawn() const { return m_framesDrawn; }
    static constexpr double kDefaultMotionBudgetMs = 33.0;

    // Names shown in the hover tooltip, by member index; "member N" where none is given.
    void setMemberNames(QStringList names) { m_memberNames = std::move(names); }
    // Says what lies under the cursor (place, level, values) for the hover tooltip and the
    // hoverDescribed signal; the view knows no data, so the window supplies it.
    using HoverDescriber = std::function<QString(const gl::PickResult&)>;
    void setHoverDescriber(HoverDescriber describer) { m_describeHover = std::move(describer); }

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
    void lookFrom(float azimuth, float elevation);
    // Another control changes the picture continuously (a slider being dragged, a time step's
    // preview until its full surfaces): its frames are drawn as camera motion is, until it
    // ends, even when a passing change (showPassingChange) would have settled meanwhile.
    void beginInteraction() override;
    void endInteraction() override { stopMoving(); }
    // A change that others may follow at once (a time step while stepping or playing): drawn
    // as a motion frame, at the resolution motion gets, and at full resolution once such
    // changes pause, as wheel turns are, so a step is on screen without a full software frame.
    void showPassingChange() override;
    // Runs `work` once, after the next frame is on screen: background work that would take the
    // cores a software OpenGL's frame needs starts when that frame is drawn.
    void afterNextFrame(QObject* context, std::function<void()> work) override;

signals:
    // Emitted once when the view cannot render (no OpenGL 4.1 core, a shader that fails).
    void renderingFailed(const QString& message);
    // A click picked a member (-1: the background) with these keyboard modifiers.
    void memberClicked(int member, Qt::KeyboardModifiers modifiers);
    // The member under the resting cursor changed (-1: none).
    void memberHovered(int member);
    // What the describer said of the point under a resting cursor (empty off the data).
    void hoverDescribed(const QString& description);
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
    void stopMoving();

private:
    void releaseGpu();
    void setHovered(int member, QPoint position, int cluster, const QString& description = {});
    [[nodiscard]] QPoint toFramebuffer(QPoint position) const;
    // The resolution scale for the next frame: 1 when still, or when frames are fast enough.
    [[nodiscard]] float frameResolutionScale() const;
    // Chooses the resolution of the motion frames to come from what this frame took.
    void adaptMotionStep(double frameMs, float scale);

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
    HoverDescriber m_describeHover;
    QStringList m_memberNames;
    QString m_placeholder = defaultPlaceholder();
    QString m_glError;
    bool m_adaptiveResolution = true;
    double m_motionBudgetMs = kDefaultMotionBudgetMs;
    int m_motionStep = 0;          // the resolution of motion frames, an index into the steps
    int m_measuredMotionStep = 0;  // where the last motion frames left m_motionStep
    bool m_moving = false;
    std::size_t m_framesDrawn = 0;
    // Wheel turns come one by one: the motion ends when they pause.
    QTimer m_settleTimer;
};

}  // namespace ensil::ui

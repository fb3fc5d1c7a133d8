// Where the isovalue controller (isovalue_session.h) shows its surfaces: the workbench's 3D view
// (ui::SilhouetteView), or a test's recorder on a QCoreApplication. The controller decides what
// is shown and when a change is passing; the display draws it. GUI thread only.
#pragma once

#include <QObject>
#include <functional>
#include <memory>

#include "data/packed_mesh.h"

namespace ensil::workbench {

class SurfaceDisplay {
public:
    SurfaceDisplay() = default;
    SurfaceDisplay(const SurfaceDisplay&) = delete;
    SurfaceDisplay& operator=(const SurfaceDisplay&) = delete;
    virtual ~SurfaceDisplay() = default;

    // The surfaces drawn at full detail (gl::Renderer::setMeshes): null clears them and their
    // reduced-detail copies. Drawn at the next repaint.
    virtual void setSurfaces(std::shared_ptr<const data::MeshSet> meshes) = 0;
    // The same surfaces in reduced detail, drawn while the picture moves
    // (gl::Renderer::setMotionMeshes).
    virtual void setMotionSurfaces(std::shared_ptr<const data::MeshSet> meshes) = 0;
    [[nodiscard]] virtual std::shared_ptr<const data::MeshSet> surfaces() const = 0;
    // Asks for a frame (coalesced with others asked for before it is drawn).
    virtual void requestRepaint() = 0;
    // A control changes the picture continuously until endInteraction: frames drawn as camera
    // motion is.
    virtual void beginInteraction() = 0;
    virtual void endInteraction() = 0;
    // A change that others may follow at once: a motion frame, full detail once they pause.
    virtual void showPassingChange() = 0;
    // Runs `work` once after the next frame is on screen (unless `context` is gone).
    virtual void afterNextFrame(QObject* context, std::function<void()> work) = 0;
};

}  // namespace ensil::workbench

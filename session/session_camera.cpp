#include "session/session_camera.h"

namespace ensil::session {

void placeCamera(const CameraState& state, gl::Renderer& renderer) {
    gl::Camera& camera = renderer.camera();
    camera.setAngles(state.azimuth, state.elevation);
    if (state.placement) {
        camera.setTarget(state.placement->target);
        camera.setDistance(state.placement->distance);
    } else {
        renderer.frameTheBox();
    }
}

}  // namespace ensil::session

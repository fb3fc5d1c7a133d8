// A session's camera put on a renderer: its angles, and its saved place, or, with none saved,
// fitted to the data box for the renderer's view size (what Reset Camera does). Headless
// rendering, opening a project and undo all place the camera through this. GUI thread.
#pragma once

#include "gl/renderer.h"
#include "session/session_state.h"

namespace ensil::session {

void placeCamera(const CameraState& camera, gl::Renderer& renderer);

}  // namespace ensil::session

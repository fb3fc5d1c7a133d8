// The session a Python `ensil.Session` holds: a session::SessionState (what a project file
// saves) and the project file it was loaded from or saved to. Its settings object shares the
// state, so changing one changes the session. Any thread.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "session/session_state.h"

namespace ensil::python {

struct PySession {
    std::shared_ptr<session::SessionState> state = std::make_shared<session::SessionState>();
    std::optional<std::string> path;  // the project file, once loaded or saved
};

}  // namespace ensil::python

// XDG_RUNTIME_DIR for Qt's platform plugins. Where it is unset (containers, CI, cron, a batch
// node, sudo), Qt picks a folder itself and says so on stderr at every start, a line a user
// cannot act on and a script must filter out. ensil gives such a process a private folder of
// its own instead, quietly.
#pragma once

#include <optional>
#include <string>

namespace ensil::gl {

// Call before the Q*Application exists. On Linux with XDG_RUNTIME_DIR unset or empty: makes
// <temp>/ensil-runtime-<uid> (mode 0700) and sets XDG_RUNTIME_DIR to it; a folder of that name
// that another user owns, or that others may enter, is not used (Qt then warns as before).
// Returns the folder set, or nothing when nothing was changed.
std::optional<std::string> ensureRuntimeDirectory();

}  // namespace ensil::gl

// The settings remembered between runs of the workbench (those of setting_table.h with a
// remembered key): how the user last drew things. Values that are missing, or that a hand-edited
// file made malformed or out of range, keep the session's value. GUI thread (QSettings).
#pragma once

#include <QSettings>

#include "session/session_state.h"

namespace ensil::session {

void restoreRemembered(const QSettings& settings, SessionState& state);
void remember(QSettings& settings, const SessionState& state);

}  // namespace ensil::session

// A project file (.ensil): a SessionState as versioned JSON. The data sources (paths relative
// to the project file when it can, absolute otherwise), the variable, member dimension, time
// index, isovalue, camera, every setting of setting_table.h under its project key, the cutting
// plane, hidden members and clusters, the selection, and the panel layout. Reading validates
// everything before anything is used, so a malformed file is refused whole (with the line, or
// the field, and the reason), never half-applied; a file written by a newer ensil is refused
// with a message saying so. Saving is atomic (QSaveFile): a failed write leaves the previous
// file as it was. Any thread.
#pragma once

#include <QByteArray>
#include <QDir>
#include <QString>
#include <stdexcept>
#include <string>

#include "session/session_state.h"

namespace ensil::session {

// Version 1: the first format. Version 2: the camera's angles and projection are saved even
// when the camera was not placed (a picture drawn from the command line). Version 3: hidden
// clusters and hidden and selected members are saved by the numbers the workbench shows them
// with (from 1), no longer by indices from 0. A reader of version N opens files of versions
// 1..N.
inline constexpr int kProjectSchemaVersion = 3;
inline constexpr const char* kProjectSuffix = "ensil";

// Why a project file cannot be used: `line` is 1-based (0 when the problem is a field, which
// `what()` then names).
class ProjectError : public std::runtime_error {
public:
    explicit ProjectError(const std::string& message, int line = 0)
        : std::runtime_error(message), m_line(line) {}
    [[nodiscard]] int line() const { return m_line; }

private:
    int m_line;
};

// The JSON text of a session; paths relative to `projectDir` where they lie below or beside it.
QByteArray projectToJson(const SessionState& state, const QDir& projectDir);
// Parses and validates; relative paths are resolved against `projectDir`. Throws ProjectError.
SessionState projectFromJson(const QByteArray& json, const QDir& projectDir);

// Writes atomically. Throws ProjectError (with the system's reason) when it cannot.
void saveProject(const SessionState& state, const QString& path);
// Reads and validates. Throws ProjectError.
SessionState loadProject(const QString& path);

}  // namespace ensil::session

// A project file (.ensil): a whole session as versioned JSON. The data sources (paths relative
// to the project file when it can, absolute otherwise), the variable, member dimension, time
// index, isovalue, camera, render mode and parameters, cutting plane, vertical exaggeration,
// background, clusters and linkage, hidden members and clusters, the selection, and the panel
// layout. Reading validates everything before anything is used, so a malformed file is refused
// whole (with the line, or the field, and the reason), never half-applied; a file written by a
// newer ensil is refused with a message saying so. Saving is atomic (QSaveFile): a failed write
// leaves the previous file as it was. Any thread.
#pragma once

#include <QByteArray>
#include <QDir>
#include <QString>
#include <glm/vec3.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "data/demo_ensemble.h"
#include "data/ensemble_reader.h"
#include "gl/render_settings.h"

namespace ensil::app {

struct ProjectCamera {
    float azimuth = -75.0F;
    float elevation = 30.0F;
    float distance = 3.0F;
    glm::vec3 target{0.5F};
    bool orthographic = false;
};

struct Project {
    // Version 1 is the first format. A reader of version N opens files of versions 1..N.
    static constexpr int kSchemaVersion = 1;

    // Either the built-in demo (with its parameters) or files; paths are absolute in memory.
    bool demo = false;
    data::DemoEnsembleParams demoParams;
    data::DataSelection data;
    std::optional<float> isovalue;  // none: the workbench's default for the variable
    std::optional<ProjectCamera> camera;
    gl::RenderSettings render;
    float verticalExaggeration = 1.0F;
    glm::vec3 background{0.11F, 0.12F, 0.14F};
    int clusters = 5;
    std::string linkage = "average";
    std::vector<int> hiddenMembers;
    std::vector<int> hiddenClusters;
    std::vector<int> selection;
    QByteArray windowGeometry;  // QMainWindow::saveGeometry / saveState, kept as they are
    QByteArray windowState;
};

// Why a project file cannot be used: `line` is 1-based (0 when the problem is a field, which
// `what()` then names).
class ProjectError : public std::runtime_error {
public:
    ProjectError(const std::string& message, int line = 0)
        : std::runtime_error(message), m_line(line) {}
    [[nodiscard]] int line() const { return m_line; }

private:
    int m_line;
};

// The JSON text of a project; paths relative to `projectDir` where they lie below it or beside it.
QByteArray projectToJson(const Project& project, const QDir& projectDir);
// Parses and validates; relative paths are resolved against `projectDir`. Throws ProjectError.
Project projectFromJson(const QByteArray& json, const QDir& projectDir);

// Writes atomically. Throws ProjectError (with the system's reason) when it cannot.
void saveProject(const Project& project, const QString& path);
// Reads and validates. Throws ProjectError.
Project loadProject(const QString& path);

inline constexpr const char* kProjectSuffix = "ensil";

}  // namespace ensil::app

// Renders a project headless: reads its data (or makes the demo), builds its isovalue's meshes
// through the cache, clusters, and draws the picture offscreen exactly as the workbench shows
// that project (same settings, camera, colours, visibility, selection, labels). Used by
// `ensil render`, for projects and for the command-line options alike. Creates its own
// offscreen OpenGL context. GUI (main) thread.
#pragma once

#include <QImage>
#include <cstddef>
#include <glm/vec4.hpp>
#include <optional>
#include <string>

#include "app/project.h"

namespace ensil::app {

struct RenderRequest {
    int width = 1600;
    int height = 1000;
    int frames = 1;  // frames drawn and timed; the median is reported
    bool useCache = true;
    bool labels = true;  // axis labels and legend
    // Without a saved camera: the angles to look from (the camera is fitted to the data box).
    float azimuth = -75.0F;
    float elevation = 30.0F;
    // A plane given across the box (gl::CuttingPlane::acrossBox) rather than in display units.
    std::optional<glm::vec4> planeAcrossBox;
};

struct RenderOutcome {
    QImage image;
    double frameMs = 0.0;  // median
    std::size_t gpuBytes = 0;
    std::size_t triangles = 0;
    std::size_t members = 0;
    float isovalue = 0.0F;
    std::string glRenderer;       // GL_RENDERER: the driver that drew it
    bool withoutDisplay = false;  // drawn through EGL's surfaceless platform
};

// Throws data::Error, ProjectError (isovalue outside the values) or std::runtime_error.
RenderOutcome renderProject(const Project& project, const RenderRequest& request);

// The source key the workbench uses for the mesh cache, so both share cached meshes.
std::string demoSourceKey(const data::DemoEnsembleParams& params);

}  // namespace ensil::app

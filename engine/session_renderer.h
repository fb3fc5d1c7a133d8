// Draws a session headless: reads its data (or makes the demo), builds its isovalue's meshes
// through the cache, clusters, and draws the picture offscreen exactly as the workbench shows
// that session (same settings, camera, colours, visibility, selection, labels). Used by
// `ensil render`, for projects and for the command-line options alike. Creates its own
// offscreen OpenGL context. Links no Qt Widgets (the link graph enforces it: this target does
// not link them). GUI (main) thread.
#pragma once

#include <QImage>
#include <cstddef>
#include <functional>
#include <glm/vec4.hpp>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "data/vertical_scale.h"
#include "session/session_state.h"

namespace ensil::engine {

struct RenderRequest {
    int width = 1600;
    int height = 1000;
    int frames = 1;  // frames drawn and timed; the median is reported
    bool useCache = true;
    // False: the session's clusters are only the default, and the picture takes
    // session::defaultClusters of the members drawn (data drawn without --clusters).
    bool clustersGiven = true;
    // A plane given across the box (gl::CuttingPlane::acrossBox: normal, position from -1 to
    // 1) rather than in display units; it replaces the session's plane normal and offset.
    std::optional<glm::vec4> planeAcrossBox;
    // The previous time step's members (by name) and the cluster identity each had there:
    // this picture's clusters are matched to them (matchStepIdentities), so colours follow the
    // groups from frame to frame. Empty: the identities come from the tree alone.
    std::vector<std::string> previousMembers;
    std::vector<int> previousIdentities;
    // One colour scale for the floor over several pictures (ensil render --times, from
    // floorScaleOverSteps): the floor's colours span these values, and floorRangeNote is added
    // to its colour bar's caption. None: the floor spans its own values.
    std::optional<std::pair<float, float>> floorRange;
    std::string floorRangeNote;
    // How far the picture is, for a long run: `stage` is "reading" or "preprocessing", each
    // from 0 to 1. Called on the calling thread or on the job's workers. None: not reported.
    std::function<void(const std::string& stage, double fraction)> progress;
};

struct RenderOutcome {
    QImage image;
    // The session as drawn: the isovalue, the camera's placement and the plane resolved, so
    // that drawing it again (saved as a project) gives the same picture.
    session::SessionState drawn;
    double frameMs = 0.0;  // median
    std::size_t gpuBytes = 0;
    std::size_t triangles = 0;
    std::size_t members = 0;
    std::string variable;  // the one drawn (the default when none was named)
    std::string note;      // what the data cannot show well (data::fewLevelsWarning), or empty
    // How much the box stretches heights over their true proportion, as its vertical axis's
    // title says (data/vertical_scale.h); none where it cannot be known.
    std::optional<data::VerticalScale> verticalScale;
    std::string glRenderer;                // GL_RENDERER: the driver that drew it
    bool withoutDisplay = false;           // drawn through EGL's surfaceless platform
    std::vector<std::string> memberNames;  // of the members drawn, and each one's identity:
    std::vector<int> memberIdentities;     // the next frame's RenderRequest::previous...
};

// Throws data::Error, session::ProjectError (isovalue outside the values) or std::runtime_error.
RenderOutcome renderSession(const session::SessionState& state, const RenderRequest& request);

// Draws `state` on an ensemble already read (the state's data source is not read again; the
// Python module draws ensembles made from arrays this way). `sourceKey` identifies the data for
// the mesh cache; empty: no cache. Throws as renderSession.
RenderOutcome renderEnsemble(std::shared_ptr<const data::Ensemble> ensemble,
                             const std::string& sourceKey, const session::SessionState& state,
                             const RenderRequest& request);

// The source key the workbench uses for the mesh cache, so both share cached meshes.
std::string demoSourceKey(const data::DemoEnsembleParams& params);

}  // namespace ensil::engine

// How a session becomes what the renderer draws, in one place for the workbench's 3D view and for
// `ensil render` (engine/session_renderer.h), so that a picture drawn from the command line is
// the workbench's by construction: the vertical exaggeration, the floor, the settings, the
// background and the projection of the session's parts that changed (showSession), the section
// and its member (sceneSection, sectionMember), and each member's colour, visibility and
// selection (sceneAppearance). The data and the isovalue's result are the caller's (SceneData).
// GUI (or the offscreen context's) thread.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "engine/floor_map.h"
#include "gl/renderer.h"
#include "session/session_model.h"
#include "session/session_state.h"

namespace ensil::engine {

// What a picture is drawn from besides the session: the data, and the result of the isovalue
// whose surfaces are drawn. Pointers, borrowed for the call; null where there is none yet.
struct SceneData {
    const data::Ensemble* ensemble = nullptr;
    const data::Member* mean = nullptr;
    const ColumnMaxima* columnMaxima = nullptr;  // of the data, without an isovalue's
    // The ensemble's value range (a member's and the mean's section are coloured on it).
    float valueMinimum = 0.0F;
    float valueMaximum = 1.0F;
    // The isovalue drawn, its P(f > c) and that probability's column maximum (for the floor).
    std::optional<float> isovalue;
    const data::FieldValues* exceedance = nullptr;
    const std::vector<float>* exceedanceColumnMaximum = nullptr;
    // One colour scale for the floor over several pictures (ensil render --times): its colours
    // span these values and the note is added to its colour bar's caption. None: its own.
    std::optional<std::pair<float, float>> floorRange;
    std::string floorRangeNote;
};

// The floor the settings ask for (none, a column maximum, the mean at a level).
gl::FloorMap sceneFloor(const SceneData& data, const gl::RenderSettings& settings);

// The member a member section shows: the first selected (a deliberate choice), else the one
// hovered last (-1: none; a picture has no hover).
int sectionMember(const std::vector<int>& selection, int lastHovered);

// The field the cutting plane's cut face shows (empty when that field is not there).
gl::SectionVolume sceneSection(const SceneData& data, gl::SectionField field, int member);

// Each member's colour (its cluster's identity), visibility and selection, from the session's
// hidden members, hidden clusters and selection under these labels and identities.
std::vector<gl::MemberAppearance> sceneAppearance(const session::SessionState& state,
                                                  const std::vector<int>& labels,
                                                  const std::vector<int>& identities,
                                                  int memberCount);

// Sets the renderer from the session's `parts`: Exaggeration (the box), Rendering and Plane
// (the settings; the floor when its choice or level changed, or with Data), Background and
// Projection. Other parts are not the renderer's settings (the data, the surfaces, the members'
// appearance, the camera's placement).
void showSession(gl::Renderer& renderer, const session::SessionState& state, const SceneData& data,
                 session::SessionParts parts);

}  // namespace ensil::engine

// The named camera views a meteorologist asks for: a map (north up, from straight above) and the
// level views from the four sides, all orthographic, plus ensil's default 3D view. One table,
// used by the workbench's View menu and toolbar and by `ensil render --view`. Any thread.
#pragma once

#include <optional>
#include <span>
#include <string_view>

#include "session/session_state.h"

namespace ensil::session {

struct ViewPreset {
    std::string_view id;     // "top", "north", ...: the --view value
    std::string_view label;  // the menu's text, with its mnemonic
    float azimuth;           // degrees, as CameraState
    float elevation;
    bool forcesOrthographic;  // the map and side views: read against their axes, like charts
};

std::span<const ViewPreset> viewPresets();
const ViewPreset* findViewPreset(std::string_view id);
// "top, north, south, east, west, default", for help texts and messages.
std::string viewPresetNames();

// The camera looking from the preset: fitted to the data box (no placement kept), and
// orthographic where the preset asks for it.
void lookFrom(const ViewPreset& preset, CameraState& camera);

}  // namespace ensil::session

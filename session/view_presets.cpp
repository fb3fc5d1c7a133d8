#include "session/view_presets.h"

#include <array>
#include <string>

namespace ensil::session {
namespace {

// Azimuth -90 looks from the south towards the north (CameraState); 0 from the east. The side
// views look level and orthographic, as a chart's cross-section does: a level in the box lies on
// the screen row of its tick on the box's edge, whatever its depth (in perspective, or from
// above, a jet at 200 hPa in the middle of the box read as 50-70 hPa on the near edge).
constexpr std::array<ViewPreset, 6> kPresets{{
    {"top", "&Map View (North Up)", -90.0F, 90.0F, true},
    {"north", "View From the &North", 90.0F, 0.0F, true},
    {"south", "View From the &South", -90.0F, 0.0F, true},
    {"east", "View From the &East", 0.0F, 0.0F, true},
    {"west", "View From the &West", 180.0F, 0.0F, true},
    {"default", "&Default 3D View", CameraState{}.azimuth, CameraState{}.elevation, false},
}};

}  // namespace

std::span<const ViewPreset> viewPresets() { return kPresets; }

const ViewPreset* findViewPreset(std::string_view id) {
    for (const ViewPreset& p : kPresets) {
        if (p.id == id) return &p;
    }
    return nullptr;
}

std::string viewPresetNames() {
    std::string names;
    for (const ViewPreset& p : kPresets) {
        if (!names.empty()) names += ", ";
        names += p.id;
    }
    return names;
}

void lookFrom(const ViewPreset& preset, CameraState& camera) {
    camera.azimuth = preset.azimuth;
    camera.elevation = preset.elevation;
    camera.placement.reset();
    if (preset.forcesOrthographic) camera.orthographic = true;
}

}  // namespace ensil::session

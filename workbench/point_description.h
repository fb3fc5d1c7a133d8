// What lies under the cursor, in words a meteorologist reads: the place in true longitude and
// latitude (through the grid's map projection), the level in the vertical axis's readable
// units (hPa, km), and the values there: the hovered member's and the mean's on a surface, the
// mean's column maximum (what the floor map shows) on the floor, the section's field on the
// cutting plane's filled cut face. Pure; GUI thread.
#pragma once

#include <QString>

#include "data/ensemble.h"
#include "geo/map_projection.h"
#include "gl/renderer.h"

namespace ensil::workbench {

struct PointContext {
    const data::Ensemble* ensemble = nullptr;
    const data::Member* mean = nullptr;
    const geo::MapProjection* projection = nullptr;  // null: the grid's own coordinates
    const data::DisplayFrame* frame = nullptr;
    // The field on the cut face, when it is filled (gl::Renderer::sectionShown); else null.
    const gl::SectionVolume* section = nullptr;
};

// Empty when the pick hit no surface, no filled cut face and no floor.
QString describePoint(const PointContext& context, const gl::PickResult& hit);

// "52.10° N, 3.40° W" (longitudes past 180 east read west).
QString formatLonLat(double lon, double lat);

}  // namespace ensil::workbench

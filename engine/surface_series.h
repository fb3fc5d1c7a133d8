// The surfaces of a time series (engine/time_series.h) written for other tools: each step's as
// exportSurfaces writes one isovalue's, named STEM_tINDEX, and for VTK XML a ParaView data file
// (.pvd) that gathers the steps' .vtm files as one dataset over time, so ParaView's time
// controls step through them. Any thread.
#pragma once

#include <filesystem>
#include <stop_token>
#include <vector>

#include "engine/surface_export.h"
#include "engine/time_series.h"

namespace ensil::engine {

// `displayFrame`: vertices in the workbench's box (vertical exaggeration 1) instead of the data's
// coordinates. `stem` empty: VARIABLE_isoVALUE. The .pvd (VTP only) comes first in the files
// returned; each step's files follow in step order. Each step's members carry that step's cluster
// numbers (its clusters matched to the previous step's). Throws as exportSurfaces.
ExportedSurfaces exportTimeSeriesSurfaces(const std::vector<TimeStepResult>& steps,
                                          SurfaceFormat format,
                                          const std::filesystem::path& directory,
                                          bool displayFrame = false, const std::string& stem = {},
                                          const std::stop_token& stop = {});

}  // namespace ensil::engine

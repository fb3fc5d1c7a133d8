// Reduced-detail isosurfaces for scrubbing the isovalue (METHODS.md section 21): every member's
// and the mean's surface extracted from the field sampled at every s-th grid point (the last
// point of each axis always kept, so surfaces still meet the box's faces where the full ones
// do), coarsely decimated, with the full field's attributes. Built in tens of milliseconds for
// the paper-sized ensemble, so the view can follow the slider while it moves; the full-detail
// meshes (isosurface_pipeline.h) replace them on release. Pure functions; any thread.
#pragma once

#include <array>
#include <cstdint>
#include <stop_token>
#include <vector>

#include "data/display_frame.h"
#include "data/ensemble.h"
#include "preprocessing/ensemble_moments.h"
#include "preprocessing/isosurface_pipeline.h"

namespace ensil::prep {

struct PreviewOptions {
    // At most this many sampled points per field: what bounds the marching cubes' and the
    // decimation's work. Chosen by measurement (ensil_scrub_benchmark prints 2^14 to 2^16):
    // the paper-sized demo's 51 previews take about a third of the time at 2^14 than at 2^16.
    std::size_t pointBudget = std::size_t{1} << 14;
    // Decimation bound of the preview, in cells of the full grid.
    float maxErrorCells = 1.0F;
};

// Which grid indices of each axis are sampled: 0, s, 2s, ... and always the last one. Axes
// that are already short (the few levels of most weather data) are kept whole.
struct PreviewSampling {
    std::array<std::vector<std::uint32_t>, 3> indices;
    int stride = 1;
    [[nodiscard]] std::size_t pointCount() const {
        return indices[0].size() * indices[1].size() * indices[2].size();
    }
};
PreviewSampling previewSampling(const data::Grid& grid, std::size_t pointBudget);

// Members in order, then the mean, as data::MeshSet holds them (no context surfaces). Throws
// data::Cancelled.
IsovalueMeshes buildPreviewMeshes(const data::Ensemble& ensemble, const EnsembleMoments& moments,
                                  const data::DisplayFrame& frame, float isovalue,
                                  const PreviewOptions& options = {},
                                  const std::stop_token& stop = {});

}  // namespace ensil::prep

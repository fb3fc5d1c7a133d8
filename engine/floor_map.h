// The floor map a session asks for (gl::FloorContent): none, the mean's column maximum, the
// mean at one level, or the column maximum of the members' spread, with its colour bar's
// caption. Shared by the workbench and `ensil render`.
#pragma once

#include <memory>
#include <stop_token>
#include <vector>

#include "data/ensemble.h"
#include "gl/renderer.h"

namespace ensil::engine {

// The floor's column maxima (nx * ny each), computed once per ensemble.
struct ColumnMaxima {
    std::vector<float> mean;    // of the mean member
    std::vector<float> spread;  // of the members' sample standard deviation (METHODS.md s. 17)
    // The standard deviation itself on the grid's points, for a section through it.
    std::shared_ptr<const data::FieldValues> stddev;
    // Of P(f > c) at `isovalue`: per isovalue, set by the caller (empty before the first).
    std::vector<float> exceedance;
    float isovalue = 0.0F;
};
// Throws data::Cancelled.
ColumnMaxima computeColumnMaxima(const data::Ensemble& ensemble, const data::Member& mean,
                                 const std::stop_token& stop = {});

gl::FloorMap floorMapFor(const data::Ensemble& ensemble, const data::Member& mean,
                         const ColumnMaxima& columnMaxima, const gl::RenderSettings& settings);

}  // namespace ensil::engine

// The floor map a session asks for (gl::FloorContent): none, the mean's column maximum, or the
// mean at one level, with its colour bar's caption. Shared by the workbench and `ensil render`.
#pragma once

#include <vector>

#include "data/ensemble.h"
#include "gl/renderer.h"

namespace ensil::app {

// `columnMaximum`: the mean's column maximum, computed once per ensemble by the caller.
gl::FloorMap floorMapFor(const data::Ensemble& ensemble, const data::Member& mean,
                         const std::vector<float>& columnMaximum,
                         const gl::RenderSettings& settings);

}  // namespace ensil::app

// Per-member figures for the member table: how far each member is from a reference field (the
// mean member) in the similarity measure of similarity.h, and how outlying a member's
// isosurface is on average. Pure functions on plain values; run on any thread.
#pragma once

#include <span>
#include <stop_token>
#include <vector>

#include "data/ensemble.h"
#include "data/job.h"
#include "data/packed_mesh.h"

namespace ensil::prep {

// For every member i, the distance of similarity.h between member i and `field`:
//   d(i) = sum_x ( sqrt|f_i(x) - mu| - sqrt|g(x) - mu| )^2 / m_i
// over the m_i points finite in both; +infinity when they share no finite point. With the mean
// member as `field` this is each member's distance to the mean member. Summed in double.
// Throws data::Cancelled, data::Error(InvalidArgument) for an empty ensemble, a non-finite
// isovalue, or a field or member whose value count differs from the grid's point count.
std::vector<double> distancesToField(const data::Ensemble& ensemble, std::span<const float> field,
                                     float isovalue, const std::stop_token& stop = {},
                                     const data::Progress& progress = {});

// The mean of the per-vertex outlyingness stored in the mesh (decoded and rescaled, as the
// vertex shader reads it); NaN for a mesh with no vertices (no isosurface to be outlying).
double meanOutlyingness(const data::PackedMesh& mesh);

}  // namespace ensil::prep

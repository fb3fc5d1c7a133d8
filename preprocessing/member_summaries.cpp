#include "preprocessing/member_summaries.h"

#include <cmath>
#include <limits>
#include <string>

#include "data/error.h"
#include "preprocessing/mesh_packing.h"
#include "preprocessing/similarity.h"

namespace ensil::prep {
namespace {

void validate(const data::Ensemble& ensemble, std::span<const float> field, float isovalue) {
    checkDistanceArguments(ensemble, isovalue, "measure the distances to the mean");
    const std::size_t points = ensemble.grid.pointCount();
    if (field.size() != points) {
        throw data::Error(data::ErrorKind::InvalidArgument,
                          "the reference field has " + std::to_string(field.size()) +
                              " values but the grid has " + std::to_string(points) + " points");
    }
}

}  // namespace

std::vector<double> distancesToField(const data::Ensemble& ensemble, std::span<const float> field,
                                     float isovalue, const std::stop_token& stop,
                                     const data::Progress& progress) {
    validate(ensemble, field, isovalue);
    const double mu = isovalue;
    // The field's square roots are the same for every member: compute them once (NaN where
    // the field is not finite, which then fails the validity test below).
    std::vector<double> fieldRoots(field.size());
    for (std::size_t p = 0; p < field.size(); ++p) {
        const double diff = std::abs(static_cast<double>(field[p]) - mu);
        fieldRoots[p] = diff <= std::numeric_limits<double>::max()
                            ? std::sqrt(diff)
                            : std::numeric_limits<double>::quiet_NaN();
    }
    const std::size_t n = ensemble.memberCount();
    std::vector<double> distances(n);
    for (std::size_t m = 0; m < n; ++m) {
        data::throwIfStopped(stop);
        const float* values = ensemble.members[m].values.data();
        double sum = 0.0;
        std::size_t common = 0;
        for (std::size_t p = 0; p < fieldRoots.size(); ++p) {
            const double diff = std::abs(static_cast<double>(values[p]) - mu);
            // NaN and infinity (in the member or the field) fail these comparisons.
            if (!(diff <= std::numeric_limits<double>::max()) || std::isnan(fieldRoots[p])) {
                continue;
            }
            const double d = std::sqrt(diff) - fieldRoots[p];
            sum += d * d;
            ++common;
        }
        distances[m] = common > 0 ? sum / static_cast<double>(common)
                                  : std::numeric_limits<double>::infinity();
        data::report(progress, static_cast<double>(m + 1) / static_cast<double>(n));
    }
    return distances;
}

double meanOutlyingness(const data::PackedMesh& mesh) {
    if (mesh.vertices.empty()) return std::numeric_limits<double>::quiet_NaN();
    double sum = 0.0;
    for (const data::PackedVertex& v : mesh.vertices) {
        sum += static_cast<double>(unpackHalf(v.outlyingness));
    }
    return sum / static_cast<double>(mesh.vertices.size()) *
           static_cast<double>(mesh.outlyingnessScale);
}

}  // namespace ensil::prep

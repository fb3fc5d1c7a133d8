#include "preprocessing/member_summaries.h"

#include <tbb/parallel_for.h>

#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "data/error.h"
#include "preprocessing/lanes.h"
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

// The mean over the points valid in both of (sqrt|f - mu| - root)^2, infinite when there are
// none. Summed in lanes (preprocessing/lanes.h), the selects (a missing value adds 0) keeping the
// loop free of branches.
double distanceToRoots(std::span<const float> values, std::span<const double> roots, double mu) {
    std::array<double, kLanes> sums{};
    std::array<std::size_t, kLanes> counts{};
    forEachInLanes(roots.size(), [&](std::size_t lane, std::size_t p) {
        const double diff = std::abs(static_cast<double>(values[p]) - mu);
        // NaN and infinity (in the member or the field) fail these comparisons.
        const bool valid = diff <= std::numeric_limits<double>::max() && roots[p] == roots[p];
        const double d = valid ? std::sqrt(diff) - roots[p] : 0.0;
        sums[lane] += d * d;
        counts[lane] += valid ? 1 : 0;
    });
    double sum = 0.0;
    std::size_t common = 0;
    for (std::size_t lane = 0; lane < kLanes; ++lane) {
        sum += sums[lane];
        common += counts[lane];
    }
    return common > 0 ? sum / static_cast<double>(common) : std::numeric_limits<double>::infinity();
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
    // The members on every core, each summed alone in the same order whatever the threads (and
    // as the streamed preprocess sums one member read by itself).
    data::PartsProgress membersDone(progress, n);
    tbb::parallel_for(std::size_t{0}, n, [&](std::size_t m) {
        data::throwIfStopped(stop);
        distances[m] = distanceToRoots(ensemble.members[m].values, fieldRoots, mu);
        membersDone.partDone();
    });
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

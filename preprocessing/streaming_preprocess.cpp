#include "preprocessing/streaming_preprocess.h"

#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "data/display_frame.h"
#include "data/ensemble_part.h"
#include "data/error.h"
#include "data/reader_support.h"
#include "preprocessing/member_summaries.h"
#include "preprocessing/vertex_attributes.h"

namespace ensil::prep {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

constexpr std::size_t kMiB = std::size_t{1} << 20;

std::string mib(std::size_t bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.0f MiB",
                  std::ceil(static_cast<double>(bytes) / static_cast<double>(kMiB)));
    return text;
}

// Bytes a layer of the slab pass costs: every member's values, and the moments' double sums,
// counts and float results for the layer (computeEnsembleMoments), and a member's scratch of
// doubles in the reader (packed integers are unpacked through one).
std::size_t bytesPerLayer(std::size_t layerPoints, std::size_t members) {
    return layerPoints * (4 * members + 40);
}

// Bytes one member costs while it is meshed: its values, distancesToField's square roots of the
// mean (doubles), and the meshes on their way through marching cubes, decimation and packing,
// taken as 16 bytes a grid point (a dense isosurface of the demo makes a few; a noisy field more).
std::size_t bytesPerMember(std::size_t points) { return points * (4 + 8 + 16); }

std::string shapeTextOf(const data::Grid& grid) {
    return data::shapeText(grid.nx(), grid.ny(), grid.nz());
}

}  // namespace

StreamingPlan planStreaming(const data::EnsembleDescription& d, std::size_t memoryLimit,
                            std::size_t threads) {
    // oneTBB's count follows the process's CPU affinity (mpirun binds each rank to its cores).
    if (threads == 0) threads = static_cast<std::size_t>(tbb::info::default_concurrency());
    const std::size_t layer = d.grid.nx() * d.grid.ny();
    const std::size_t nz = d.grid.nz();
    const std::size_t points = layer * nz;
    const std::size_t n = d.members;
    StreamingPlan plan;
    plan.memoryLimit = memoryLimit;
    // Kept for the whole run: the moments (mean and variance, floats, whole grid) and the
    // distance sums with the blocks they are added through (three of about 4 MiB).
    // (twice: the total and the slab's own, merged in slab order).
    plan.resultBytes = 8 * points + 48 * n * n + 12 * kMiB;
    plan.memberBytes = bytesPerMember(points);
    const std::size_t perLayer = bytesPerLayer(layer, n);
    const std::size_t least = plan.resultBytes + std::max(2 * perLayer, plan.memberBytes);
    if (memoryLimit < least) {
        throw data::Error(data::ErrorKind::OutOfMemory,
                          "a memory limit of " + mib(memoryLimit) + " is too small for '" +
                              d.variable + "' (" + std::to_string(n) + " members of " +
                              shapeTextOf(d.grid) + " points): streaming needs at least " +
                              mib(least) +
                              " (the moments of the whole grid, two layers of every member, or "
                              "one member while it is meshed); give --memory-limit " +
                              mib(least) + " or more");
    }
    const std::size_t room = memoryLimit - plan.resultBytes;
    const std::size_t layers = std::min(nz, room / perLayer);
    // As few slabs as the budget allows.
    plan.slabs = evenSlabs(d, (nz + layers - 1) / layers);
    std::size_t thickest = 0;
    for (const data::EnsemblePart& slab : plan.slabs)
        thickest = std::max(thickest, slab.layerCount);
    plan.slabBytes = thickest * perLayer;
    plan.membersAtOnce =
        std::clamp<std::size_t>(room / plan.memberBytes, 1, std::max<std::size_t>(1, threads));
    return plan;
}

std::vector<data::EnsemblePart> evenSlabs(const data::EnsembleDescription& d, std::size_t count) {
    const std::size_t nz = d.grid.nz();
    count = std::max<std::size_t>(1, std::min(count, nz / 2));
    const std::size_t base = nz / count, extra = nz % count;
    std::vector<data::EnsemblePart> slabs;
    std::size_t first = 0;
    for (std::size_t s = 0; s < count; ++s) {
        const std::size_t thickness = base + (s < extra ? 1 : 0);
        slabs.push_back({0, d.members, first, thickness});
        first += thickness;
    }
    return slabs;
}

SlabSums emptySlabSums(const data::EnsembleDescription& d, float isovalue) {
    SlabSums sums;
    const std::size_t points = d.grid.pointCount();
    constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
    sums.moments.mean.name = "mean";
    sums.moments.mean.values.assign(points, kNaN);
    sums.moments.variance.assign(points, kNaN);
    sums.distances = DistanceSums(d.members, isovalue);
    sums.validValues.assign(d.members, 0.0);
    return sums;
}

DistanceSums addSlab(SlabSums& sums, const data::DataSelection& selection,
                     const data::EnsembleDescription& description, const data::EnsemblePart& slab,
                     const std::stop_token& stop) {
    const data::Ensemble part = data::openEnsemblePart(selection, description, slab, stop);
    // The moments are per point: the slab's are the whole grid's over its layers.
    const EnsembleMoments moments = computeEnsembleMoments(part, stop);
    const std::size_t offset = slab.firstLayer * description.grid.nx() * description.grid.ny();
    std::copy(moments.mean.values.begin(), moments.mean.values.end(),
              sums.moments.mean.values.begin() + static_cast<std::ptrdiff_t>(offset));
    std::copy(moments.variance.begin(), moments.variance.end(),
              sums.moments.variance.begin() + static_cast<std::ptrdiff_t>(offset));
    std::vector<std::span<const float>> values;
    values.reserve(part.memberCount());
    for (std::size_t m = 0; m < part.memberCount(); ++m) {
        const data::FieldValues& v = part.members[m].values;
        values.emplace_back(v.data(), v.size());
        std::size_t valid = 0;
        float lo = std::numeric_limits<float>::infinity(), hi = -lo;
        for (const float x : v) {
            const bool ok = x == x;  // openEnsemblePart made infinities NaN
            valid += ok ? 1 : 0;
            lo = ok ? std::min(lo, x) : lo;
            hi = ok ? std::max(hi, x) : hi;
        }
        sums.validValues[slab.firstMember + m] += static_cast<double>(valid);
        sums.minimum = std::min(sums.minimum, static_cast<double>(lo));
        sums.maximum = std::max(sums.maximum, static_cast<double>(hi));
    }
    DistanceSums distances(description.members, sums.distances.isovalue());
    distances.add(values, stop);
    sums.infiniteValues += static_cast<double>(part.infiniteValues);
    return distances;
}

MemberResult meshMember(const data::DataSelection& selection,
                        const data::EnsembleDescription& description, std::size_t member,
                        const EnsembleMoments& moments, const AxisTables& axes,
                        const PipelineOptions& options, const std::stop_token& stop) {
    const data::Ensemble one =
        data::openEnsemblePart(selection, description, {member, 1, 0, description.grid.nz()}, stop);
    MemberResult r;
    r.meshed = meshField(one.grid, one.members.front().values, options.isovalue, axes, &moments,
                         options, stop);
    const data::FieldValues& mean = moments.mean.values;
    r.distanceToMean =
        distancesToField(one, {mean.data(), mean.size()}, options.isovalue, stop).front();
    return r;
}

namespace {
// Runs fn(i) for every i < count, `atOnce` at a time, each thread holding one member at most.
template <typename Fn>
void forMembersAtOnce(std::size_t count, std::size_t atOnce, const std::stop_token& stop,
                      const data::Progress& progress, Fn&& fn) {
    data::PartsProgress membersDone(progress, count);
    tbb::task_arena arena(static_cast<int>(std::max<std::size_t>(1, atOnce)));
    arena.execute([&] {
        tbb::parallel_for(std::size_t{0}, count, [&](std::size_t i) {
            if (stop.stop_requested()) return;
            // Isolated: a thread waiting inside marching cubes' own parallel loop must not start
            // another member, or more members than the budget allows would be in memory.
            tbb::this_task_arena::isolate([&] { fn(i); });
            membersDone.partDone();
        });
    });
    data::throwIfStopped(stop);
}
}  // namespace

std::vector<MemberResult> meshMembers(const data::DataSelection& selection,
                                      const data::EnsembleDescription& d,
                                      const std::vector<std::size_t>& members,
                                      const EnsembleMoments& moments, const AxisTables& axes,
                                      const PipelineOptions& options, std::size_t atOnce,
                                      const std::stop_token& stop, const data::Progress& progress) {
    std::vector<MemberResult> results(members.size());
    forMembersAtOnce(members.size(), atOnce, stop, progress, [&](std::size_t i) {
        if (members[i] == kMeanMember) {
            // The mean has no outlyingness of its own, as in buildIsovalueMeshes.
            results[i].meshed = meshField(d.grid, moments.mean.values, options.isovalue, axes,
                                          nullptr, options, stop);
        } else {
            results[i] = meshMember(selection, d, members[i], moments, axes, options, stop);
        }
    });
    return results;
}

std::vector<double> distancesToMeanOf(const data::DataSelection& selection,
                                      const data::EnsembleDescription& d,
                                      const std::vector<std::size_t>& members,
                                      const EnsembleMoments& moments, float isovalue,
                                      std::size_t atOnce, const std::stop_token& stop,
                                      const data::Progress& progress) {
    std::vector<double> distances(members.size());
    const data::FieldValues& mean = moments.mean.values;
    forMembersAtOnce(members.size(), atOnce, stop, progress, [&](std::size_t i) {
        const data::Ensemble one =
            data::openEnsemblePart(selection, d, {members[i], 1, 0, d.grid.nz()}, stop);
        distances[i] = distancesToField(one, {mean.data(), mean.size()}, isovalue, stop).front();
    });
    return distances;
}

std::vector<std::size_t> concludeSlabs(const SlabSums& sums, const data::DataSelection& selection,
                                       const data::EnsembleDescription& d,
                                       const RangeCheck& checkRange, StreamedEnsemble& out) {
    std::vector<std::size_t> keep;
    for (std::size_t m = 0; m < d.members; ++m) {
        (sums.validValues[m] > 0.0 ? keep : out.membersWithoutData).push_back(m);
    }
    if (keep.empty()) {
        throw data::Error(data::ErrorKind::AllValuesMissing,
                          "every value of '" + d.variable + "' in " +
                              data::sourceOf(selection.paths) +
                              " is missing (fill value or outside valid_range): there is "
                              "nothing to draw");
    }
    for (const std::size_t m : keep) out.memberNames.push_back(d.memberNames.at(m));
    out.minimum = sums.minimum;
    out.maximum = sums.maximum;
    out.infiniteValues = sums.infiniteValues;
    if (checkRange) checkRange(out.minimum, out.maximum);
    out.distances =
        (keep.size() == d.members ? sums.distances : sums.distances.subset(keep)).finish();
    return keep;
}

void collectMembers(StreamedEnsemble& out, std::vector<MemberResult>&& results,
                    double wallSeconds) {
    const std::size_t k = results.size() - 1;
    out.meshes.members.resize(k);
    out.distancesToMean.assign(k, 0.0);
    std::vector<FieldMeshStats> stats;
    for (std::size_t i = 0; i < results.size(); ++i) {
        stats.push_back(results[i].meshed.stats);
        if (i < k) {
            out.meshes.members[i] = std::move(results[i].meshed.mesh);
            out.distancesToMean[i] = results[i].distanceToMean;
        } else {
            out.meshes.mean = std::move(results[i].meshed.mesh);
        }
    }
    out.memberSeconds = wallSeconds;
    summariseMeshes(out.meshes, stats, wallSeconds);
}

SlabSums sumSlabs(const data::DataSelection& selection, const data::EnsembleDescription& d,
                  const std::vector<data::EnsemblePart>& slabs, float isovalue,
                  const std::stop_token& stop, const data::Progress& progress) {
    SlabSums sums = emptySlabSums(d, isovalue);
    for (std::size_t s = 0; s < slabs.size(); ++s) {
        sums.distances.merge(addSlab(sums, selection, d, slabs[s], stop));
        data::report(progress, static_cast<double>(s + 1) / static_cast<double>(slabs.size()));
    }
    return sums;
}

StreamedEnsemble streamPreprocess(const data::DataSelection& selection,
                                  const data::EnsembleDescription& d, const StreamingPlan& plan,
                                  const PipelineOptions& options, float verticalExaggeration,
                                  const RangeCheck& checkRange, const std::stop_token& stop,
                                  const data::Progress& progress) {
    StreamedEnsemble out;
    out.plan = plan;
    const float iso = options.isovalue;
    out.meshes.isovalue = iso;

    // Pass 1: slabs of every member.
    auto start = Clock::now();
    const SlabSums sums = sumSlabs(selection, d, plan.slabs, iso, stop,
                                   [&](double f) { data::report(progress, 0.4 * f); });
    out.slabSeconds = since(start);
    const std::vector<std::size_t> keep = concludeSlabs(sums, selection, d, checkRange, out);

    // Pass 2: each kept member whole, and the mean member, a few at a time.
    start = Clock::now();
    const AxisTables axes = axisTables(data::DisplayFrame(d.grid, verticalExaggeration));
    std::vector<std::size_t> fields = keep;
    fields.push_back(kMeanMember);
    std::vector<MemberResult> results =
        meshMembers(selection, d, fields, sums.moments, axes, options, plan.membersAtOnce, stop,
                    [&](double f) { data::report(progress, 0.4 + 0.6 * f); });
    collectMembers(out, std::move(results), since(start));
    return out;
}

}  // namespace ensil::prep

#include "data/thinned_ensemble.h"

#include <algorithm>
#include <limits>
#include <string>

#include "data/ensemble_part.h"
#include "data/error.h"
#include "data/reader_support.h"

namespace ensil::data {

std::vector<std::size_t> thinnedIndices(std::size_t n, std::size_t stride) {
    stride = std::max<std::size_t>(1, stride);
    std::vector<std::size_t> indices;
    for (std::size_t i = 0; i + 1 < n; i += stride) indices.push_back(i);
    if (n > 0) indices.push_back(n - 1);
    return indices;
}

namespace {

Axis thinnedAxis(const Axis& axis, std::size_t stride) {
    Axis thinned = axis;
    thinned.values.clear();
    for (const std::size_t i : thinnedIndices(axis.size(), stride)) {
        thinned.values.push_back(axis.values[i]);
    }
    return thinned;
}

std::size_t thinnedCount(std::size_t n, std::size_t stride) {
    return thinnedIndices(n, stride).size();
}

}  // namespace

Grid thinnedGrid(const Grid& grid, std::size_t stride) {
    return {thinnedAxis(grid.x(), stride), thinnedAxis(grid.y(), stride),
            thinnedAxis(grid.z(), stride)};
}

std::size_t thinningStrideFor(const EnsembleDescription& d, std::size_t budgetBytes) {
    const std::size_t largest = std::max({d.grid.nx(), d.grid.ny(), d.grid.nz()});
    for (std::size_t stride = 2; stride <= std::max<std::size_t>(2, largest); ++stride) {
        const std::size_t points = thinnedCount(d.grid.nx(), stride) *
                                   thinnedCount(d.grid.ny(), stride) *
                                   thinnedCount(d.grid.nz(), stride);
        if (d.members * points * sizeof(float) <= budgetBytes) return stride;
    }
    return 0;
}

Ensemble openThinnedEnsemble(const DataSelection& selection, const EnsembleDescription& d,
                             const std::vector<EnsemblePart>& slabs, std::size_t stride,
                             const std::stop_token& stop, const Progress& progress) {
    const std::string what = "'" + d.variable + "' in " + sourceOf(selection.paths);
    // The slabs must cover the layers in order with every member: checked before any memory.
    std::size_t nextLayer = 0;
    for (const EnsemblePart& slab : slabs) {
        checkEnsemblePart(d, slab, sourceOf(selection.paths));
        if (slab.firstLayer != nextLayer || slab.firstMember != 0 ||
            slab.memberCount != d.members) {
            throw Error(ErrorKind::InvalidArgument,
                        "the slabs to read a thinned copy of " + what +
                            " do not cover its layers in order with every member");
        }
        nextLayer += slab.layerCount;
    }
    if (nextLayer != d.grid.nz()) {
        throw Error(ErrorKind::InvalidArgument, "the slabs to read a thinned copy of " + what +
                                                    " cover " + std::to_string(nextLayer) +
                                                    " of its " + std::to_string(d.grid.nz()) +
                                                    " layers");
    }
    Ensemble thinned = ensembleDescribedBy(d, selection.paths);
    thinned.grid = thinnedGrid(d.grid, stride);
    const std::vector<std::size_t> xs = thinnedIndices(d.grid.nx(), stride);
    const std::vector<std::size_t> ys = thinnedIndices(d.grid.ny(), stride);
    const std::vector<std::size_t> zs = thinnedIndices(d.grid.nz(), stride);
    for (Member& member : thinned.members) member.values.resize(thinned.grid.pointCount());
    const std::size_t layerPoints = thinned.grid.nx() * thinned.grid.ny();
    auto nextZ = zs.begin();
    std::size_t done = 0;
    for (const EnsemblePart& slab : slabs) {
        throwIfStopped(stop);
        const std::size_t end = slab.firstLayer + slab.layerCount;
        if (nextZ == zs.end() || *nextZ >= end) {
            // No layer of this slab is kept: not read at all.
            done += slab.layerCount;
            report(progress, static_cast<double>(done) / static_cast<double>(d.grid.nz()));
            continue;
        }
        const Ensemble part = openEnsemblePart(selection, d, slab, stop);
        thinned.infiniteValues += part.infiniteValues;
        for (std::size_t m = 0; m < part.memberCount(); ++m) {
            if (thinned.members[m].name.empty()) thinned.members[m].name = part.members[m].name;
        }
        for (; nextZ != zs.end() && *nextZ < end; ++nextZ) {
            const std::size_t kz = static_cast<std::size_t>(nextZ - zs.begin());
            const std::size_t localZ = *nextZ - slab.firstLayer;
            for (std::size_t m = 0; m < part.memberCount(); ++m) {
                const FieldValues& from = part.members[m].values;
                float* to = thinned.members[m].values.data() + kz * layerPoints;
                for (std::size_t jy = 0; jy < ys.size(); ++jy) {
                    const std::size_t row = part.grid.index(0, ys[jy], localZ);
                    for (std::size_t ix = 0; ix < xs.size(); ++ix) {
                        to[jy * xs.size() + ix] = from[row + xs[ix]];
                    }
                }
            }
        }
        done += slab.layerCount;
        report(progress, static_cast<double>(done) / static_cast<double>(d.grid.nz()));
    }
    return thinned;
}

}  // namespace ensil::data

#include "preprocessing/marching_cubes.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <cmath>
#include <limits>
#include <numeric>

#include "preprocessing/marching_cubes_table.h"

namespace ensil::prep {
namespace {

constexpr std::uint32_t kNoVertex = std::numeric_limits<std::uint32_t>::max();

bool crosses(float a, float b, float iso) {
    // NaN compares false both ways: an edge touching a missing value never crosses.
    return (a > iso && b <= iso) || (a <= iso && b > iso);
}

struct Extraction {
    const data::Grid& grid;
    std::span<const float> f;
    float iso;
    std::size_t nx, ny, nz, nxy;
    // Vertex id per grid edge, by axis, indexed by the edge's lower grid point.
    std::array<std::vector<std::uint32_t>, 3> edgeVertex;

    Extraction(const data::Grid& g, std::span<const float> values, float isovalue)
        : grid(g), f(values), iso(isovalue), nx(g.nx()), ny(g.ny()), nz(g.nz()), nxy(nx * ny) {
        for (auto& ev : edgeVertex) ev.assign(g.pointCount(), kNoVertex);
    }

    // Calls visit(axis, lowerPoint, upperPoint) for each crossing edge starting in layer k.
    template <typename Visit>
    void forEachCrossing(std::size_t k, Visit&& visit) const {
        const std::array<std::size_t, 3> step{1, nx, nxy};
        for (std::size_t j = 0; j < ny; ++j) {
            for (std::size_t i = 0; i < nx; ++i) {
                const std::size_t p = i + nx * j + nxy * k;
                const std::array<bool, 3> has{i + 1 < nx, j + 1 < ny, k + 1 < nz};
                for (int a = 0; a < 3; ++a) {
                    const auto ai = static_cast<std::size_t>(a);
                    if (has[ai] && crosses(f[p], f[p + step[ai]], iso)) visit(a, p, p + step[ai]);
                }
            }
        }
    }

    std::size_t cellCase(std::size_t i, std::size_t j, std::size_t k, bool& valid) const {
        std::size_t mask = 0;
        valid = true;
        for (int c = 0; c < 8; ++c) {
            const std::size_t p =
                (i + (c & 1)) + nx * (j + ((c >> 1) & 1)) + nxy * (k + ((c >> 2) & 1));
            const float v = f[p];
            valid = valid && !std::isnan(v);
            mask |= static_cast<std::size_t>(v > iso) << c;
        }
        return mask;
    }

    [[nodiscard]] std::uint32_t vertexOf(std::size_t i, std::size_t j, std::size_t k,
                                         int edge) const {
        const int c = mc::kEdgeCorner[static_cast<std::size_t>(edge)];
        const std::size_t p =
            (i + (c & 1)) + nx * (j + ((c >> 1) & 1)) + nxy * (k + ((c >> 2) & 1));
        return edgeVertex[static_cast<std::size_t>(mc::edgeAxis(edge))][p];
    }
};

// Parallel over layers: count per layer, prefix-sum, size the output, then fill each layer at
// its offset, so the result is the same whatever the thread count.
template <typename Count, typename Resize, typename Fill>
void countThenFill(std::size_t layers, const std::stop_token& stop, Count&& count, Resize&& resize,
                   Fill&& fill) {
    std::vector<std::size_t> offsets(layers + 1, 0);
    std::atomic<bool> stopped{false};
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, layers), [&](const auto& r) {
        for (std::size_t k = r.begin(); k != r.end(); ++k) {
            if (stop.stop_requested()) stopped = true;
            if (!stopped) offsets[k + 1] = count(k);
        }
    });
    if (stopped) throw data::Cancelled();
    std::partial_sum(offsets.begin(), offsets.end(), offsets.begin());
    resize(offsets.back());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, layers), [&](const auto& r) {
        for (std::size_t k = r.begin(); k != r.end(); ++k) fill(k, offsets[k]);
    });
}

}  // namespace

data::TriangleMesh extractIsosurface(const data::Grid& grid, std::span<const float> values,
                                     float isovalue, const std::stop_token& stop,
                                     const data::Progress& progress) {
    data::TriangleMesh mesh;
    if (values.size() != grid.pointCount() || grid.nz() < 2) return mesh;
    Extraction x(grid, values, isovalue);

    // 1. One vertex per crossing grid edge, linearly interpolated along it.
    countThenFill(
        x.nz, stop,
        [&](std::size_t k) {
            std::size_t n = 0;
            x.forEachCrossing(k, [&](int, std::size_t, std::size_t) { ++n; });
            return n;
        },
        [&](std::size_t total) { mesh.positions.resize(total); },
        [&](std::size_t k, std::size_t first) {
            std::size_t id = first;
            x.forEachCrossing(k, [&](int a, std::size_t p, std::size_t q) {
                x.edgeVertex[static_cast<std::size_t>(a)][p] = static_cast<std::uint32_t>(id);
                const float t = (isovalue - values[p]) / (values[q] - values[p]);
                // Grid indices of the edge's lower point (integer division on purpose).
                const std::size_t pi = p % x.nx, pj = (p / x.nx) % x.ny, pk = p / x.nxy;
                glm::vec3 pos{static_cast<float>(pi), static_cast<float>(pj),
                              static_cast<float>(pk)};
                pos[a] += t;
                mesh.positions[id++] = pos;
            });
        });
    data::report(progress, 0.5);

    // 2. Triangles from the case table, cell layer by cell layer.
    const auto& table = mc::caseTable();
    const auto forEachCell = [&](std::size_t k, auto&& visit) {
        for (std::size_t j = 0; j + 1 < x.ny; ++j) {
            for (std::size_t i = 0; i + 1 < x.nx; ++i) {
                bool valid = false;
                const std::size_t mask = x.cellCase(i, j, k, valid);
                if (valid && mask != 0 && mask != 255) visit(i, j, mask);
            }
        }
    };
    countThenFill(
        x.nz - 1, stop,
        [&](std::size_t k) {
            std::size_t n = 0;
            forEachCell(k, [&](std::size_t, std::size_t, std::size_t mask) {
                for (const std::int8_t* e = table.triangles[mask].data(); *e >= 0; ++e) ++n;
            });
            return n;
        },
        [&](std::size_t total) { mesh.indices.resize(total); },
        [&](std::size_t k, std::size_t first) {
            std::size_t out = first;
            forEachCell(k, [&](std::size_t i, std::size_t j, std::size_t mask) {
                for (const std::int8_t* e = table.triangles[mask].data(); *e >= 0; ++e) {
                    mesh.indices[out++] = x.vertexOf(i, j, k, *e);
                }
            });
        });
    data::report(progress, 1.0);
    return mesh;
}

}  // namespace ensil::prep

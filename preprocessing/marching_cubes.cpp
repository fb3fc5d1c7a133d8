#include "preprocessing/marching_cubes.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <array>
#include <atomic>
#include <bit>
#include <cstdint>
#include <numeric>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "preprocessing/marching_cubes_table.h"

namespace ensil::prep {
namespace {

// The extraction works on bit rows, in the spirit of flying edges: one pass over the values
// turns each grid row (fixed j, k) into two bit sets, "inside" (f > mu) and "valid" (not NaN);
// everything after that is 64 points per word. Crossing edges and the cells that make
// triangles are found by bitwise operations on neighbouring rows, so the (mostly empty) rest
// of the grid costs a few instructions per 64 points, and no grid-sized index arrays are
// needed: a vertex's id is its row's first id plus the rank of its edge among the row's
// crossings (a popcount).
using Word = std::uint64_t;
constexpr std::size_t kBits = 64;

struct Bits {
    std::size_t nx, ny, nz, words, rows;
    std::vector<Word> inside, valid;
    std::array<std::vector<Word>, 3> cross;  // by axis: bit i = the edge from point i crosses
    // Per row and axis: the local id (within the row) of the first crossing in each word.
    // A row's vertices are its x crossings, then its y crossings, then its z crossings.
    std::array<std::vector<std::uint32_t>, 3> firstInWord;
    std::vector<std::uint32_t> rowVertices, rowTriangles;  // counts, then offsets

    Bits(std::size_t x, std::size_t y, std::size_t z)
        : nx(x), ny(y), nz(z), words((x + kBits - 1) / kBits), rows(y * z) {
        inside.assign(rows * words, 0);
        valid.assign(rows * words, 0);
        for (auto& c : cross) c.assign(rows * words, 0);
        for (auto& f : firstInWord) f.assign(rows * words, 0);
        rowVertices.assign(rows + 1, 0);
        rowTriangles.assign(rows + 1, 0);
    }
    [[nodiscard]] std::size_t row(std::size_t j, std::size_t k) const { return j + ny * k; }
};

// Bits i and i + 1 of a bit row (bit i in bit 0); i + 1 must be a point of the row.
Word pairAt(const Word* row, std::size_t i) {
    const std::size_t w = i / kBits, b = i % kBits;
    Word pair = row[w] >> b;
    if (b == kBits - 1) pair |= row[w + 1] << 1;
    return pair & 3U;
}

// Word w of the row shifted down by one point (bit i holds point i + 1).
Word nextPoint(const Word* row, std::size_t w, std::size_t words) {
    return (row[w] >> 1) | (w + 1 < words ? row[w + 1] << (kBits - 1) : 0);
}

// Fills the inside and valid bits of one row of nx values. NaN compares false both ways, so a
// missing value is never inside and never valid.
void classifyRow(const float* f, std::size_t nx, float iso, Word* inside, Word* valid) {
    for (std::size_t w = 0; w * kBits < nx; ++w) {
        const std::size_t begin = w * kBits, end = std::min(nx, begin + kBits);
        Word in = 0, ok = 0;
        std::size_t i = begin;
#if defined(__SSE2__)
        const __m128 level = _mm_set1_ps(iso);
        for (; i + 4 <= end; i += 4) {
            const __m128 v = _mm_loadu_ps(f + i);
            const auto shift = i - begin;
            in |= static_cast<Word>(_mm_movemask_ps(_mm_cmpgt_ps(v, level))) << shift;
            ok |= static_cast<Word>(_mm_movemask_ps(_mm_cmpord_ps(v, v))) << shift;
        }
#endif
        for (; i < end; ++i) {
            in |= static_cast<Word>(f[i] > iso) << (i - begin);
            ok |= static_cast<Word>(f[i] == f[i]) << (i - begin);
        }
        inside[w] = in;
        valid[w] = ok;
    }
}

// How many triangles each case makes.
const std::array<std::uint8_t, 256>& triangleCounts() {
    static const std::array<std::uint8_t, 256> counts = [] {
        std::array<std::uint8_t, 256> c{};
        const auto& table = mc::caseTable();
        for (std::size_t m = 0; m < 256; ++m) {
            std::size_t n = 0;
            while (table.triangles[m][n] >= 0) ++n;
            c[m] = static_cast<std::uint8_t>(n / 3);
        }
        return c;
    }();
    return counts;
}

// Per cell edge: its axis, the x offset of its lower point and the offset of that point's row.
struct EdgeRef {
    std::size_t axis, dx, dy, dz;
};
const std::array<EdgeRef, 12>& edgeRefs() {
    static const std::array<EdgeRef, 12> refs = [] {
        std::array<EdgeRef, 12> r{};
        for (std::size_t e = 0; e < 12; ++e) {
            const auto c = static_cast<std::size_t>(mc::kEdgeCorner[e]);
            r[e] = {static_cast<std::size_t>(mc::edgeAxis(static_cast<int>(e))), c & 1U,
                    (c >> 1) & 1U, (c >> 2) & 1U};
        }
        return r;
    }();
    return refs;
}

// The cells of cell row (j, k) that make triangles: all eight corners valid, not all on one
// side. Calls visit(i, caseMask) for each, in increasing i.
template <typename Visit>
void forEachActiveCell(const Bits& b, std::size_t j, std::size_t k, Visit&& visit) {
    const std::size_t W = b.words;
    const Word* in00 = &b.inside[b.row(j, k) * W];
    const Word* in10 = &b.inside[b.row(j + 1, k) * W];
    const Word* in01 = &b.inside[b.row(j, k + 1) * W];
    const Word* in11 = &b.inside[b.row(j + 1, k + 1) * W];
    const Word* ok00 = &b.valid[b.row(j, k) * W];
    const Word* ok10 = &b.valid[b.row(j + 1, k) * W];
    const Word* ok01 = &b.valid[b.row(j, k + 1) * W];
    const Word* ok11 = &b.valid[b.row(j + 1, k + 1) * W];
    for (std::size_t w = 0; w < W; ++w) {
        // Columns (four points at one i) whose points are all valid, and those that differ.
        const Word okColumn = ok00[w] & ok10[w] & ok01[w] & ok11[w];
        const Word okColumnNext = nextPoint(ok00, w, W) & nextPoint(ok10, w, W) &
                                  nextPoint(ok01, w, W) & nextPoint(ok11, w, W);
        const Word mixed = (in00[w] ^ in10[w]) | (in00[w] ^ in01[w]) | (in00[w] ^ in11[w]);
        const Word mixedNext = (nextPoint(in00, w, W) ^ nextPoint(in10, w, W)) |
                               (nextPoint(in00, w, W) ^ nextPoint(in01, w, W)) |
                               (nextPoint(in00, w, W) ^ nextPoint(in11, w, W));
        // Bits past the row's end are invalid, so the last point starts no cell.
        Word active =
            okColumn & okColumnNext & (mixed | mixedNext | (in00[w] ^ nextPoint(in00, w, W)));
        while (active != 0) {
            const std::size_t i = w * kBits + static_cast<std::size_t>(std::countr_zero(active));
            active &= active - 1;
            const Word mask = pairAt(in00, i) | pairAt(in10, i) << 2 | pairAt(in01, i) << 4 |
                              pairAt(in11, i) << 6;
            visit(i, static_cast<std::size_t>(mask));
        }
    }
}

// Parallel over z-layers in blocks, checking the stop token between layers.
template <typename Work>
void forEachLayer(std::size_t layers, const std::stop_token& stop, Work&& work) {
    std::atomic<bool> stopped{false};
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, layers), [&](const auto& r) {
        for (std::size_t k = r.begin(); k != r.end(); ++k) {
            if (stop.stop_requested()) stopped = true;
            if (!stopped) work(k);
        }
    });
    if (stopped) throw data::Cancelled();
}

}  // namespace

data::TriangleMesh extractIsosurface(const data::Grid& grid, std::span<const float> values,
                                     float isovalue, const std::stop_token& stop,
                                     const data::Progress& progress) {
    data::TriangleMesh mesh;
    if (values.size() != grid.pointCount() || grid.nz() < 2) return mesh;
    Bits b(grid.nx(), grid.ny(), grid.nz());
    const std::size_t nx = b.nx, ny = b.ny, nz = b.nz, W = b.words, nxy = nx * ny;

    // 1. The only pass over the values: inside and valid bits per row.
    forEachLayer(nz, stop, [&](std::size_t k) {
        for (std::size_t j = 0; j < ny; ++j) {
            const std::size_t r = b.row(j, k);
            classifyRow(values.data() + nxy * k + nx * j, nx, isovalue, &b.inside[r * W],
                        &b.valid[r * W]);
        }
    });

    // 2. Crossing edges and triangle counts per row. An edge crosses when its ends differ in
    // "inside" and both are valid (so an edge touching NaN never crosses).
    const auto& counts = triangleCounts();
    forEachLayer(nz, stop, [&](std::size_t k) {
        for (std::size_t j = 0; j < ny; ++j) {
            const std::size_t r = b.row(j, k);
            const Word* in = &b.inside[r * W];
            const Word* ok = &b.valid[r * W];
            std::uint32_t local = 0;
            for (std::size_t a = 0; a < 3; ++a) {
                const bool hasNext = a == 0 || (a == 1 ? j + 1 < ny : k + 1 < nz);
                const std::size_t other = a == 1 ? b.row(j + 1, k) : b.row(j, k + 1);
                for (std::size_t w = 0; w < W; ++w) {
                    Word c = 0;
                    if (a == 0) {
                        c = (in[w] ^ nextPoint(in, w, W)) & ok[w] & nextPoint(ok, w, W);
                    } else if (hasNext) {
                        c = (in[w] ^ b.inside[other * W + w]) & ok[w] & b.valid[other * W + w];
                    }
                    b.cross[a][r * W + w] = c;
                    b.firstInWord[a][r * W + w] = local;
                    local += static_cast<std::uint32_t>(std::popcount(c));
                }
            }
            b.rowVertices[r + 1] = local;
            if (j + 1 < ny && k + 1 < nz) {
                std::uint32_t triangles = 0;
                forEachActiveCell(
                    b, j, k, [&](std::size_t, std::size_t mask) { triangles += counts[mask]; });
                b.rowTriangles[r + 1] = triangles;
            }
        }
    });
    std::partial_sum(b.rowVertices.begin(), b.rowVertices.end(), b.rowVertices.begin());
    std::partial_sum(b.rowTriangles.begin(), b.rowTriangles.end(), b.rowTriangles.begin());
    mesh.positions.resize(b.rowVertices.back());
    mesh.indices.resize(3 * static_cast<std::size_t>(b.rowTriangles.back()));
    data::report(progress, 0.5);

    // The vertex on edge `axis` from point i of row r.
    const auto vertexId = [&](std::size_t axis, std::size_t r, std::size_t i) {
        const std::size_t at = r * W + i / kBits;
        const Word below = b.cross[axis][at] & ((Word{1} << (i % kBits)) - 1);
        return b.rowVertices[r] + b.firstInWord[axis][at] +
               static_cast<std::uint32_t>(std::popcount(below));
    };

    // 3. Vertices (linear interpolation along the edge, from its lower point, so a vertex on a
    // face of the box lies exactly on it) and triangles, each row at its offset: the result
    // does not depend on the number of threads.
    const auto& table = mc::caseTable();
    const auto& refs = edgeRefs();
    const std::array<std::size_t, 3> step{1, nx, nxy};
    forEachLayer(nz, stop, [&](std::size_t k) {
        for (std::size_t j = 0; j < ny; ++j) {
            const std::size_t r = b.row(j, k);
            std::size_t id = b.rowVertices[r];
            for (std::size_t a = 0; a < 3; ++a) {
                for (std::size_t w = 0; w < W; ++w) {
                    for (Word c = b.cross[a][r * W + w]; c != 0; c &= c - 1) {
                        const std::size_t i =
                            w * kBits + static_cast<std::size_t>(std::countr_zero(c));
                        const std::size_t p = i + nx * j + nxy * k, q = p + step[a];
                        const float t = (isovalue - values[p]) / (values[q] - values[p]);
                        glm::vec3 pos{static_cast<float>(i), static_cast<float>(j),
                                      static_cast<float>(k)};
                        pos[static_cast<glm::length_t>(a)] += t;
                        mesh.positions[id++] = pos;
                    }
                }
            }
            if (j + 1 >= ny || k + 1 >= nz) continue;
            std::uint32_t* out = &mesh.indices[3 * static_cast<std::size_t>(b.rowTriangles[r])];
            forEachActiveCell(b, j, k, [&](std::size_t i, std::size_t mask) {
                for (const std::int8_t* e = table.triangles[mask].data(); *e >= 0; ++e) {
                    const EdgeRef& ref = refs[static_cast<std::size_t>(*e)];
                    *out++ = vertexId(ref.axis, b.row(j + ref.dy, k + ref.dz), i + ref.dx);
                }
            });
        }
    });
    data::report(progress, 1.0);
    return mesh;
}

}  // namespace ensil::prep

#include "preprocessing/marching_cubes.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cstdint>
#include <numeric>
#include <utility>
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
// of the grid costs a few instructions per 64 points. No grid-sized index arrays are needed:
// a row's vertices are numbered from its offset in crossing order, and the triangles of a cell
// row look their vertices up in the ids of its four point rows only.
using Word = std::uint64_t;
constexpr std::size_t kBits = 64;

struct Bits {
    std::size_t nx, ny, nz, words, rows;
    std::vector<Word> inside, valid;
    std::array<std::vector<Word>, 3> cross;  // by axis: bit i = the edge from point i crosses
    // A row's vertices are its x crossings, then its y crossings, then its z crossings: per
    // row, where each axis's start within the row's vertices.
    std::vector<std::array<std::uint32_t, 3>> axisStart;
    std::vector<std::uint32_t> rowVertices, rowTriangles;  // counts, then offsets
    // The cells that make triangles, found once: per z-layer, (i << 8 | case) in row order, and
    // per row where its cells start in its layer's list.
    std::vector<std::vector<std::uint64_t>> layerCells;
    std::vector<std::uint32_t> rowCellsBegin;

    Bits(std::size_t x, std::size_t y, std::size_t z)
        : nx(x), ny(y), nz(z), words((x + kBits - 1) / kBits), rows(y * z) {
        inside.assign(rows * words, 0);
        valid.assign(rows * words, 0);
        for (auto& c : cross) c.assign(rows * words, 0);
        axisStart.assign(rows, {});
        rowVertices.assign(rows + 1, 0);
        rowTriangles.assign(rows + 1, 0);
        layerCells.resize(z);
        rowCellsBegin.assign(rows + 1, 0);
    }
    [[nodiscard]] std::size_t row(std::size_t j, std::size_t k) const { return j + ny * k; }
};

// Set bits in a word. Without -mpopcnt (x86-64's baseline has no POPCNT) std::popcount becomes
// a call into libgcc, which costs more than this branch-free sum of bit fields.
int countBits(Word x) {
#if defined(__POPCNT__)
    return std::popcount(x);
#else
    x -= (x >> 1) & 0x5555555555555555U;
    x = (x & 0x3333333333333333U) + ((x >> 2) & 0x3333333333333333U);
    x = (x + (x >> 4)) & 0x0f0f0f0f0f0f0f0fU;
    return static_cast<int>((x * 0x0101010101010101U) >> 56);
#endif
}

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

// Per case: how many triangles it makes and which of the 12 edges they use.
struct CaseInfo {
    std::uint8_t triangles = 0;
    std::uint16_t edges = 0;
};
const std::array<CaseInfo, 256>& caseInfo() {
    static const std::array<CaseInfo, 256> info = [] {
        std::array<CaseInfo, 256> c{};
        const auto& table = mc::caseTable();
        for (std::size_t m = 0; m < 256; ++m) {
            std::size_t n = 0;
            for (; table.triangles[m][n] >= 0; ++n) {
                c[m].edges |= static_cast<std::uint16_t>(1U << table.triangles[m][n]);
            }
            c[m].triangles = static_cast<std::uint8_t>(n / 3);
        }
        return c;
    }();
    return info;
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
    const auto& cases = caseInfo();
    forEachLayer(nz, stop, [&](std::size_t k) {
        std::vector<std::uint64_t>& cells = b.layerCells[k];
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
                    if (w == 0) b.axisStart[r][a] = local;
                    b.cross[a][r * W + w] = c;
                    local += static_cast<std::uint32_t>(countBits(c));
                }
            }
            b.rowVertices[r + 1] = local;
            b.rowCellsBegin[r] = static_cast<std::uint32_t>(cells.size());
            if (j + 1 < ny && k + 1 < nz) {
                std::uint32_t triangles = 0;
                forEachActiveCell(b, j, k, [&](std::size_t i, std::size_t mask) {
                    triangles += cases[mask].triangles;
                    cells.push_back(std::uint64_t{i} << 8 | mask);
                });
                b.rowTriangles[r + 1] = triangles;
            }
        }
    });
    std::partial_sum(b.rowVertices.begin(), b.rowVertices.end(), b.rowVertices.begin());
    std::partial_sum(b.rowTriangles.begin(), b.rowTriangles.end(), b.rowTriangles.begin());
    mesh.positions.resize(b.rowVertices.back());
    mesh.indices.resize(3 * static_cast<std::size_t>(b.rowTriangles.back()));
    data::report(progress, 0.5);

    // Writes the vertex ids of row r's crossing edges into ids[axis * nx + i] (the other
    // entries are never read: only crossing edges carry vertices).
    const auto rowIds = [&](std::size_t r, std::uint32_t* ids) {
        for (std::size_t a = 0; a < 3; ++a) {
            std::uint32_t id = b.rowVertices[r] + b.axisStart[r][a];
            for (std::size_t w = 0; w < W; ++w) {
                for (Word c = b.cross[a][r * W + w]; c != 0; c &= c - 1) {
                    ids[a * nx + w * kBits + static_cast<std::size_t>(std::countr_zero(c))] = id++;
                }
            }
        }
    };

    // 3. Vertices (linear interpolation along the edge, from its lower point, so a vertex on a
    // face of the box lies exactly on it) and triangles, each row at its offset: the result
    // does not depend on the number of threads.
    const auto& table = mc::caseTable();
    const auto& refs = edgeRefs();
    const std::array<std::size_t, 3> step{1, nx, nxy};
    forEachLayer(nz, stop, [&](std::size_t k) {
        // Vertex ids of the cell row's four point rows, by (dy, dz): rows j and j + 1 of layers
        // k and k + 1; as j advances, the rows j + 1 become the rows j.
        std::vector<std::uint32_t> scratch(k + 1 < nz ? std::size_t{12} * nx : 0);
        std::array<std::uint32_t*, 4> rowsOf{};
        for (std::size_t s = 0; s < 4 && !scratch.empty(); ++s) rowsOf[s] = &scratch[s * 3 * nx];
        if (!scratch.empty()) {
            rowIds(b.row(0, k), rowsOf[0]);
            rowIds(b.row(0, k + 1), rowsOf[2]);
        }
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
            rowIds(b.row(j + 1, k), rowsOf[1]);
            rowIds(b.row(j + 1, k + 1), rowsOf[3]);
            // Through data(): with no triangles at all the vector is empty, and indexing it
            // would bind a reference to null (UBSan stops there).
            std::uint32_t* out =
                mesh.indices.data() + 3 * static_cast<std::size_t>(b.rowTriangles[r]);
            const std::vector<std::uint64_t>& cells = b.layerCells[k];
            std::array<std::uint32_t, 12> ids{};  // this cell's vertex per edge
            for (std::size_t c = b.rowCellsBegin[r]; c < b.rowCellsBegin[r + 1]; ++c) {
                const std::size_t i = cells[c] >> 8, mask = cells[c] & 0xFFU;
                // Each edge's id once per cell, though several triangles may use it.
                for (unsigned used = cases[mask].edges; used != 0; used &= used - 1) {
                    const auto e = static_cast<std::size_t>(std::countr_zero(used));
                    const EdgeRef& ref = refs[e];
                    ids[e] = rowsOf[ref.dy + 2 * ref.dz][ref.axis * nx + i + ref.dx];
                }
                for (const std::int8_t* e = table.triangles[mask].data(); *e >= 0; ++e) {
                    *out++ = ids[static_cast<std::uint8_t>(*e)];
                }
            }
            std::swap(rowsOf[0], rowsOf[1]);
            std::swap(rowsOf[2], rowsOf[3]);
        }
    });
    data::report(progress, 1.0);
    return mesh;
}

}  // namespace ensil::prep

#include "preprocessing/marching_cubes_table.h"

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace ensil::prep::mc {
namespace {

// Edge along axis a whose lower corner is c (bit a of c clear).
int edgeId(int a, int c) {
    const int u = (a + 1) % 3, v = (a + 2) % 3;
    const int lowBit = u < v ? u : v, highBit = u < v ? v : u;
    const int index = ((c >> lowBit) & 1) | (((c >> highBit) & 1) << 1);
    return a * 4 + index;
}

int edgeBetween(int p, int q) {
    const int diff = p ^ q;
    const int a = diff == 1 ? 0 : diff == 2 ? 1 : 2;
    return edgeId(a, p < q ? p : q);
}

// The four corners of face (axis a, side s), counter-clockwise seen from outside the cube.
std::array<int, 4> faceCorners(int a, int s) {
    const int u = (a + 1) % 3, v = (a + 2) % 3;
    const auto corner = [&](int bu, int bv) { return (s << a) | (bu << u) | (bv << v); };
    // (u, v, a) is right-handed: (0,0),(1,0),(1,1),(0,1) is counter-clockwise seen from +a.
    if (s == 1) return {corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1)};
    return {corner(0, 0), corner(0, 1), corner(1, 1), corner(1, 0)};
}

// Whether two edges lie on a common face of the cube.
bool shareFace(int e1, int e2);

// A fan start whose diagonals never join two vertices on one cube face: such a diagonal lies
// in the face plane, and the neighbouring cell may draw the same edge, which would make the
// mesh non-manifold. Returns -1 when every start has such a diagonal.
int fanStart(const std::vector<int>& loop) {
    const std::size_t n = loop.size();
    for (std::size_t s = 0; s < n; ++s) {
        bool good = true;
        for (std::size_t i = 2; i + 1 < n && good; ++i) {
            good = !shareFace(loop[s], loop[(s + i) % n]);
        }
        if (good) return static_cast<int>(s);
    }
    return -1;
}

CaseTable buildTable() {
    CaseTable table;
    for (int mask = 0; mask < 256; ++mask) {
        const auto inside = [mask](int c) { return ((mask >> c) & 1) != 0; };
        std::array<int, 12> next{};
        next.fill(-1);
        for (int a = 0; a < 3; ++a) {
            for (int s = 0; s < 2; ++s) {
                const auto p = faceCorners(a, s);
                // Crossings in counter-clockwise order; "enter" goes from outside to inside.
                std::vector<std::pair<int, bool>> crossings;
                for (int t = 0; t < 4; ++t) {
                    const int from = p[static_cast<std::size_t>(t)];
                    const int to = p[static_cast<std::size_t>((t + 1) % 4)];
                    if (inside(from) != inside(to)) {
                        crossings.emplace_back(edgeBetween(from, to), inside(to));
                    }
                }
                // Each entry is joined to the crossing after it: that cuts off every inside
                // corner on its own, the same decision from both cells sharing the face.
                for (std::size_t i = 0; i < crossings.size(); ++i) {
                    if (crossings[i].second) {
                        const auto& after = crossings[(i + 1) % crossings.size()];
                        next[static_cast<std::size_t>(crossings[i].first)] = after.first;
                    }
                }
            }
        }
        // Chain the face segments into closed loops and fan-triangulate each loop.
        std::array<bool, 12> used{};
        std::size_t out = 0;
        auto& tris = table.triangles[static_cast<std::size_t>(mask)];
        for (int start = 0; start < 12; ++start) {
            if (next[static_cast<std::size_t>(start)] < 0 ||
                used[static_cast<std::size_t>(start)]) {
                continue;
            }
            std::vector<int> loop;
            for (int e = start; !used[static_cast<std::size_t>(e)];
                 e = next[static_cast<std::size_t>(e)]) {
                used[static_cast<std::size_t>(e)] = true;
                loop.push_back(e);
            }
            const int fan = fanStart(loop);
            if (fan < 0) throw std::logic_error("marching cubes: a loop has no clean fan");
            std::rotate(loop.begin(), loop.begin() + fan, loop.end());
            for (std::size_t i = 1; i + 1 < loop.size(); ++i) {
                // Loops run so that this fan is counter-clockwise seen from lower values.
                tris[out++] = static_cast<std::int8_t>(loop[0]);
                tris[out++] = static_cast<std::int8_t>(loop[i]);
                tris[out++] = static_cast<std::int8_t>(loop[i + 1]);
            }
        }
        tris[out] = -1;
    }
    return table;
}

bool shareFace(int e1, int e2) {
    const auto faces = [](int e) {
        const int a = e / 4;
        int c = 0;  // the edge's lower corner
        for (int corner = 0; corner < 8; ++corner) {
            if (((corner >> a) & 1) == 0 && edgeId(a, corner) == e) c = corner;
        }
        std::array<int, 2> f{};
        int n = 0;
        for (int b = 0; b < 3; ++b) {
            if (b != a) f[static_cast<std::size_t>(n++)] = b * 2 + ((c >> b) & 1);
        }
        return f;
    };
    const auto f1 = faces(e1), f2 = faces(e2);
    return f1[0] == f2[0] || f1[0] == f2[1] || f1[1] == f2[0] || f1[1] == f2[1];
}

}  // namespace

const std::array<int, 12> kEdgeCorner = [] {
    std::array<int, 12> corners{};
    for (int a = 0; a < 3; ++a) {
        for (int c = 0; c < 8; ++c) {
            if (((c >> a) & 1) == 0) corners[static_cast<std::size_t>(edgeId(a, c))] = c;
        }
    }
    return corners;
}();

const CaseTable& caseTable() {
    static const CaseTable table = buildTable();
    return table;
}

}  // namespace ensil::prep::mc

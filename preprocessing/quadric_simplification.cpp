#include "preprocessing/quadric_simplification.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <limits>
#include <utility>
#include <vector>

namespace ensil::prep {
namespace {

using Index = std::uint32_t;
constexpr Index kNoVertex = std::numeric_limits<Index>::max();
// A collapse may turn none of the triangles around the moving vertex by more than about 72
// degrees (cosine 0.3). Only refusing turns past 90 degrees (a fold) left a few sharp spikes:
// on ten demo members the farthest full-resolution vertex lay 0.68 cells from the decimated
// surface against 0.59 with this limit, for 2 % more triangles (still fewer than meshoptimizer's).
constexpr float kMinTurnCosine = 0.3F;
constexpr std::size_t kLastPassShare = 200;

// The sum of area-weighted squared distances to a set of planes, as a function of the offset d
// from the vertex that owns it: d'Ad + 2b'd + c. Kept relative to its own vertex so that every
// number stays small and float is precise enough (around absolute positions of a few hundred
// cells, the constant term would swamp an error of a hundredth of a cell).
struct LocalQuadric {
    float a00 = 0, a01 = 0, a02 = 0, a11 = 0, a12 = 0, a22 = 0;
    float b0 = 0, b1 = 0, b2 = 0, c = 0;
    float weight = 0;  // the planes' summed area

    // A sum of squared distances as the mean over the planes' area (0 without planes).
    [[nodiscard]] float mean(float summed) const { return weight > 0.0F ? summed / weight : 0.0F; }
    [[nodiscard]] float sum(const glm::vec3& d) const {
        return d.x * (a00 * d.x + 2.0F * (a01 * d.y + a02 * d.z + b0)) +
               d.y * (a11 * d.y + 2.0F * (a12 * d.z + b1)) + d.z * (a22 * d.z + 2.0F * b2) + c;
    }
    // Adds `other`, which belongs to a vertex at -d from this one.
    void addFrom(const LocalQuadric& other, const glm::vec3& d) {
        const float shiftedC = other.sum(d);
        b0 += other.a00 * d.x + other.a01 * d.y + other.a02 * d.z + other.b0;
        b1 += other.a01 * d.x + other.a11 * d.y + other.a12 * d.z + other.b1;
        b2 += other.a02 * d.x + other.a12 * d.y + other.a22 * d.z + other.b2;
        c += shiftedC;
        a00 += other.a00, a01 += other.a01, a02 += other.a02;
        a11 += other.a11, a12 += other.a12, a22 += other.a22;
        weight += other.weight;
    }
};

bool isDegenerate(Index i0, Index i1, Index i2) { return i0 == i1 || i1 == i2 || i0 == i2; }

// Each vertex starts with the planes of its own triangles, which pass through it: only A. With
// c the cross product of two edges (its length twice the area, its direction the normal),
// area * n n' = c c' / |c|: one square root and one division a triangle, in float (the edges
// are differences of nearby positions, a cell or less, so float loses nothing that matters).
std::vector<LocalQuadric> planeQuadrics(const std::vector<glm::vec3>& positions,
                                        const std::vector<Index>& indices) {
    std::vector<LocalQuadric> quadrics(positions.size());
    for (std::size_t t = 0; t < indices.size(); t += 3) {
        const glm::vec3 p0 = positions[indices[t]];
        const glm::vec3 c =
            glm::cross(positions[indices[t + 1]] - p0, positions[indices[t + 2]] - p0);
        const float area = std::sqrt(glm::dot(c, c));
        if (!(area > 0.0F) || !std::isfinite(area)) continue;  // no plane
        const glm::vec3 s = c / area;
        const float a00 = c.x * s.x, a01 = c.x * s.y, a02 = c.x * s.z, a11 = c.y * s.y,
                    a12 = c.y * s.z, a22 = c.z * s.z;
        for (int k = 0; k < 3; ++k) {
            LocalQuadric& q = quadrics[indices[t + k]];
            q.a00 += a00, q.a01 += a01, q.a02 += a02, q.a11 += a11, q.a12 += a12, q.a22 += a22;
            q.weight += area;
        }
    }
    return quadrics;
}

// A vertex is on an open border when its triangles' next vertices are not the same multiset as
// their previous vertices (round a closed fan each neighbour is once next, once previous). Three
// sums of the difference, exact in 64-bit arithmetic, compare the multisets in one pass without
// an edge table; sets that differ and agree in all three are not met in practice.
std::vector<std::uint8_t> openBorderVertices(const std::vector<Index>& indices,
                                             std::size_t vertexCount) {
    std::vector<std::uint64_t> sums(vertexCount, 0), squares(vertexCount, 0), xors(vertexCount, 0);
    for (std::size_t t = 0; t < indices.size(); t += 3)
        for (std::size_t e = 0; e < 3; ++e) {
            const std::uint64_t v = indices[t + e];
            const std::uint64_t next = indices[t + (e + 1) % 3],
                                previous = indices[t + (e + 2) % 3];
            sums[v] += next - previous;
            squares[v] += next * next - previous * previous;
            xors[v] ^= next ^ previous;
        }
    std::vector<std::uint8_t> border(vertexCount);
    for (std::size_t v = 0; v < vertexCount; ++v)
        border[v] = (sums[v] | squares[v] | xors[v]) != 0 ? 1 : 0;
    return border;
}

// The working mesh of one pass: vertices compacted after every pass, so that each pass costs
// what is left of the mesh.
struct WorkingMesh {
    std::vector<glm::vec3> positions;
    std::vector<LocalQuadric> quadrics;
    std::vector<std::uint8_t> border;
    std::vector<Index> indices;

    // The triangles around each vertex, in compressed rows, each row in triangle order: for
    // each triangle, its other two corners in winding order after the vertex (next, previous).
    // Reading the corners from here rather than through the triangles' indices saves a
    // dependent load a triangle; it made the simplification 13 % faster (the cheapest collapses
    // read per vertex, the shape checks). Round a vertex that is not on an open border, every
    // neighbour is the next corner of one triangle (and the previous of another), so the nexts
    // alone list the neighbours, each once.
    struct Corners {
        Index next, previous;
    };
    std::vector<Index> firstTriangle;
    std::vector<Corners> corners;

    void findTrianglesAroundVertices() {
        const std::size_t n = positions.size();
        // firstTriangle[v] counts up to the end of v's row, then is counted down to its start
        // while the triangles are visited backwards (so each row stays in triangle order): no
        // second array of cursors.
        firstTriangle.assign(n + 1, 0);
        for (const Index i : indices) ++firstTriangle[i];
        for (std::size_t v = 1; v < n; ++v) firstTriangle[v] += firstTriangle[v - 1];
        firstTriangle[n] = Index(indices.size());
        corners.resize(indices.size());
        for (std::size_t t = indices.size(); t > 0;)
            for (t -= 3; const std::size_t e : {0, 1, 2}) {
                const Index at = --firstTriangle[indices[t + e]];
                corners[at] = {indices[t + (e + 1) % 3], indices[t + (e + 2) % 3]};
            }
    }
};

// Moving `vertex` onto its neighbour `to`.
struct Candidate {
    float error;  // mean squared distance (cells squared)
    Index vertex, to;
};

// The cheapest collapse of every vertex that may move, cheaper than the bound. A vertex's
// neighbours are taken in the order of its row (each the next corner of one of its triangles):
// the first of equally cheap collapses is kept, so this order decides between them (the test
// spheres are full of exact ties). Taking each edge once from the triangle where it runs from the
// lower index to the higher, as this did before, cost a fifth more time in mispredicted branches.
std::vector<Candidate> cheapestCollapses(const WorkingMesh& m, double limit) {
    const std::size_t n = m.positions.size();
    std::vector<Candidate> candidates;
    candidates.reserve(n);
    for (Index u = 0; u < n; ++u) {
        if (m.border[u] != 0) continue;
        const LocalQuadric q = m.quadrics[u];
        const glm::vec3 pu = m.positions[u];
        // Compared unnormalised: the weight is the moving vertex's own.
        float best = std::numeric_limits<float>::infinity();
        Index to = kNoVertex;
        const auto consider = [&](Index x) {
            const float s = std::abs(q.sum(m.positions[x] - pu));
            if (s < best) best = s, to = x;
        };
        for (Index k = m.firstTriangle[u]; k < m.firstTriangle[u + 1]; ++k)
            consider(m.corners[k].next);
        if (to == kNoVertex) continue;
        const float error = q.mean(best);
        if (error <= limit) candidates.push_back({error, u, to});
    }
    return candidates;
}

// Orders the candidates by error in bands of a factor of four (a factor of two in distance: the
// float's top exponent bits), keeping vertex order within a band. Finer order made the meshes
// no smaller but cost a sort, and vertex order follows the grid, which keeps a pass's memory
// accesses close together.
std::vector<Candidate> inErrorBands(const std::vector<Candidate>& candidates) {
    constexpr unsigned kBandShift = 24;  // sign and the exponent's top 7 bits
    constexpr std::size_t kBands = 256;
    auto band = [](float e) { return std::bit_cast<std::uint32_t>(e) >> kBandShift; };
    std::vector<std::size_t> start(kBands + 1, 0);
    for (const Candidate& c : candidates) ++start[band(c.error) + 1];
    for (std::size_t b = 0; b < kBands; ++b) start[b + 1] += start[b];
    std::vector<Candidate> ordered(candidates.size());
    for (const Candidate& c : candidates) ordered[start[band(c.error)]++] = c;
    return ordered;
}

class CollapsePass {
public:
    // One for all passes, so that its arrays are made once: each pass starts with start().
    explicit CollapsePass(WorkingMesh& m) : m_(m), m_mark(m.positions.size(), 0) {}

    void start() {
        const std::size_t n = m_.positions.size();
        m_movedTo.resize(n);
        for (Index v = 0; v < n; ++v) m_movedTo[v] = v;
        m_role.assign(n, Role::Untouched);
        m_firstMerged.assign(n, kNoVertex);
        m_nextMerged.resize(n);  // written when a vertex joins a list
        m_mark.resize(n);        // stamps only grow, so the old marks never match
    }

    // Collapses in the given order. A vertex moves at most once in a pass and only if nothing
    // has moved onto it, so its quadric is still the one its error was judged with and every
    // error is exact; a vertex that stays may take in any number of neighbours (its position,
    // the other end of each error, does not change), so a pass removes about half the vertices
    // left, not four in ten. Returns the collapses made; `worst` grows to the largest error
    // accepted.
    std::size_t run(const std::vector<Candidate>& ordered, double limit, double& worst) {
        std::size_t made = 0;
        for (const Candidate& c : ordered) {
            const Index a = c.vertex, b = c.to;
            if (m_role[a] != Role::Untouched) continue;
            if (m_role[b] == Role::Moved) continue;  // next pass, with fresh candidates
            float error = c.error;
            Index to = b;
            if (!mayCollapse(a, b)) {
                // The cheapest is refused for its shape: the next cheapest may do.
                to = nextAllowedTarget(a, b, limit, error);
                if (to == kNoVertex) continue;
            }
            m_movedTo[a] = to;
            m_role[a] = Role::Moved;
            m_role[to] = Role::Kept;
            m_nextMerged[a] = m_firstMerged[to];
            m_firstMerged[to] = a;
            m_.quadrics[to].addFrom(m_.quadrics[a], m_.positions[to] - m_.positions[a]);
            worst = std::max(worst, double(error));
            ++made;
        }
        return made;
    }

    // Renumbers the kept vertices in order and drops the triangles that collapsed.
    void apply() {
        const std::size_t n = m_.positions.size();
        // The lists of moved vertices are not needed any more; their array is reused.
        std::vector<Index>& renumbered = m_firstMerged;
        Index kept = 0;
        for (Index v = 0; v < n; ++v) {
            renumbered[v] = kept;
            m_.positions[kept] = m_.positions[v];
            m_.quadrics[kept] = m_.quadrics[v];
            m_.border[kept] = m_.border[v];
            kept += m_movedTo[v] == v ? 1 : 0;
        }
        m_.positions.resize(kept);
        m_.quadrics.resize(kept);
        m_.border.resize(kept);
        // Each vertex's new number, where it went: one lookup a corner below, not two.
        for (Index v = 0; v < n; ++v) renumbered[v] = renumbered[m_movedTo[v]];
        // Every triangle is written, and kept by moving on past it (as every vertex above):
        // which ones collapsed is as good as random, so a branch on it is often mispredicted.
        std::size_t out = 0;
        for (std::size_t t = 0; t < m_.indices.size(); t += 3) {
            const Index i0 = renumbered[m_.indices[t]], i1 = renumbered[m_.indices[t + 1]],
                        i2 = renumbered[m_.indices[t + 2]];
            m_.indices[out] = i0, m_.indices[out + 1] = i1, m_.indices[out + 2] = i2;
            out += isDegenerate(i0, i1, i2) ? 0 : 3;
        }
        m_.indices.resize(out);
    }

private:
    // The two corners other than v (which has not moved) of the triangle at row entry k, as
    // this pass has moved them so far, in winding order after v.
    [[nodiscard]] std::pair<Index, Index> othersAt(Index k) const {
        return {m_movedTo[m_.corners[k].next], m_movedTo[m_.corners[k].previous]};
    }

    // Moving a onto b must not turn any of a's other triangles too far, must keep the surface one
    // sheet (a and b share exactly the two neighbours of the edge's two triangles: the link
    // condition), and must not flatten a closed tetrahedron.
    bool mayCollapse(Index a, Index b) {
        const std::uint32_t aroundA = ++m_stamp, shared = ++m_stamp;
        const glm::vec3 pa = m_.positions[a], pb = m_.positions[b];
        int trianglesA = 0;
        for (Index k = m_.firstTriangle[a]; k < m_.firstTriangle[a + 1]; ++k) {
            // Nothing has moved onto a this pass (it could not move then), so its own row holds
            // all its triangles and it is still a corner of each: x and y are the other two, in
            // winding order. a is not on the border, so its neighbours are the x's.
            const auto [x, y] = othersAt(k);
            if (x == y || x == a || y == a) continue;  // collapsed this pass
            ++trianglesA;
            m_mark[x] = aroundA;
            if (x == b || y == b) continue;  // one of the two triangles that go
            const glm::vec3 px = m_.positions[x], py = m_.positions[y];
            const glm::vec3 before = glm::cross(px - pa, py - pa);
            const glm::vec3 after = glm::cross(px - pb, py - pb);
            // cos > k, squared (no square roots): dot > 0 and dot^2 > k^2 |before|^2 |after|^2.
            const float dot = glm::dot(before, after);
            if (!(dot > 0.0F && dot * dot > kMinTurnCosine * kMinTurnCosine *
                                                glm::dot(before, before) * glm::dot(after, after)))
                return false;
        }
        // b's triangles now: its own and those of every vertex moved onto it this pass (in
        // each, the moved vertex stands for b; the ones that went are degenerate). Its neighbours
        // are the x's, and on an open border also the y's (the last one round is no x).
        int common = 0, trianglesB = 0;
        const auto countShared = [&](Index x) {
            // Without a branch: whether b's neighbour is also a's is as good as random.
            const bool both = x != a && m_mark[x] == aroundA;
            common += both ? 1 : 0;
            m_mark[x] = both ? shared : m_mark[x];
        };
        const bool open = m_.border[b] != 0;
        for (Index v = b; v != kNoVertex; v = v == b ? m_firstMerged[b] : m_nextMerged[v])
            for (Index k = m_.firstTriangle[v]; k < m_.firstTriangle[v + 1]; ++k) {
                const auto [x, y] = othersAt(k);
                if (x == y || x == b || y == b) continue;
                ++trianglesB;
                countShared(x);
                if (open) countShared(y);
            }
        return common == 2 && !(trianglesA == 3 && trianglesB == 3);
    }

    // The cheapest other neighbour of a, within the bound, that has not moved and is not refused.
    Index nextAllowedTarget(Index a, Index refused, double limit, float& error) {
        m_options.clear();
        const LocalQuadric& q = m_.quadrics[a];
        for (Index k = m_.firstTriangle[a]; k < m_.firstTriangle[a + 1]; ++k) {
            const Index x = m_.corners[k].next;
            if (x == refused || m_role[x] == Role::Moved) continue;
            const float e = q.mean(std::abs(q.sum(m_.positions[x] - m_.positions[a])));
            if (e <= limit) m_options.push_back({e, a, x});
        }
        std::sort(m_options.begin(), m_options.end(),
                  [](const Candidate& l, const Candidate& r) { return l.error < r.error; });
        for (const Candidate& o : m_options)
            if (mayCollapse(a, o.to)) {
                error = o.error;
                return o.to;
            }
        return kNoVertex;
    }

    WorkingMesh& m_;
    // What each vertex did this pass: a vertex that took in a neighbour is kept where it is.
    enum class Role : std::uint8_t { Untouched, Moved, Kept };
    std::vector<Index> m_movedTo;  // where each vertex went this pass (itself if it stayed)
    std::vector<Role> m_role;
    // The vertices moved onto each kept vertex this pass, as a list through m_nextMerged.
    std::vector<Index> m_firstMerged, m_nextMerged;
    std::vector<std::uint32_t> m_mark;
    std::uint32_t m_stamp = 0;
    std::vector<Candidate> m_options;
};

}  // namespace

SimplifiedMesh simplifyMesh(data::TriangleMesh mesh, float maxError) {
    SimplifiedMesh result;
    if (!(maxError > 0.0F) || mesh.empty()) {
        result.mesh = std::move(mesh);
        return result;
    }
    WorkingMesh m;
    const std::size_t n = mesh.vertexCount();
    m.positions = std::move(mesh.positions);
    m.indices = std::move(mesh.indices);
    // Triangles that name no vertex or one twice are dropped, in place (kept <= t).
    std::size_t kept = 0;
    for (std::size_t t = 0; t + 2 < m.indices.size(); t += 3) {
        const Index i0 = m.indices[t], i1 = m.indices[t + 1], i2 = m.indices[t + 2];
        if (isDegenerate(i0, i1, i2) || std::max({i0, i1, i2}) >= n) continue;
        m.indices[kept] = i0, m.indices[kept + 1] = i1, m.indices[kept + 2] = i2;
        kept += 3;
    }
    m.indices.resize(kept);
    m.quadrics = planeQuadrics(m.positions, m.indices);
    m.border = openBorderVertices(m.indices, m.positions.size());
    const double limit = double(maxError) * double(maxError);
    double worst = 0.0;
    CollapsePass pass(m);
    // Each pass removes about half the vertices left, so the passes together cost about twice
    // the first; they stop when no collapse within the bound is left,
    // or after a pass that removed almost nothing (below).
    for (;;) {
        m.findTrianglesAroundVertices();
        // The unordered list goes before the pass: this is when the working memory is largest.
        const std::vector<Candidate> ordered = inErrorBands(cheapestCollapses(m, limit));
        if (ordered.empty()) break;
        pass.start();
        const std::size_t made = pass.run(ordered, limit, worst);
        if (made == 0) break;
        pass.apply();
        // A pass that removes under 1 in kLastPassShare of the vertices left is the last: what
        // remains is held by the shape checks, and every further pass would cost a whole pass
        // for a handful (on a terraced exceedance surface, ten passes for 0.2 % of its vertices).
        if (made * kLastPassShare < m.positions.size()) break;
    }
    result.mesh.positions = std::move(m.positions);
    result.mesh.indices = std::move(m.indices);
    result.error = float(std::sqrt(worst));
    return result;
}

}  // namespace ensil::prep

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

// Each vertex starts with the planes of its own triangles, which pass through it: only A.
std::vector<LocalQuadric> planeQuadrics(const std::vector<glm::vec3>& positions,
                                        const std::vector<Index>& indices) {
    std::vector<LocalQuadric> quadrics(positions.size());
    for (std::size_t t = 0; t < indices.size(); t += 3) {
        const glm::dvec3 p0 = positions[indices[t]];
        glm::dvec3 n = glm::cross(glm::dvec3(positions[indices[t + 1]]) - p0,
                                  glm::dvec3(positions[indices[t + 2]]) - p0);
        const double area = glm::length(n);
        if (!(area > 0.0)) continue;  // zero area (or not finite): no plane
        n /= area;
        for (int k = 0; k < 3; ++k) {
            LocalQuadric& q = quadrics[indices[t + k]];
            q.a00 += float(n.x * n.x * area), q.a01 += float(n.x * n.y * area);
            q.a02 += float(n.x * n.z * area), q.a11 += float(n.y * n.y * area);
            q.a12 += float(n.y * n.z * area), q.a22 += float(n.z * n.z * area);
            q.weight += float(area);
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
    // each triangle, its other two corners in winding order after the vertex (next, previous)
    // and which corner of the triangle the vertex is. Reading the corners from here rather than
    // through the triangles' indices saves a dependent load a triangle; it made the
    // simplification 13 % faster (the cheapest collapses read per vertex, the shape checks).
    struct Corners {
        Index next, previous;
    };
    std::vector<Index> firstTriangle;
    std::vector<Corners> corners;
    std::vector<std::uint8_t> cornerAt;

    void findTrianglesAroundVertices() {
        const std::size_t n = positions.size();
        firstTriangle.assign(n + 1, 0);
        for (const Index i : indices) ++firstTriangle[i + 1];
        for (std::size_t v = 0; v < n; ++v) firstTriangle[v + 1] += firstTriangle[v];
        corners.resize(indices.size());
        cornerAt.resize(indices.size());
        std::vector<Index> fill(firstTriangle.begin(), firstTriangle.end() - 1);
        for (std::size_t t = 0; t < indices.size(); t += 3)
            for (std::size_t e = 0; e < 3; ++e) {
                const Index at = fill[indices[t + e]]++;
                corners[at] = {indices[t + (e + 1) % 3], indices[t + (e + 2) % 3]};
                cornerAt[at] = std::uint8_t(e);
            }
    }
    // The row entry k's other corners in the triangle's own order (first corner first).
    [[nodiscard]] std::pair<Index, Index> inTriangleOrder(Index k) const {
        const Corners c = corners[k];
        return cornerAt[k] == 1 ? std::pair{c.previous, c.next} : std::pair{c.next, c.previous};
    }
};

struct Candidate {
    float error;  // mean squared distance (cells squared)
    Index vertex;
};

// The cheapest collapse of every vertex that may move, cheaper than the bound. Each edge is
// taken from the triangle where it runs from the lower index to the higher (its twin runs the
// other way; an open border edge's ends are both on the border and stay), and a vertex's edges in
// the order of those triangles, then of the edges within one (u -> next is the triangle's edge
// number cornerAt, previous -> u the one before it): the first of equally cheap collapses is
// kept, so this order decides between them (the test spheres are full of exact ties).
std::vector<Candidate> cheapestCollapses(const WorkingMesh& m, double limit,
                                         std::vector<Index>& target) {
    const std::size_t n = m.positions.size();
    std::vector<float> cheapest(n, std::numeric_limits<float>::infinity());
    target.assign(n, kNoVertex);
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
        for (Index k = m.firstTriangle[u]; k < m.firstTriangle[u + 1]; ++k) {
            const auto [next, previous] = m.corners[k];
            if (m.cornerAt[k] == 0) {
                if (u < next) consider(next);
                if (previous < u) consider(previous);
            } else {
                if (previous < u) consider(previous);
                if (u < next) consider(next);
            }
        }
        cheapest[u] = best;
        target[u] = to;
    }
    std::vector<Candidate> candidates;
    for (Index v = 0; v < n; ++v) {
        if (target[v] == kNoVertex) continue;
        const float error = m.quadrics[v].mean(cheapest[v]);
        if (error <= limit) candidates.push_back({error, v});
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
    explicit CollapsePass(WorkingMesh& m)
        : m_(m),
          m_movedTo(m.positions.size()),
          m_locked(m.positions.size(), 0),
          m_mark(m.positions.size(), 0) {
        for (Index v = 0; v < m_movedTo.size(); ++v) m_movedTo[v] = v;
    }

    // Collapses in the given order, each vertex moving or receiving at most once in a pass (so
    // every error is exact when it is judged). Returns the collapses made; `worst` grows to
    // the largest error accepted.
    std::size_t run(const std::vector<Candidate>& ordered, const std::vector<Index>& target,
                    double limit, double& worst) {
        std::size_t made = 0;
        for (const Candidate& c : ordered) {
            const Index a = c.vertex, b = target[a];
            if (m_locked[a] != 0 || m_locked[b] != 0) continue;  // next pass, with fresh errors
            float error = c.error;
            Index to = b;
            if (!mayCollapse(a, b)) {
                // The cheapest is refused for its shape: the next cheapest may do.
                to = nextAllowedTarget(a, b, limit, error);
                if (to == kNoVertex) continue;
            }
            m_movedTo[a] = to;
            m_locked[a] = m_locked[to] = 1;
            m_.quadrics[to].addFrom(m_.quadrics[a], m_.positions[to] - m_.positions[a]);
            worst = std::max(worst, double(error));
            ++made;
        }
        return made;
    }

    // Renumbers the kept vertices in order and drops the triangles that collapsed.
    void apply() {
        const std::size_t n = m_.positions.size();
        std::vector<Index> renumbered(n, kNoVertex);
        Index kept = 0;
        for (Index v = 0; v < n; ++v) {
            if (m_movedTo[v] != v) continue;
            renumbered[v] = kept;
            m_.positions[kept] = m_.positions[v];
            m_.quadrics[kept] = m_.quadrics[v];
            m_.border[kept] = m_.border[v];
            ++kept;
        }
        m_.positions.resize(kept);
        m_.quadrics.resize(kept);
        m_.border.resize(kept);
        std::size_t out = 0;
        for (std::size_t t = 0; t < m_.indices.size(); t += 3) {
            const Index i0 = m_movedTo[m_.indices[t]], i1 = m_movedTo[m_.indices[t + 1]],
                        i2 = m_movedTo[m_.indices[t + 2]];
            if (isDegenerate(i0, i1, i2)) continue;
            m_.indices[out++] = renumbered[i0];
            m_.indices[out++] = renumbered[i1];
            m_.indices[out++] = renumbered[i2];
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
            // a has not moved this pass (it would be locked), so it is still a corner: x and y
            // are the other two, in winding order.
            const auto [x, y] = othersAt(k);
            if (x == y || x == a || y == a) continue;  // collapsed this pass
            ++trianglesA;
            m_mark[x] = m_mark[y] = aroundA;
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
        int common = 0, trianglesB = 0;
        for (Index k = m_.firstTriangle[b]; k < m_.firstTriangle[b + 1]; ++k) {
            const auto [x, y] = othersAt(k);
            if (x == y || x == b || y == b) continue;
            ++trianglesB;
            if (x != a && m_mark[x] == aroundA) m_mark[x] = shared, ++common;
            if (y != a && m_mark[y] == aroundA) m_mark[y] = shared, ++common;
        }
        return common == 2 && !(trianglesA == 3 && trianglesB == 3);
    }

    // The cheapest other neighbour of a, within the bound, that is neither locked nor refused.
    Index nextAllowedTarget(Index a, Index refused, double limit, float& error) {
        m_options.clear();
        const LocalQuadric& q = m_.quadrics[a];
        for (Index k = m_.firstTriangle[a]; k < m_.firstTriangle[a + 1]; ++k) {
            const auto [first, second] = m_.inTriangleOrder(k);
            for (const Index x : {first, second}) {
                if (x == a || x == refused || m_locked[x] != 0) continue;
                if (std::any_of(m_options.begin(), m_options.end(),
                                [x](const Candidate& o) { return o.vertex == x; }))
                    continue;
                const float e = q.mean(std::abs(q.sum(m_.positions[x] - m_.positions[a])));
                if (e <= limit) m_options.push_back({e, x});
            }
        }
        std::sort(m_options.begin(), m_options.end(),
                  [](const Candidate& l, const Candidate& r) { return l.error < r.error; });
        for (const Candidate& o : m_options)
            if (mayCollapse(a, o.vertex)) {
                error = o.error;
                return o.vertex;
            }
        return kNoVertex;
    }

    WorkingMesh& m_;
    std::vector<Index> m_movedTo;  // where each vertex went this pass (itself if it stayed)
    std::vector<std::uint8_t> m_locked;
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
    std::vector<Index> target;
    // Each pass removes about four in ten of the vertices left, so the passes together cost
    // about two and a half of the first; they stop when no collapse within the bound is left,
    // or after a pass that removed almost nothing (below).
    for (;;) {
        m.findTrianglesAroundVertices();
        const std::vector<Candidate> candidates = cheapestCollapses(m, limit, target);
        if (candidates.empty()) break;
        CollapsePass pass(m);
        const std::size_t made = pass.run(inErrorBands(candidates), target, limit, worst);
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

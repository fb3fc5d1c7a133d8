#include "hausdorff.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <limits>
#include <unordered_map>
#include <vector>

namespace {

// Closest point on triangle abc to p (Ericson, Real-Time Collision Detection, 5.1.5).
glm::dvec3 closestOnTriangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                             const glm::dvec3& c) {
    const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return a;
    const glm::dvec3 bp = p - b;
    const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + ab * (d1 / (d1 - d3));
    const glm::dvec3 cp = p - c;
    const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + ac * (d2 / (d2 - d6));
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
        return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    }
    const double denom = 1.0 / (va + vb + vc);
    return a + ab * (vb * denom) + ac * (vc * denom);
}

}  // namespace

SurfaceDistance distanceToSurface(const ensil::data::TriangleMesh& from,
                                  const ensil::data::TriangleMesh& to) {
    SurfaceDistance result;
    if (from.positions.empty() || to.empty()) return result;
    constexpr double kBucket = 2.0;  // cells
    const auto key = [](int x, int y, int z) {
        return (static_cast<long long>(x) * 73856093) ^ (static_cast<long long>(y) * 19349663) ^
               (static_cast<long long>(z) * 83492791);
    };
    std::unordered_map<long long, std::vector<std::size_t>> buckets;
    for (std::size_t t = 0; t < to.indices.size(); t += 3) {
        glm::vec3 lo = to.positions[to.indices[t]], hi = lo;
        for (int k = 1; k < 3; ++k) {
            lo = glm::min(lo, to.positions[to.indices[t + k]]);
            hi = glm::max(hi, to.positions[to.indices[t + k]]);
        }
        for (int x = int(std::floor(lo.x / kBucket)); x <= int(std::floor(hi.x / kBucket)); ++x)
            for (int y = int(std::floor(lo.y / kBucket)); y <= int(std::floor(hi.y / kBucket)); ++y)
                for (int z = int(std::floor(lo.z / kBucket)); z <= int(std::floor(hi.z / kBucket));
                     ++z)
                    buckets[key(x, y, z)].push_back(t);
    }
    double sum = 0.0;
    for (const glm::vec3& pf : from.positions) {
        const glm::dvec3 p(pf);
        double best = std::numeric_limits<double>::infinity();
        // Search growing shells of buckets until the nearest triangle found is closer than
        // any unsearched bucket could be.
        for (int r = 0; r < 64 && best > (r - 1) * kBucket; ++r) {
            const int bx = int(std::floor(p.x / kBucket)), by = int(std::floor(p.y / kBucket)),
                      bz = int(std::floor(p.z / kBucket));
            for (int x = bx - r; x <= bx + r; ++x)
                for (int y = by - r; y <= by + r; ++y)
                    for (int z = bz - r; z <= bz + r; ++z) {
                        if (std::max({std::abs(x - bx), std::abs(y - by), std::abs(z - bz)}) != r)
                            continue;
                        const auto found = buckets.find(key(x, y, z));
                        if (found == buckets.end()) continue;
                        for (std::size_t t : found->second) {
                            const glm::dvec3 q =
                                closestOnTriangle(p, glm::dvec3(to.positions[to.indices[t]]),
                                                  glm::dvec3(to.positions[to.indices[t + 1]]),
                                                  glm::dvec3(to.positions[to.indices[t + 2]]));
                            best = std::min(best, glm::length(p - q));
                        }
                    }
        }
        result.maximum = std::max(result.maximum, best);
        sum += best;
    }
    result.mean = sum / static_cast<double>(from.positions.size());
    return result;
}

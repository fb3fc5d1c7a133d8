// Topology and geometry checks for triangle meshes in tests.
#pragma once

#include <cmath>
#include <glm/geometric.hpp>
#include <map>
#include <set>
#include <utility>

#include "data/triangle_mesh.h"

namespace ensil::test {

struct Topology {
    std::size_t edges = 0;
    std::size_t boundaryEdges = 0;     // used by one triangle
    std::size_t nonManifoldEdges = 0;  // used by three or more
    std::size_t inconsistentEdges =
        0;           // a directed edge used twice: neighbours disagree on winding
    long euler = 0;  // V - E + F over the vertices that triangles use
};

inline Topology topologyOf(const data::TriangleMesh& m) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
    std::set<std::uint32_t> used;
    for (std::size_t t = 0; t < m.indices.size(); t += 3) {
        for (int e = 0; e < 3; ++e) {
            const auto a = m.indices[t + static_cast<std::size_t>(e)];
            const auto b = m.indices[t + static_cast<std::size_t>((e + 1) % 3)];
            ++directed[{a, b}];
            used.insert(a);
        }
    }
    Topology topo;
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> undirected;
    for (const auto& [edge, count] : directed) {
        if (count > 1) ++topo.inconsistentEdges;
        undirected[{std::min(edge.first, edge.second), std::max(edge.first, edge.second)}] += count;
    }
    for (const auto& [edge, count] : undirected) {
        ++topo.edges;
        if (count == 1) ++topo.boundaryEdges;
        if (count > 2) ++topo.nonManifoldEdges;
    }
    topo.euler = static_cast<long>(used.size()) - static_cast<long>(topo.edges) +
                 static_cast<long>(m.triangleCount());
    return topo;
}

inline double areaOf(const data::TriangleMesh& m) {
    double area = 0;
    for (std::size_t t = 0; t < m.indices.size(); t += 3) {
        const glm::vec3 a = m.positions[m.indices[t]], b = m.positions[m.indices[t + 1]],
                        c = m.positions[m.indices[t + 2]];
        area += 0.5 * glm::length(glm::cross(b - a, c - a));
    }
    return area;
}

}  // namespace ensil::test

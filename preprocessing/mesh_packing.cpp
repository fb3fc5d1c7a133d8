#include "preprocessing/mesh_packing.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/packing.hpp>

namespace ensil::prep {
namespace {

constexpr float kHalfMax = 65504.0F;

// Among the four snorm16 roundings around the exact encoding, the one that decodes closest:
// plain rounding leaves errors up to 4e-4 rad near the octahedron's folds.
void packUnitVector(const glm::vec3& v, std::int16_t out[2]) {
    const glm::vec2 e = octahedralEncode(v);
    const glm::vec2 base = glm::floor(glm::clamp(e, -1.0F, 1.0F) * 32767.0F);
    float best = -2.0F;
    for (int c = 0; c < 4; ++c) {
        const glm::vec2 q = glm::clamp(base + glm::vec2(c & 1, c >> 1), -32767.0F, 32767.0F);
        const float d = glm::dot(octahedralDecode(q / 32767.0F), v);
        if (d > best) {
            best = d;
            out[0] = static_cast<std::int16_t>(q.x);
            out[1] = static_cast<std::int16_t>(q.y);
        }
    }
}

std::uint16_t unorm16(float t) {
    return static_cast<std::uint16_t>(std::lround(std::clamp(t, 0.0F, 1.0F) * 65535.0F));
}

}  // namespace

std::uint16_t packHalf(float f) {
    if (std::isnan(f)) f = 0.0F;
    return glm::packHalf1x16(std::clamp(f, -kHalfMax, kHalfMax));
}

float unpackHalf(std::uint16_t h) { return glm::unpackHalf1x16(h); }

glm::vec2 octahedralEncode(const glm::vec3& n) {
    const glm::vec3 v = n / (std::abs(n.x) + std::abs(n.y) + std::abs(n.z));
    glm::vec2 e{v.x, v.y};
    if (v.z < 0.0F) {
        const glm::vec2 sign{e.x >= 0.0F ? 1.0F : -1.0F, e.y >= 0.0F ? 1.0F : -1.0F};
        e = (glm::vec2(1.0F) - glm::abs(glm::vec2(e.y, e.x))) * sign;
    }
    return e;
}

glm::vec3 octahedralDecode(glm::vec2 e) {
    glm::vec3 v{e.x, e.y, 1.0F - std::abs(e.x) - std::abs(e.y)};
    const float t = std::max(-v.z, 0.0F);
    v.x += v.x >= 0.0F ? -t : t;
    v.y += v.y >= 0.0F ? -t : t;
    return glm::normalize(v);
}

glm::vec3 unpackUnitVector(const std::int16_t e[2]) {
    return octahedralDecode({std::max(static_cast<float>(e[0]) / 32767.0F, -1.0F),
                             std::max(static_cast<float>(e[1]) / 32767.0F, -1.0F)});
}

data::PackedMesh packMesh(const data::TriangleMesh& mesh, const VertexAttributes& a) {
    data::PackedMesh packed;
    packed.indices = mesh.indices;
    if (mesh.positions.empty()) return packed;
    packed.boundsMin = packed.boundsMax = mesh.positions.front();
    for (const glm::vec3& p : mesh.positions) {
        packed.boundsMin = glm::min(packed.boundsMin, p);
        packed.boundsMax = glm::max(packed.boundsMax, p);
    }
    const float largest = a.outlyingness.empty()
                              ? 0.0F
                              : *std::max_element(a.outlyingness.begin(), a.outlyingness.end());
    packed.outlyingnessScale = largest > 0.0F ? largest : 1.0F;
    const glm::vec3 extent = glm::max(packed.boundsMax - packed.boundsMin, glm::vec3(1e-20F));
    packed.vertices.resize(mesh.positions.size());
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        data::PackedVertex& out = packed.vertices[v];
        const glm::vec3 t = (mesh.positions[v] - packed.boundsMin) / extent;
        for (int c = 0; c < 3; ++c) out.position[c] = unorm16(t[c]);
        out.kappa1 = packHalf(a.kappa1[v]);
        out.kappa2 = packHalf(a.kappa2[v]);
        out.outlyingness = packHalf(a.outlyingness[v] / packed.outlyingnessScale);
        packUnitVector(a.normals[v], out.normal);
        packUnitVector(a.principalDirections[v], out.direction);
    }
    return packed;
}

glm::vec3 unpackPosition(const data::PackedMesh& mesh, const data::PackedVertex& v) {
    const glm::vec3 t{static_cast<float>(v.position[0]) / 65535.0F,
                      static_cast<float>(v.position[1]) / 65535.0F,
                      static_cast<float>(v.position[2]) / 65535.0F};
    return mesh.boundsMin + t * (mesh.boundsMax - mesh.boundsMin);
}

float maximumOutlyingness(const data::MeshSet& meshes) {
    float maximum = 0.0F;
    for (const data::PackedMesh& mesh : meshes.members) {
        // Finite non-negative halves (bit patterns below 0x7C00, the first infinity) order
        // like their bits.
        std::uint16_t largest = 0;
        for (const data::PackedVertex& v : mesh.vertices) {
            if (v.outlyingness < 0x7C00U) largest = std::max(largest, v.outlyingness);
        }
        maximum = std::max(maximum, unpackHalf(largest) * mesh.outlyingnessScale);
    }
    return maximum;
}

}  // namespace ensil::prep

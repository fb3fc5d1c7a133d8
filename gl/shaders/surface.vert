#version 410 core
// Unpacks the 20-byte vertex (data/packed_mesh.h): the GL vertex formats have already turned
// the fields into floats; what is left is the mapping from grid index to display space
// (grid_display.glsl) and the octahedral decode of the unit vectors.
layout(location = 0) in vec3 a_position;      // unorm16 within the mesh bounds
layout(location = 1) in vec2 a_kappa;         // half floats: kappa1, kappa2
layout(location = 2) in float a_outlyingness; // half float, times u_outlyingnessScale
layout(location = 3) in vec2 a_normal;        // octahedral snorm16
layout(location = 4) in vec2 a_direction;     // octahedral snorm16

uniform mat4 u_viewProjection;
uniform float u_outlyingnessScale;

#include "grid_display.glsl"

out Surface {
    vec3 position;
    vec3 normal;
    vec3 direction;
    vec2 kappa;
    float outlyingness;
} v;

vec3 octahedralDecode(vec2 e) {
    vec3 v = vec3(e, 1.0 - abs(e.x) - abs(e.y));
    float t = max(-v.z, 0.0);
    v.x += v.x >= 0.0 ? -t : t;
    v.y += v.y >= 0.0 ? -t : t;
    return normalize(v);
}

void main() {
    v.position = displayPosition(a_position);
    v.normal = octahedralDecode(a_normal);
    v.direction = octahedralDecode(a_direction);
    v.kappa = a_kappa;
    v.outlyingness = a_outlyingness * u_outlyingnessScale;
    gl_Position = u_viewProjection * vec4(v.position, 1.0);
}

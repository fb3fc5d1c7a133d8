#version 410 core
// Unpacks the 20-byte vertex (data/packed_mesh.h): the GL vertex formats have already turned
// the fields into floats; what is left is the mapping from grid index to display space, which
// is separable: one table of display coordinates per axis, one row each of u_axisTables.
layout(location = 0) in vec3 a_position;      // unorm16 within the mesh bounds
layout(location = 1) in vec2 a_kappa;         // half floats: kappa1, kappa2
layout(location = 2) in float a_outlyingness; // half float, times u_outlyingnessScale
layout(location = 3) in vec2 a_normal;        // octahedral snorm16
layout(location = 4) in vec2 a_direction;     // octahedral snorm16

uniform mat4 u_viewProjection;
uniform vec3 u_boundsMin;
uniform vec3 u_boundsMax;
uniform sampler2D u_axisTables;
uniform ivec3 u_axisSize;
uniform float u_outlyingnessScale;

out Surface {
    vec3 position;
    vec3 normal;
    vec3 direction;
    vec2 kappa;
    float outlyingness;
} v;

float displayCoordinate(int axis, float index) {
    int last = u_axisSize[axis] - 1;
    float i = clamp(index, 0.0, float(last));
    int i0 = min(int(floor(i)), last - 1);
    float a = texelFetch(u_axisTables, ivec2(i0, axis), 0).r;
    float b = texelFetch(u_axisTables, ivec2(i0 + 1, axis), 0).r;
    return mix(a, b, i - float(i0));
}

vec3 octahedralDecode(vec2 e) {
    vec3 v = vec3(e, 1.0 - abs(e.x) - abs(e.y));
    float t = max(-v.z, 0.0);
    v.x += v.x >= 0.0 ? -t : t;
    v.y += v.y >= 0.0 ? -t : t;
    return normalize(v);
}

void main() {
    vec3 index = mix(u_boundsMin, u_boundsMax, a_position);
    v.position = vec3(displayCoordinate(0, index.x), displayCoordinate(1, index.y),
                      displayCoordinate(2, index.z));
    v.normal = octahedralDecode(a_normal);
    v.direction = octahedralDecode(a_direction);
    v.kappa = a_kappa;
    v.outlyingness = a_outlyingness * u_outlyingnessScale;
    gl_Position = u_viewProjection * vec4(v.position, 1.0);
}

#version 410 core
// Values arrive normalised to [0, 1]; negative marks a missing value.
uniform sampler2D u_map;
uniform float u_opacity;
in vec2 v_uv;
out vec4 o_color;

// The colour scale's polynomial, from gl/palette.h (kViridisCoefficients), so the floor and
// its colour bar agree.
uniform vec3 u_viridis[7];
vec3 viridis(float t) {
    vec3 c = u_viridis[6];
    for (int i = 5; i >= 0; --i) c = u_viridis[i] + t * c;
    return c;
}

void main() {
    float value = texture(u_map, v_uv).r;
    if (value < 0.0) {
        o_color = vec4(0.5, 0.5, 0.5, u_opacity);
        return;
    }
    o_color = vec4(viridis(clamp(value, 0.0, 1.0)), u_opacity);
}

#version 410 core
// The field on the cut face: display position -> grid index (per axis, through tables of the
// inverse of the separable display mapping) -> the field's value, trilinear between grid
// points, as the value under the cursor is read (data::sampleTrilinear).
uniform sampler3D u_volume;        // values normalised to [0, 1]; negative marks missing
uniform sampler2D u_indexTables;   // row a: grid index along axis a, evenly across the box
uniform int u_indexSamples;        // texels per row
uniform vec3 u_boxMin;
uniform vec3 u_boxMax;
uniform vec3 u_gridSize;           // points along each axis
in vec3 v_display;
out vec4 o_color;

// The colour scale's polynomial, from gl/palette.h, as the floor and the colour bars use it.
uniform vec3 u_viridis[7];
vec3 viridis(float t) {
    vec3 c = u_viridis[6];
    for (int i = 5; i >= 0; --i) c = u_viridis[i] + t * c;
    return c;
}

void main() {
    vec3 across = clamp((v_display - u_boxMin) / max(u_boxMax - u_boxMin, vec3(1e-9)), 0.0, 1.0);
    float samples = float(u_indexSamples);
    vec3 index;
    for (int a = 0; a < 3; ++a) {
        float u = (across[a] * (samples - 1.0) + 0.5) / samples;
        index[a] = texture(u_indexTables, vec2(u, (float(a) + 0.5) / 3.0)).r;
    }
    float value = texture(u_volume, (index + 0.5) / u_gridSize).r;
    if (value < 0.0) {
        o_color = vec4(0.5, 0.5, 0.5, 1.0);
        return;
    }
    o_color = vec4(viridis(clamp(value, 0.0, 1.0)), 1.0);
}

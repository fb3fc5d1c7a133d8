// A 3D field's colour at a display-space point (the filled cut face, the context surface
// coloured by the spread; METHODS.md section 18): display position -> grid index per axis,
// through tables of the inverse of the separable display mapping -> the field's value,
// trilinear between grid points as data::sampleTrilinear reads it -> the colour scale.
uniform sampler3D u_fieldVolume;       // values normalised to [0, 1]; negative marks missing
uniform sampler2D u_fieldIndexTables;  // row a: grid index along axis a, evenly across the box
uniform int u_fieldIndexSamples;       // texels per row
uniform vec3 u_fieldBoxMin;
uniform vec3 u_fieldBoxMax;
uniform vec3 u_fieldGridSize;          // points along each axis

// The colour scale's polynomial, from gl/palette.h, as the floor and the colour bars use it.
uniform vec3 u_viridis[7];
vec3 viridis(float t) {
    vec3 c = u_viridis[6];
    for (int i = 5; i >= 0; --i) c = u_viridis[i] + t * c;
    return c;
}

// The field's normalised value at a display-space point (negative where missing).
float fieldValueAt(vec3 display) {
    vec3 across = clamp((display - u_fieldBoxMin) / max(u_fieldBoxMax - u_fieldBoxMin, vec3(1e-9)),
                        0.0, 1.0);
    float samples = float(u_fieldIndexSamples);
    vec3 index;
    for (int a = 0; a < 3; ++a) {
        float u = (across[a] * (samples - 1.0) + 0.5) / samples;
        index[a] = texture(u_fieldIndexTables, vec2(u, (float(a) + 0.5) / 3.0)).r;
    }
    return texture(u_fieldVolume, (index + 0.5) / u_fieldGridSize).r;
}

// Its colour: the scale's, gray where missing.
vec3 fieldColourAt(vec3 display) {
    float value = fieldValueAt(display);
    return value < 0.0 ? vec3(0.5) : viridis(clamp(value, 0.0, 1.0));
}

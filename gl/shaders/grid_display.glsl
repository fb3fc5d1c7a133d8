// From a packed vertex position (unorm16 within the mesh's bounds, data/packed_mesh.h) to
// display space: the mapping from grid index to display coordinates is separable, one table of
// display coordinates per axis, one row each of u_axisTables (METHODS.md section 3).
uniform vec3 u_boundsMin;
uniform vec3 u_boundsMax;
uniform sampler2D u_axisTables;
uniform ivec3 u_axisSize;

float displayCoordinate(int axis, float index) {
    int last = u_axisSize[axis] - 1;
    float i = clamp(index, 0.0, float(last));
    int i0 = min(int(floor(i)), last - 1);
    float a = texelFetch(u_axisTables, ivec2(i0, axis), 0).r;
    float b = texelFetch(u_axisTables, ivec2(i0 + 1, axis), 0).r;
    return mix(a, b, i - float(i0));
}

vec3 displayPosition(vec3 packedPosition) {
    vec3 index = mix(u_boundsMin, u_boundsMax, packedPosition);
    return vec3(displayCoordinate(0, index.x), displayCoordinate(1, index.y),
                displayCoordinate(2, index.z));
}

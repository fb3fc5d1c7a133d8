#version 410 core
// A textured quad on the floor of the data box: the column maximum of the mean member.
layout(location = 0) in vec2 a_corner;  // (0,0) .. (1,1)
uniform mat4 u_viewProjection;
uniform vec3 u_boxMin;
uniform vec3 u_boxMax;
uniform vec2 u_texelInset;  // half a texel: grid points sit at texel centres
out vec2 v_uv;

void main() {
    v_uv = mix(u_texelInset, vec2(1.0) - u_texelInset, a_corner);
    vec3 p = vec3(mix(u_boxMin.xy, u_boxMax.xy, a_corner), u_boxMin.z);
    gl_Position = u_viewProjection * vec4(p, 1.0);
}

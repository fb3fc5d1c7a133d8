#version 410 core
// The rims of the isosurfaces, where they meet the data box (gl/mesh_rims.h): segments between
// packed vertices of a mesh, widened on screen by map_lines.geom like every other line.
layout(location = 0) in vec3 a_position;  // unorm16 within the mesh bounds
uniform mat4 u_viewProjection;

#include "grid_display.glsl"

out vec3 v_position;  // display space, for the cutting plane

void main() {
    v_position = displayPosition(a_position);
    gl_Position = u_viewProjection * vec4(v_position, 1.0);
}

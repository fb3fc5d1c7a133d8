#version 410 core
// Plain colored lines (bounding box, axes) in display space.
layout(location = 0) in vec3 a_position;
uniform mat4 u_viewProjection;

void main() {
    gl_Position = u_viewProjection * vec4(a_position, 1.0);
}

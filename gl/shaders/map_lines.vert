#version 410 core
// Map lines on the box floor (coastlines, borders, graticule) and the box's edges, in display
// space; the geometry shader widens each segment on screen.
layout(location = 0) in vec3 a_position;
uniform mat4 u_viewProjection;

out vec3 v_position;  // display space, for the cutting plane

void main() {
    v_position = a_position;
    gl_Position = u_viewProjection * vec4(a_position, 1.0);
}

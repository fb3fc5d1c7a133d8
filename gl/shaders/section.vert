#version 410 core
// The cutting plane's cut face (a polygon in display space), filled with a field.
layout(location = 0) in vec3 a_position;
uniform mat4 u_viewProjection;
out vec3 v_display;

void main() {
    v_display = a_position;
    gl_Position = u_viewProjection * vec4(a_position, 1.0);
}

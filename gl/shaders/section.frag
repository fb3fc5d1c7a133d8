#version 410 core
// The field on the cutting plane's cut face (gl/renderer_section.cpp).
#include "field_lookup.glsl"
in vec3 v_display;
out vec4 o_color;

void main() {
    o_color = vec4(fieldColourAt(v_display), 1.0);
}

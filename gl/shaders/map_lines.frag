#version 410 core
// Coverage falls from 1 to 0 across the last pixel of the line's width: an antialiased edge.
uniform vec4 u_color;
uniform float u_halfWidth;
noperspective in float v_across;
out vec4 o_color;

void main() {
    float coverage = clamp(u_halfWidth + 0.5 - abs(v_across), 0.0, 1.0);
    if (coverage <= 0.0) discard;
    o_color = vec4(u_color.rgb, u_color.a * coverage);
}

#version 410 core
// Coverage falls from 1 to 0 across the last pixel of the line's width: an antialiased edge.
uniform vec4 u_color;
uniform float u_halfWidth;
// The cutting plane, as the surfaces use it (surface.frag): the viewer's side n.p > offset is
// cut away. Off for the map lines and the box, on for the isosurfaces' rims.
uniform bool u_planeEnabled;
uniform vec4 u_plane;
noperspective in float v_across;
in vec3 g_position;
out vec4 o_color;

void main() {
    if (u_planeEnabled && dot(u_plane.xyz, g_position) > u_plane.w) discard;
    float coverage = clamp(u_halfWidth + 0.5 - abs(v_across), 0.0, 1.0);
    if (coverage <= 0.0) discard;
    o_color = vec4(u_color.rgb, u_color.a * coverage);
}

#version 410 core
// Widens each line segment into a screen-space quad u_halfWidth pixels to either side, with
// one more pixel for the antialiased edge: OpenGL core profiles (macOS) draw lines only one
// pixel wide, and a map line must read over any floor colour, so it is drawn twice, a dark
// casing under a light core.
layout(lines) in;
layout(triangle_strip, max_vertices = 4) out;

uniform vec2 u_viewport;    // the scene's size in pixels
uniform float u_halfWidth;  // pixels

in vec3 v_position[];               // display space
noperspective out float v_across;  // pixels from the line's centre, signed
out vec3 g_position;               // display space, for the cutting plane

void main() {
    vec4 a = gl_in[0].gl_Position;
    vec4 b = gl_in[1].gl_Position;
    // A segment behind the eye has no place on screen.
    if (a.w <= 0.0 || b.w <= 0.0) return;
    vec2 sa = a.xy / a.w * 0.5 * u_viewport;
    vec2 sb = b.xy / b.w * 0.5 * u_viewport;
    vec2 along = sb - sa;
    float len = length(along);
    vec2 dir = len > 1e-6 ? along / len : vec2(1.0, 0.0);
    vec2 normal = vec2(-dir.y, dir.x);
    float reach = u_halfWidth + 1.0;
    // Offsets in pixels back to clip space: multiply by w and divide by half the viewport.
    vec2 toClip = 2.0 / u_viewport;
    for (int end = 0; end < 2; ++end) {
        vec4 p = end == 0 ? a : b;
        for (int side = 1; side >= -1; side -= 2) {
            v_across = float(side) * reach;
            g_position = v_position[end];
            gl_Position = vec4(p.xy + float(side) * normal * reach * toClip * p.w, p.zw);
            EmitVertex();
        }
    }
    EndPrimitive();
}

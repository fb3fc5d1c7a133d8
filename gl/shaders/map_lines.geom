#version 410 core
// Widens each line segment into a screen-space quad u_halfWidth pixels to either side, with
// one more pixel for the antialiased edge: OpenGL core profiles (macOS) draw lines only one
// pixel wide, and a map line must read over any floor colour, so it is drawn twice, a dark
// casing under a light core.
layout(lines) in;
layout(triangle_strip, max_vertices = 4) out;

uniform vec2 u_viewport;    // the scene's size in pixels
uniform float u_halfWidth;  // pixels

noperspective out float v_across;  // pixels from the line's centre, signed

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
    v_across = reach;
    gl_Position = vec4(a.xy + normal * reach * toClip * a.w, a.zw);
    EmitVertex();
    v_across = -reach;
    gl_Position = vec4(a.xy - normal * reach * toClip * a.w, a.zw);
    EmitVertex();
    v_across = reach;
    gl_Position = vec4(b.xy + normal * reach * toClip * b.w, b.zw);
    EmitVertex();
    v_across = -reach;
    gl_Position = vec4(b.xy - normal * reach * toClip * b.w, b.zw);
    EmitVertex();
    EndPrimitive();
}

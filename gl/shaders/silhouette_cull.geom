#version 410 core
// Drops, before rasterisation, the triangles that cannot hold a silhouette or an intersection
// curve (the silhouette modes: shaded and spaghetti). Most of an isosurface faces the viewer and
// would otherwise be shaded and discarded fragment by fragment, which is where a software
// rasteriser such as llvmpipe spends its time. A fragment is on a silhouette when
// |v.n| <= sqrt(t (2 - t)) with t = clamp(tau |kappa_v|, 1e-4, 1) (surface.frag), and
// |kappa_v| <= max(|kappa1|, |kappa2|); so a triangle whose |v.n| stays above the widest such
// bound of its vertices, without changing sign, holds no silhouette. The margin covers the
// slightly non-linear interpolation of normals and view directions across a triangle.
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

in Surface {
    vec3 position;
    vec3 normal;
    vec3 direction;
    vec2 kappa;
    float outlyingness;
} v_in[];

out Surface {
    vec3 position;
    vec3 normal;
    vec3 direction;
    vec2 kappa;
    float outlyingness;
} v_out;

uniform vec3 u_eye;
uniform bool u_orthographic;
uniform vec3 u_viewDirection;
uniform float u_tau;
uniform bool u_planeEnabled;
uniform vec4 u_plane;          // as in surface.frag: the viewer's side is n.p > offset
uniform float u_planeEpsilon;

const float kMargin = 1.25;

bool mayHoldSilhouette() {
    float widest = 0.0;
    float lo = 1e30;
    float hi = -1e30;
    for (int i = 0; i < 3; ++i) {
        vec3 n = normalize(v_in[i].normal);
        vec3 v = u_orthographic ? -u_viewDirection : normalize(u_eye - v_in[i].position);
        float vn = dot(v, n);
        lo = min(lo, vn);
        hi = max(hi, vn);
        float kappa = max(abs(v_in[i].kappa.x), abs(v_in[i].kappa.y));
        float t = clamp(u_tau * kappa, 1e-4, 1.0);
        widest = max(widest, sqrt(t * (2.0 - t)));
    }
    if (lo <= 0.0 && hi >= 0.0) return true;  // the contour itself crosses the triangle
    return min(abs(lo), abs(hi)) <= widest * kMargin;
}

void main() {
    bool curve = false;
    if (u_planeEnabled) {
        float lo = 1e30;
        float hi = -1e30;
        for (int i = 0; i < 3; ++i) {
            float side = dot(u_plane.xyz, v_in[i].position) - u_plane.w;
            lo = min(lo, side);
            hi = max(hi, side);
        }
        if (lo > 0.0) return;  // wholly on the viewer's side: cut away
        // Curves are drawn where the surface lies within eps behind the plane.
        curve = hi >= -u_planeEpsilon * kMargin;
    }
    if (!curve && !mayHoldSilhouette()) return;
    for (int i = 0; i < 3; ++i) {
        v_out.position = v_in[i].position;
        v_out.normal = v_in[i].normal;
        v_out.direction = v_in[i].direction;
        v_out.kappa = v_in[i].kappa;
        v_out.outlyingness = v_in[i].outlyingness;
        gl_Position = gl_in[i].gl_Position;
        EmitVertex();
    }
    EndPrimitive();
}

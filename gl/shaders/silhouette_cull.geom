#version 410 core
// Cuts the silhouette modes' (shaded and spaghetti) triangles down, before rasterisation, to the
// parts that can hold a fragment the fragment shader keeps. A software rasteriser such as
// llvmpipe spends its time per covered pixel, even on pixels the fragment shader discards at
// once, so every pixel not rasterised is time saved. Each test below is a clip distance, linear
// across the triangle, that is negative only where surface.frag would discard; a triangle that is
// negative everywhere on one of them is dropped here.
//
// Silhouette: a fragment is kept when |v.n| <= sqrt(t (2 - t)), t = clamp(tau |kappa_v|, 1e-4,
// 1). Within a triangle |kappa_v| <= max(|kappa1|, |kappa2|) of its vertices, so the bound is at
// most `widest`, that of the vertex of largest curvature. Write the fragment's normal before
// normalisation n_f = sum_i b_i n_i (|n_f| <= 1) and its unnormalised view vector
// e - p_f = sum_i b_i (e - p_i). Then (e - p_f).n_f = sum_i b_i d_i (v_i.n_i) + E, with d_i the
// vertex's distance to the eye and E = -sum_{i<j} b_i b_j (p_j - p_i).(n_j - n_i), at most a
// third of the largest such product: second order in the triangle's size. A kept fragment has
// |(e - p_f).n_f| <= widest |e - p_f| |n_f| <= widest sum_i b_i d_i. So it lies where
// sum_i b_i (d_i (widest -+ v_i.n_i)) + |E| >= 0: distances 0 and 1, linear across the triangle.
// In orthographic views v is constant, d_i = 1 and E = 0.
//
// Cutting plane: distance 2 cuts away the viewer's side exactly (it is linear in position). The
// intersection curve's strip, at most eps behind the plane, is kept whatever the other tests say:
// those distances become the larger of theirs and the strip's at each vertex, which, the maximum
// being convex, keeps every point where either holds.
//
// Antialiasing: surface.frag also draws a fringe beyond each band's edge, where a pixel-wide box
// filter still reaches into the band: at most half its fwidth, 0.71 pixels. A pixel whose centre
// lies in the fringe writes the samples of the triangle that cover it, up to 0.71 pixels
// farther, so the silhouette and curve distances are widened by twice their gradient's length
// per pixel (the triangle's, from its corners on screen): no sample such a pixel writes is
// clipped away.
//
// Density-based removal: outlyingness is interpolated linearly, and fragments at or below the
// member's group threshold o_min are discarded: distance 3.
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

out gl_PerVertex {
    vec4 gl_Position;
    float gl_ClipDistance[4];  // 0, 1: silhouette band; 2: cutting plane; 3: removal
};

uniform vec3 u_eye;
uniform bool u_orthographic;
uniform vec3 u_viewDirection;
uniform float u_tau;
uniform bool u_planeEnabled;
uniform vec4 u_plane;          // as in surface.frag: the viewer's side is n.p > offset
uniform float u_planeEpsilon;
uniform bool u_removal;
uniform float u_removalMin;    // o*_min
uniform float u_removalMax;    // o*_max
uniform int u_groupSize;       // s_G
uniform int u_memberIndex;     // i_M
uniform vec2 u_viewportSize;   // pixels

// Slack for rounding between this stage and the fragment shader.
const float kSlack = 1e-3;

// The bound on |E| above: a third of the largest (p_j - p_i).(n_j - n_i) over the edges.
float interpolationError() {
    if (u_orthographic) return 0.0;
    float largest = 0.0;
    for (int i = 0; i < 3; ++i) {
        int j = (i + 1) % 3;
        largest = max(largest, abs(dot(v_in[j].position - v_in[i].position,
                                       v_in[j].normal - v_in[i].normal)));
    }
    return largest / 3.0;
}

// The lower edge of member u_memberIndex's outlyingness band (surface.frag's removalFactor).
float removalThreshold() {
    int group = u_memberIndex % u_groupSize;
    return u_removalMin + float(group) * (u_removalMax - u_removalMin) / float(u_groupSize);
}

// How much a quantity linear over the triangle, with these values at its corners, changes per
// pixel on screen; very large when the triangle is seen edge-on or reaches behind the eye, so
// that nothing is dropped there.
float perPixel(float c0, float c1, float c2) {
    vec2 s[3];
    for (int i = 0; i < 3; ++i) {
        vec4 p = gl_in[i].gl_Position;
        if (p.w <= 1e-6) return 1e30;
        s[i] = (p.xy / p.w * 0.5 + 0.5) * u_viewportSize;
    }
    vec2 e1 = s[1] - s[0], e2 = s[2] - s[0];
    float det = e1.x * e2.y - e1.y * e2.x;
    if (abs(det) < 1e-6) return 1e30;
    float d1 = c1 - c0, d2 = c2 - c0;
    return length(vec2(d1 * e2.y - d2 * e1.y, e1.x * d2 - e2.x * d1)) / abs(det);
}

void main() {
    float vn[3];
    float eyeDistance[3];
    float widest = 0.0;
    for (int i = 0; i < 3; ++i) {
        vec3 n = normalize(v_in[i].normal);
        vec3 toEye = u_eye - v_in[i].position;
        eyeDistance[i] = u_orthographic ? 1.0 : length(toEye);
        vec3 v = u_orthographic ? -u_viewDirection : toEye / eyeDistance[i];
        vn[i] = dot(v, n);
        float kappa = max(abs(v_in[i].kappa.x), abs(v_in[i].kappa.y));
        float t = clamp(u_tau * kappa, 1e-4, 1.0);
        widest = max(widest, sqrt(t * (2.0 - t)));
    }
    float error = interpolationError();

    // behind[i]: how far vertex i lies behind the plane; the curve's strip is behind <= eps.
    float behind[3] = float[3](1.0, 1.0, 1.0);
    float curve[3] = float[3](-1.0, -1.0, -1.0);
    if (u_planeEnabled) {
        for (int i = 0; i < 3; ++i) {
            behind[i] = u_plane.w - dot(u_plane.xyz, v_in[i].position);
            curve[i] = u_planeEpsilon + kSlack - behind[i];
        }
        if (max(behind[0], max(behind[1], behind[2])) < 0.0) return;  // all on the viewer's side
    }
    bool removal = u_removal && u_groupSize >= 1;
    float threshold = removal ? removalThreshold() : 0.0;

    float upper[3];
    float lower[3];
    float kept[3];
    for (int i = 0; i < 3; ++i) {
        float band = eyeDistance[i] * (widest + kSlack) + error;
        upper[i] = band - eyeDistance[i] * vn[i];
        lower[i] = band + eyeDistance[i] * vn[i];
    }
    float upperFringe = 2.0 * perPixel(upper[0], upper[1], upper[2]);
    float lowerFringe = 2.0 * perPixel(lower[0], lower[1], lower[2]);
    float curveFringe = u_planeEnabled ? 2.0 * perPixel(curve[0], curve[1], curve[2]) : 0.0;
    // The fragment shader's own hard edges (the plane's cut, removal's threshold) are decided at
    // pixel centres; their clip distances get the same margin, so that the samples of a pixel it
    // keeps are not clipped either.
    float behindFringe = u_planeEnabled ? 2.0 * perPixel(behind[0], behind[1], behind[2]) : 0.0;
    float keptFringe = 0.0;
    if (removal) {
        keptFringe = 2.0 * perPixel(v_in[0].outlyingness, v_in[1].outlyingness,
                                    v_in[2].outlyingness);
    }
    for (int i = 0; i < 3; ++i) {
        float onCurve = curve[i] + curveFringe;
        upper[i] = max(upper[i] + upperFringe, onCurve);
        lower[i] = max(lower[i] + lowerFringe, onCurve);
        kept[i] = removal ? max(v_in[i].outlyingness - threshold + keptFringe, onCurve) : 1.0;
        behind[i] += behindFringe;
    }
    if (max(upper[0], max(upper[1], upper[2])) < 0.0 ||
        max(lower[0], max(lower[1], lower[2])) < 0.0 ||
        max(kept[0], max(kept[1], kept[2])) < 0.0) {
        return;  // nothing on this triangle would be drawn
    }
    for (int i = 0; i < 3; ++i) {
        v_out.position = v_in[i].position;
        v_out.normal = v_in[i].normal;
        v_out.direction = v_in[i].direction;
        v_out.kappa = v_in[i].kappa;
        v_out.outlyingness = v_in[i].outlyingness;
        gl_Position = gl_in[i].gl_Position;
        gl_ClipDistance[0] = upper[i];
        gl_ClipDistance[1] = lower[i];
        gl_ClipDistance[2] = behind[i];
        gl_ClipDistance[3] = kept[i];
        EmitVertex();
    }
    EndPrimitive();
}

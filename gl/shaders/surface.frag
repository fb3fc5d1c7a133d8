#version 410 core
// Silhouettes of isosurfaces (METHODS.md sections 9 to 12). Modes:
//   0 shaded silhouettes, 1 3D spaghetti plot, 2 semi-transparent surfaces, 3 solid lit surface.
// Modes 0 and 2 are translucent and write weighted blended order-independent transparency
// (McGuire & Bavoil 2013): the image does not depend on the order members are drawn in, and
// needs one pass, no sorting. Modes 1 and 3 are opaque.
// With u_pick set, every fragment the mode would draw writes the member's id instead (the
// picking pass; opaque, depth-tested, so the front-most member wins).
in Surface {
    vec3 position;
    vec3 normal;
    vec3 direction;
    vec2 kappa;
    float outlyingness;
} v_in;

uniform int u_mode;
uniform vec3 u_eye;
uniform bool u_orthographic;
uniform vec3 u_viewDirection;  // towards the scene, for orthographic views
uniform vec3 u_color;
uniform float u_tau;           // silhouette thickness
uniform float u_surfaceAlpha;
uniform bool u_removal;
uniform float u_removalMin;    // o*_min
uniform float u_removalMax;    // o*_max
uniform int u_groupSize;       // s_G
uniform int u_memberIndex;     // i_M
uniform bool u_planeEnabled;
uniform vec4 u_plane;          // unit normal and offset; the viewer's side is n.p > offset
uniform float u_planeEpsilon;  // eps: the thickness of the intersection curves
uniform bool u_pick;
uniform int u_pickId;          // 0 = nothing pickable (the mean), else member + 1

layout(location = 0) out vec4 o_color;   // opaque colour, OIT accumulation, or the pick id
layout(location = 1) out float o_reveal; // OIT revealage

const float kEpsilon = 1e-4;

float silhouetteCoefficient(vec3 v, vec3 n) {
    // Curvature along the view direction (Euler's formula).
    vec3 w = v - dot(n, v) * n;
    float kappaV = v_in.kappa.x;
    float lw = length(w);
    if (lw > 1e-6) {
        float c = dot(w / lw, normalize(v_in.direction));
        kappaV = v_in.kappa.x * c * c + v_in.kappa.y * (1.0 - c * c);
    }
    // Convex and concave parts are outlined alike: the thickness uses |kappa_v|.
    float t = clamp(u_tau * abs(kappaV), kEpsilon, 1.0);
    return abs(dot(v, n)) / sqrt(t * (2.0 - t));
}

float removalFactor() {
    if (!u_removal || u_groupSize < 1) return 1.0;
    int group = u_memberIndex % u_groupSize;
    float step = (u_removalMax - u_removalMin) / float(u_groupSize);
    float lo = u_removalMin + float(group) * step;
    float hi = u_removalMin + float(group + 1) * step;
    return clamp((v_in.outlyingness - lo) / max(hi - lo, 1e-20), 0.0, 1.0);
}

// The intersection curve's coefficient, like sigma: 0 on the plane, 1 at eps behind it, above 1
// farther away (METHODS.md section 11). Fragments on the viewer's side are discarded by the caller.
float planeCoefficient(float behind) {
    if (!u_planeEnabled) return 2.0;
    return behind / max(u_planeEpsilon, 1e-6);
}

vec3 lit(vec3 colour, vec3 v, vec3 n) {
    // A headlight, two-sided: isosurfaces have no preferred side.
    return colour * (0.3 + 0.7 * abs(dot(n, v)));
}

void writeOpaque(vec3 colour) {
    o_color = u_pick ? vec4(vec3((u_pickId >> 16) & 255, (u_pickId >> 8) & 255, u_pickId & 255)
                            / 255.0, 1.0)
                     : vec4(colour, 1.0);
    o_reveal = 0.0;
}

void writeTranslucent(vec3 colour, float alpha) {
    if (u_pick) {
        writeOpaque(colour);
        return;
    }
    float z = gl_FragCoord.z;
    float weight = clamp(alpha * max(1e-2, 3e3 * pow(1.0 - z, 3.0)), 1e-2, 3e3);
    o_color = vec4(colour * alpha, alpha) * weight;
    o_reveal = alpha;
}

void main() {
    float behindPlane = u_planeEpsilon * 2.0;
    if (u_planeEnabled) {
        float side = dot(u_plane.xyz, v_in.position) - u_plane.w;
        if (side > 0.0) discard;
        behindPlane = -side;
    }
    vec3 n = normalize(v_in.normal);
    vec3 v = u_orthographic ? -u_viewDirection : normalize(u_eye - v_in.position);
    if (u_mode == 3) {
        writeOpaque(lit(u_color, v, n));
        return;
    }
    float plane = planeCoefficient(behindPlane);
    if (u_mode == 2) {
        if (plane <= 1.0) {
            writeTranslucent(u_color, 1.0);  // the intersection curve, over the surfaces
        } else {
            writeTranslucent(lit(u_color, v, n), u_surfaceAlpha * removalFactor());
        }
        return;
    }
    float sigma = min(silhouetteCoefficient(v, n), plane);
    if (sigma > 1.0) discard;
    float removal = plane <= 1.0 ? 1.0 : removalFactor();
    if (removal <= 0.0) discard;
    if (u_mode == 1) {
        writeOpaque(u_color);
        return;
    }
    vec3 colour = sigma < 0.5 ? u_color : 0.5 * u_color;
    float alpha = sigma < 0.5 ? 1.0 : 1.0 - (sigma - 0.5) / 0.5;
    writeTranslucent(colour, alpha * removal);
}

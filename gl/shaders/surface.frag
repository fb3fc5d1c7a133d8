#version 410 core
// Silhouettes of isosurfaces (algorithms.md sections 6 and 7). Modes:
//   0 shaded silhouettes, 1 3D spaghetti plot, 2 semi-transparent surfaces, 3 solid lit surface.
// Modes 0 and 2 are translucent and write weighted blended order-independent transparency
// (McGuire & Bavoil 2013): the image does not depend on the order members are drawn in, and
// needs one pass, no sorting. Modes 1 and 3 are opaque.
in vec3 v_position;
in vec3 v_normal;
in vec3 v_direction;
in vec2 v_kappa;
in float v_outlyingness;

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

layout(location = 0) out vec4 o_color;   // opaque colour, or OIT accumulation
layout(location = 1) out float o_reveal; // OIT revealage

const float kEpsilon = 1e-4;

float silhouetteCoefficient(vec3 v, vec3 n) {
    // Curvature along the view direction (Euler's formula).
    vec3 w = v - dot(n, v) * n;
    float kappaV = v_kappa.x;
    float lw = length(w);
    if (lw > 1e-6) {
        float c = dot(w / lw, normalize(v_direction));
        kappaV = v_kappa.x * c * c + v_kappa.y * (1.0 - c * c);
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
    return clamp((v_outlyingness - lo) / max(hi - lo, 1e-20), 0.0, 1.0);
}

vec3 lit(vec3 colour, vec3 v, vec3 n) {
    // A headlight, two-sided: isosurfaces have no preferred side.
    return colour * (0.3 + 0.7 * abs(dot(n, v)));
}

void writeTranslucent(vec3 colour, float alpha) {
    float z = gl_FragCoord.z;
    float weight = clamp(alpha * max(1e-2, 3e3 * pow(1.0 - z, 3.0)), 1e-2, 3e3);
    o_color = vec4(colour * alpha, alpha) * weight;
    o_reveal = alpha;
}

void main() {
    vec3 n = normalize(v_normal);
    vec3 v = u_orthographic ? -u_viewDirection : normalize(u_eye - v_position);
    if (u_mode == 3) {
        o_color = vec4(lit(u_color, v, n), 1.0);
        o_reveal = 0.0;
        return;
    }
    if (u_mode == 2) {
        writeTranslucent(lit(u_color, v, n), u_surfaceAlpha * removalFactor());
        return;
    }
    float sigma = silhouetteCoefficient(v, n);
    if (sigma > 1.0) discard;
    float removal = removalFactor();
    if (removal <= 0.0) discard;
    if (u_mode == 1) {
        o_color = vec4(u_color, 1.0);
        o_reveal = 0.0;
        return;
    }
    vec3 colour = sigma < 0.5 ? u_color : 0.5 * u_color;
    float alpha = sigma < 0.5 ? 1.0 : 1.0 - (sigma - 0.5) / 0.5;
    writeTranslucent(colour, alpha * removal);
}

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
uniform bool u_emphasis;       // a selected member drawn as a surface: a thicker, opaque rim
uniform bool u_dashed;         // an outlier of the contour boxplot: silhouettes dashed
uniform bool u_colourByField;  // the context surface coloured by a field (the spread)
#include "field_lookup.glsl"

layout(location = 0) out vec4 o_color;   // opaque colour, OIT accumulation, or the pick id
layout(location = 1) out float o_reveal; // OIT revealage

const float kEpsilon = 1e-4;
const float kEmphasisThickening = 2.5;  // the rim of a selected surface, in tau
const float kWidestFilter = 2.0;        // the box filter's largest width, in coefficient units

float silhouetteCoefficient(vec3 v, vec3 n, float tau) {
    // Curvature along the view direction (Euler's formula).
    vec3 w = v - dot(n, v) * n;
    float kappaV = v_in.kappa.x;
    float lw = length(w);
    if (lw > 1e-6) {
        float c = dot(w / lw, normalize(v_in.direction));
        kappaV = v_in.kappa.x * c * c + v_in.kappa.y * (1.0 - c * c);
    }
    // Convex and concave parts are outlined alike: the thickness uses |kappa_v|.
    float t = clamp(tau * abs(kappaV), kEpsilon, 1.0);
    return abs(dot(v, n)) / sqrt(t * (2.0 - t));
}

// Antialiasing (METHODS.md section 11): every band is drawn with what a pixel-wide box filter
// over its coefficient gives, the coefficient's change across the pixel being `width`
// (fwidth). A band thinner than a pixel then fades instead of breaking into dots, and its
// edges are smooth; the picking pass keeps the exact thresholds.

// The fraction of the pixel where the coefficient is at most 1.
float coverage(float coefficient, float width) {
    if (u_pick) return coefficient <= 1.0 ? 1.0 : 0.0;
    return clamp((1.0 - coefficient) / width + 0.5, 0.0, 1.0);
}

// The shaded silhouette's opacity profile a(s) (1 up to s = 0.5, then falling linearly to 0 at
// 1) and the profile weighted by its colour's brightness c(s) (1 inside, 0.5 on the outer
// half), each integrated from 0 to s: the box filter is their difference over the pixel.
float opacityIntegral(float s) {
    return s < 0.5 ? s : (s < 1.0 ? -s * s + 2.0 * s - 0.25 : 0.75);
}
float brightnessIntegral(float s) {
    return s < 0.5 ? s : 0.25 + 0.5 * opacityIntegral(s);
}

float removalFactor() {
    if (!u_removal || u_groupSize < 1) return 1.0;
    int group = u_memberIndex % u_groupSize;
    float step = (u_removalMax - u_removalMin) / float(u_groupSize);
    float lo = u_removalMin + float(group) * step;
    float hi = u_removalMin + float(group + 1) * step;
    return clamp((v_in.outlyingness - lo) / max(hi - lo, 1e-20), 0.0, 1.0);
}

// The intersection curve's depth behind the plane: eps, but never more than kCurvePixels of
// screen. Where a surface meets the plane at a grazing angle its distance behind the plane grows
// slowly across the screen, and a depth of eps alone would cover an area, not a curve (METHODS.md
// section 11). `behindPerPixel` is that distance's change per pixel on screen.
const float kCurvePixels = 3.0;
float curveDepth(float behindPerPixel) {
    return max(min(u_planeEpsilon, kCurvePixels * behindPerPixel), 1e-6);
}

// The intersection curve's coefficient, like sigma: 0 on the plane, 1 at the curve's depth
// behind it, above 1 farther away. Fragments on the viewer's side are discarded by the caller.
float planeCoefficient(float behind, float depth) {
    if (!u_planeEnabled) return 2.0;
    return behind / depth;
}

vec3 lit(vec3 colour, vec3 v, vec3 n) {
    // A headlight, two-sided: isosurfaces have no preferred side.
    return colour * (0.3 + 0.7 * abs(dot(n, v)));
}

// `alpha` is the share of the pixel covered: with alpha-to-coverage on (the opaque pass over the
// multisampled scene), that share of its samples is written.
void writeOpaque(vec3 colour, float alpha) {
    o_color = u_pick ? vec4(vec3((u_pickId >> 16) & 255, (u_pickId >> 8) & 255, u_pickId & 255)
                            / 255.0, 1.0)
                     : vec4(colour, alpha);
    o_reveal = 0.0;
}

void writeTranslucent(vec3 colour, float alpha) {
    if (u_pick) {
        writeOpaque(colour, 1.0);
        return;
    }
    float z = gl_FragCoord.z;
    float weight = clamp(alpha * max(1e-2, 3e3 * pow(1.0 - z, 3.0)), 1e-2, 3e3);
    o_color = vec4(colour * alpha, alpha) * weight;
    o_reveal = alpha;
}

// The cutting plane's curves are dashed, so they are never mistaken for silhouettes: along the
// curve (across the gradient of the distance behind the plane, on screen), dashes of the
// member's colour alternate with darker gaps every kDashPixels. Each member's dashes start
// elsewhere (by the golden ratio of a period): the curves of many members side by side would
// otherwise line their dashes up into stripes across them all.
const float kDashPixels = 6.0;
vec3 curveColour(vec3 colour, vec2 gradient) {
    if (u_pick || dot(gradient, gradient) < 1e-20) return colour;
    vec2 along = normalize(vec2(-gradient.y, gradient.x));
    float phase = fract(float(u_memberIndex) * 0.618034);
    return fract(dot(gl_FragCoord.xy, along) / (2.0 * kDashPixels) + phase) < 0.5
               ? colour
               : 0.35 * colour;
}

// An outlier's silhouettes are dashed: diagonal stripes on screen, kDashPixels of colour and
// of a darker gap, cut any line that is not itself diagonal into dashes.
vec3 outlierColour(vec3 colour) {
    if (!u_dashed || u_pick) return colour;
    return fract((gl_FragCoord.x + gl_FragCoord.y) / (2.0 * kDashPixels)) < 0.5 ? colour
                                                                               : 0.3 * colour;
}

void main() {
    float side = dot(u_plane.xyz, v_in.position) - u_plane.w;
    float behindPlane = u_planeEnabled ? -side : u_planeEpsilon * 2.0;
    vec3 n = normalize(v_in.normal);
    vec3 v = u_orthographic ? -u_viewDirection : normalize(u_eye - v_in.position);
    vec2 planeGradient = vec2(dFdx(behindPlane), dFdy(behindPlane));
    float depth = curveDepth(length(planeGradient));
    float plane = planeCoefficient(behindPlane, depth);
    float silhouette = silhouetteCoefficient(v, n, u_tau);
    float rim = u_emphasis ? silhouetteCoefficient(v, n, u_tau * kEmphasisThickening) : 2.0;
    // Screen-space rates of change, taken before any fragment is discarded (derivatives are
    // undefined in control flow that differs between neighbouring fragments). At most
    // kWidestFilter: on tiny triangles the derivatives come from values extrapolated far
    // beyond the triangle and can be wild, which would sprinkle dust where no band is.
    float silhouetteWidth = clamp(fwidth(silhouette), 1e-4, kWidestFilter);
    // The plane coefficient's own fwidth, from the distance's: the depth is itself made of
    // derivatives, which are constant over the 2x2 quads derivatives are taken on.
    float planeWidth = clamp((abs(planeGradient.x) + abs(planeGradient.y)) / depth, 1e-4,
                             kWidestFilter);
    float rimWidth = clamp(fwidth(rim), 1e-4, kWidestFilter);
    if (u_planeEnabled && side > 0.0) discard;
    // The context surface may take its colour from a field (the members' spread) here.
    vec3 base = u_colourByField && !u_pick ? fieldColourAt(v_in.position) : u_color;
    if (u_mode == 3) {
        writeOpaque(lit(base, v, n), 1.0);
        return;
    }
    float curve = coverage(plane, planeWidth);
    if (u_mode == 2) {
        // A surface; an emphasised (selected) one has a full-opacity silhouette rim, thicker
        // than the others'; the intersection curve lies over both.
        vec3 colour = lit(base, v, n);
        float alpha = u_surfaceAlpha * removalFactor();
        float edge = u_emphasis ? coverage(rim, rimWidth) : 0.0;
        colour = mix(colour, u_color, edge);
        alpha = mix(alpha, 1.0, edge);
        colour = mix(colour, curveColour(u_color, planeGradient), curve);
        alpha = mix(alpha, 1.0, curve);
        if (alpha <= 0.0 && !u_pick) discard;
        writeTranslucent(colour, alpha);
        return;
    }
    float band = coverage(silhouette, silhouetteWidth);
    if (max(band, curve) <= 0.0) discard;
    bool onCurve = curve >= band;
    float removal = onCurve ? 1.0 : removalFactor();
    if (removal <= 0.0) discard;
    if (u_mode == 1) {
        // Opaque: the coverage becomes the share of the pixel's samples written.
        writeOpaque(onCurve ? curveColour(u_color, planeGradient) : outlierColour(u_color),
                    max(band, curve));
        return;
    }
    if (onCurve) {
        writeTranslucent(curveColour(u_color, planeGradient), curve);
        return;
    }
    if (u_pick) {
        writeOpaque(u_color, 1.0);
        return;
    }
    float lo = silhouette - 0.5 * silhouetteWidth, hi = silhouette + 0.5 * silhouetteWidth;
    float opacity = (opacityIntegral(hi) - opacityIntegral(lo)) / silhouetteWidth;
    float brightness = (brightnessIntegral(hi) - brightnessIntegral(lo)) / silhouetteWidth;
    if (opacity <= 0.0) discard;
    writeTranslucent(outlierColour(u_color) * (brightness / opacity), opacity * removal);
}

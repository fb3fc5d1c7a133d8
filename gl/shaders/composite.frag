#version 410 core
// Resolves weighted blended OIT over the opaque image (blended with SRC_ALPHA,
// ONE_MINUS_SRC_ALPHA).
uniform sampler2D u_accumulation;
uniform sampler2D u_revealage;
in vec2 v_uv;
out vec4 o_color;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    float reveal = texelFetch(u_revealage, p, 0).r;
    if (reveal >= 0.9999) discard;
    vec4 accumulation = texelFetch(u_accumulation, p, 0);
    vec3 average = accumulation.rgb / max(accumulation.a, 1e-5);
    o_color = vec4(average, 1.0 - reveal);
}

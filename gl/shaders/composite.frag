#version 410 core
// Resolves weighted blended OIT over the opaque image (blended with SRC_ALPHA,
// ONE_MINUS_SRC_ALPHA), sample by sample: reading gl_SampleID runs this once for each sample of
// the multisampled scene, so antialiased translucent edges stay antialiased.
uniform sampler2DMS u_accumulation;
uniform sampler2DMS u_revealage;
in vec2 v_uv;
out vec4 o_color;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    float reveal = texelFetch(u_revealage, p, gl_SampleID).r;
    if (reveal >= 0.9999) discard;
    vec4 accumulation = texelFetch(u_accumulation, p, gl_SampleID);
    vec3 average = accumulation.rgb / max(accumulation.a, 1e-5);
    o_color = vec4(average, 1.0 - reveal);
}

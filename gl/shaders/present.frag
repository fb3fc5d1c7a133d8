#version 410 core
// Copies the renderer's scene image into the caller's framebuffer (which may be multisampled):
// pixel for pixel, or scaled up with bilinear filtering when the scene was drawn smaller.
uniform sampler2D u_scene;
uniform bool u_scaled;
uniform vec2 u_frameSize;
out vec4 o_color;
void main() {
    // Opaque: blending and alpha-to-coverage leave the scene's alpha below 1 in places, which a
    // window or a saved image must not take for transparency.
    vec3 colour = u_scaled ? texture(u_scene, gl_FragCoord.xy / u_frameSize).rgb
                           : texelFetch(u_scene, ivec2(gl_FragCoord.xy), 0).rgb;
    o_color = vec4(colour, 1.0);
}

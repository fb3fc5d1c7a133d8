#version 410 core
// Copies the renderer's scene image into the caller's framebuffer (which may be multisampled):
// pixel for pixel, or scaled up with bilinear filtering when the scene was drawn smaller.
uniform sampler2D u_scene;
uniform bool u_scaled;
uniform vec2 u_frameSize;
out vec4 o_color;
void main() {
    o_color = u_scaled ? texture(u_scene, gl_FragCoord.xy / u_frameSize)
                       : texelFetch(u_scene, ivec2(gl_FragCoord.xy), 0);
}

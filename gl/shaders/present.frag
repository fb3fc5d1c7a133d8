#version 410 core
// Copies the renderer's scene image into the caller's framebuffer (which may be multisampled).
uniform sampler2D u_scene;
out vec4 o_color;
void main() {
    o_color = texelFetch(u_scene, ivec2(gl_FragCoord.xy), 0);
}

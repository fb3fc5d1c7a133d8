// The renderer's own framebuffers, so that translucent passes can test depth against the opaque
// scene whatever framebuffer the caller binds (a window's is multisampled and its depth cannot
// be shared): the scene (RGBA8 colour, 24-bit depth texture) and the order-independent
// transparency targets (RGBA16F accumulation, R16F revealage) that share the scene's depth.
// GUI thread, context current.
#pragma once

#include "gl/gl_functions.h"

namespace ensil::gl {

class RenderTargets {
public:
    // (Re)creates the textures when the size changed. Throws std::runtime_error when the driver
    // refuses the framebuffer.
    void ensure(GlFunctions& f, int width, int height);
    // The picking target (RGBA8 ids, its own depth), made on first use.
    void ensurePick(GlFunctions& f, int width, int height);
    void release(GlFunctions& f);

    [[nodiscard]] GLuint sceneFramebuffer() const { return m_scene; }
    [[nodiscard]] GLuint transparencyFramebuffer() const { return m_transparency; }
    [[nodiscard]] GLuint sceneColor() const { return m_color; }
    [[nodiscard]] GLuint accumulation() const { return m_accumulation; }
    [[nodiscard]] GLuint revealage() const { return m_revealage; }
    [[nodiscard]] GLuint pickFramebuffer() const { return m_pick; }

private:
    void releasePick(GlFunctions& f);

    int m_width = 0, m_height = 0;
    GLuint m_scene = 0, m_transparency = 0;
    GLuint m_color = 0, m_depth = 0, m_accumulation = 0, m_revealage = 0;
    int m_pickWidth = 0, m_pickHeight = 0;
    GLuint m_pick = 0, m_pickIds = 0, m_pickDepth = 0;
};

}  // namespace ensil::gl

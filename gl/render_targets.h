// The renderer's own framebuffers, so that translucent passes can test depth against the opaque
// scene whatever framebuffer the caller binds (a window's may be multisampled and its depth
// cannot be shared).
//
// The scene is drawn multisampled (antialiased edges of surfaces, silhouettes, curves and the
// box; METHODS.md section 11): an RGBA8 colour and a 24-bit depth renderbuffer, and the
// order-independent transparency targets (RGBA16F accumulation, R16F revealage), multisampled
// textures that share the scene's depth and are composited sample by sample. The colour is then
// resolved into a single-sampled, filtered texture, which the frame is copied (or scaled up)
// from. GUI thread, context current.
#pragma once

#include "gl/gl_functions.h"

namespace ensil::gl {

class RenderTargets {
public:
    // (Re)creates the targets when the size or the sample count changed. `samples` is what is
    // asked for; the driver's limits may lower it (samples()). Throws std::runtime_error when
    // the driver refuses a framebuffer.
    void ensure(GlFunctions& f, int width, int height, int samples);
    // The picking target (RGBA8 ids, its own depth; single-sampled, as ids cannot be blended),
    // made on first use.
    void ensurePick(GlFunctions& f, int width, int height);
    void release(GlFunctions& f);
    // Averages the multisampled scene into sceneColor(). Scissor test off.
    void resolve(GlFunctions& f);

    [[nodiscard]] GLuint sceneFramebuffer() const { return m_scene; }
    [[nodiscard]] GLuint transparencyFramebuffer() const { return m_transparency; }
    [[nodiscard]] GLuint sceneColor() const { return m_resolvedColor; }
    [[nodiscard]] GLuint accumulation() const { return m_accumulation; }  // multisampled
    [[nodiscard]] GLuint revealage() const { return m_revealage; }        // multisampled
    [[nodiscard]] GLuint pickFramebuffer() const { return m_pick; }
    [[nodiscard]] int samples() const { return m_samples; }

private:
    void releasePick(GlFunctions& f);

    int m_width = 0, m_height = 0, m_requestedSamples = 0, m_samples = 0;
    GLuint m_scene = 0, m_transparency = 0, m_resolved = 0;
    GLuint m_color = 0, m_depth = 0;  // renderbuffers
    GLuint m_accumulation = 0, m_revealage = 0, m_resolvedColor = 0;
    int m_pickWidth = 0, m_pickHeight = 0;
    GLuint m_pick = 0, m_pickIds = 0, m_pickDepth = 0;
};

}  // namespace ensil::gl

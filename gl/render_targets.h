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

#include <array>
#include <cstddef>

#include "gl/gl_functions.h"

namespace ensil::gl {

class RenderTargets {
public:
    // Makes the targets of this size and sample count current. The last two sets are kept: the
    // view alternates between motion frames at a reduced resolution and still frames at its
    // full one, and making a set afresh cost a still frame of the demo more than its drawing
    // (on llvmpipe, 4 samples of 76 bytes a pixel are allocated and cleared: 38 MB for a
    // 934 x 534 view, page by page). `reduced`: this frame is drawn below the view's full
    // resolution, so the set it leaves (the full one) is kept whatever its size; otherwise a
    // set left that is larger than this one is released (an exported picture's, say, once the
    // view draws again). `samples` is what is asked for; the driver's limits may lower it
    // (samples()). Throws std::runtime_error when the driver refuses a framebuffer.
    void ensure(GlFunctions& f, int width, int height, int samples, bool reduced = false);
    // The picking target (RGBA8 ids, its own depth; single-sampled, as ids cannot be blended),
    // made on first use.
    void ensurePick(GlFunctions& f, int width, int height);
    void release(GlFunctions& f);
    // Averages the multisampled scene into sceneColor(). Scissor test off.
    void resolve(GlFunctions& f);

    [[nodiscard]] GLuint sceneFramebuffer() const { return current().scene; }
    [[nodiscard]] GLuint transparencyFramebuffer() const { return current().transparency; }
    [[nodiscard]] GLuint sceneColor() const { return current().resolvedColor; }
    [[nodiscard]] GLuint accumulation() const { return current().accumulation; }  // multisampled
    [[nodiscard]] GLuint revealage() const { return current().revealage; }        // multisampled
    [[nodiscard]] GLuint pickFramebuffer() const { return m_pick; }
    [[nodiscard]] int samples() const { return current().samples; }
    // For tests: the scene sets made so far, and the pixels of those held now.
    [[nodiscard]] std::size_t setsMade() const { return m_setsMade; }
    [[nodiscard]] long long pixelsHeld() const;

private:
    struct SceneSet {
        int width = 0, height = 0, requestedSamples = 0, samples = 0;
        GLuint scene = 0, transparency = 0, resolved = 0;
        GLuint color = 0, depth = 0;  // renderbuffers
        GLuint accumulation = 0, revealage = 0, resolvedColor = 0;

        [[nodiscard]] bool is(int w, int h, int s) const {
            return scene != 0 && width == w && height == h && requestedSamples == s;
        }
        [[nodiscard]] long long pixels() const { return static_cast<long long>(width) * height; }
    };
    [[nodiscard]] const SceneSet& current() const { return m_sets[m_current]; }
    void make(GlFunctions& f, SceneSet& set, int width, int height, int samples);
    static void releaseSet(GlFunctions& f, SceneSet& set);
    void releasePick(GlFunctions& f);

    std::array<SceneSet, 2> m_sets;
    std::size_t m_current = 0;
    std::size_t m_setsMade = 0;
    int m_pickWidth = 0, m_pickHeight = 0;
    GLuint m_pick = 0, m_pickIds = 0, m_pickDepth = 0;
};

}  // namespace ensil::gl

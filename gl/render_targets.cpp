#include "gl/render_targets.h"

#include <algorithm>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <vector>

namespace ensil::gl {
namespace {
GLuint texture(GlFunctions& f, GLint internalFormat, GLenum format, GLenum type, int w, int h,
               GLint filter = GL_NEAREST) {
    GLuint t = 0;
    f.glGenTextures(1, &t);
    f.glBindTexture(GL_TEXTURE_2D, t);
    f.glTexImage2D(GL_TEXTURE_2D, 0, internalFormat, w, h, 0, format, type, nullptr);
    f.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    f.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    f.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    f.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return t;
}

GLuint multisampledTexture(GlFunctions& f, GLenum internalFormat, int samples, int w, int h) {
    GLuint t = 0;
    f.glGenTextures(1, &t);
    f.glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, t);
    f.glTexImage2DMultisample(GL_TEXTURE_2D_MULTISAMPLE, samples, internalFormat, w, h, GL_TRUE);
    f.glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, 0);
    return t;
}

GLuint renderbuffer(GlFunctions& f, GLenum internalFormat, int samples, int w, int h) {
    GLuint r = 0;
    f.glGenRenderbuffers(1, &r);
    f.glBindRenderbuffer(GL_RENDERBUFFER, r);
    f.glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, internalFormat, w, h);
    f.glBindRenderbuffer(GL_RENDERBUFFER, 0);
    return r;
}

// What a framebuffer attachment is: a texture of this target, or a renderbuffer.
struct Attachment {
    GLenum target = GL_TEXTURE_2D;  // GL_TEXTURE_2D, GL_TEXTURE_2D_MULTISAMPLE or GL_RENDERBUFFER
    GLuint name = 0;
};

void attach(GlFunctions& f, GLenum point, const Attachment& a) {
    if (a.target == GL_RENDERBUFFER) {
        f.glFramebufferRenderbuffer(GL_FRAMEBUFFER, point, GL_RENDERBUFFER, a.name);
    } else {
        f.glFramebufferTexture2D(GL_FRAMEBUFFER, point, a.target, a.name, 0);
    }
}

// A framebuffer drawing into these colour attachments (0, 1, ...) with this depth (none when
// its name is 0).
GLuint framebuffer(GlFunctions& f, std::initializer_list<Attachment> colours, Attachment depth,
                   const char* what) {
    GLuint fbo = 0;
    f.glGenFramebuffers(1, &fbo);
    f.glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    std::vector<GLenum> buffers;
    for (const Attachment& colour : colours) {
        const auto point = static_cast<GLenum>(GL_COLOR_ATTACHMENT0 + buffers.size());
        attach(f, point, colour);
        buffers.push_back(point);
    }
    if (depth.name != 0) attach(f, GL_DEPTH_ATTACHMENT, depth);
    f.glDrawBuffers(static_cast<GLsizei>(buffers.size()), buffers.data());
    if (f.glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        throw std::runtime_error(std::string("the OpenGL driver refused the ") + what +
                                 " framebuffer");
    }
    return fbo;
}

// The most samples every scene target can have, at most `wanted` and at least 1.
int supportedSamples(GlFunctions& f, int wanted) {
    int limit = wanted;
    for (const GLenum query :
         {GL_MAX_SAMPLES, GL_MAX_COLOR_TEXTURE_SAMPLES, GL_MAX_DEPTH_TEXTURE_SAMPLES}) {
        GLint value = 1;
        f.glGetIntegerv(query, &value);
        limit = std::min(limit, static_cast<int>(value));
    }
    return std::max(limit, 1);
}
}  // namespace

void RenderTargets::ensure(GlFunctions& f, int width, int height, int samples, bool reduced) {
    if (m_sets[m_current].is(width, height, samples)) return;
    const std::size_t other = 1 - m_current;
    if (!m_sets[other].is(width, height, samples)) {
        releaseSet(f, m_sets[other]);
        make(f, m_sets[other], width, height, samples);
    }
    m_current = other;
    SceneSet& left = m_sets[1 - m_current];
    if (!reduced && left.pixels() > current().pixels()) releaseSet(f, left);
}

void RenderTargets::make(GlFunctions& f, SceneSet& set, int width, int height, int samples) {
    set.width = width;
    set.height = height;
    set.requestedSamples = samples;
    set.samples = supportedSamples(f, samples);
    set.color = renderbuffer(f, GL_RGBA8, set.samples, width, height);
    set.depth = renderbuffer(f, GL_DEPTH_COMPONENT24, set.samples, width, height);
    set.accumulation = multisampledTexture(f, GL_RGBA16F, set.samples, width, height);
    set.revealage = multisampledTexture(f, GL_R16F, set.samples, width, height);
    // Filtered: a scene drawn smaller than the frame is scaled up from it (Renderer::present).
    set.resolvedColor = texture(f, GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, width, height, GL_LINEAR);

    const Attachment depth{GL_RENDERBUFFER, set.depth};
    set.scene = framebuffer(f, {{GL_RENDERBUFFER, set.color}}, depth, "scene");
    // The transparent members test against the opaque scene's depth.
    set.transparency = framebuffer(
        f,
        {{GL_TEXTURE_2D_MULTISAMPLE, set.accumulation}, {GL_TEXTURE_2D_MULTISAMPLE, set.revealage}},
        depth, "transparency");
    set.resolved = framebuffer(f, {{GL_TEXTURE_2D, set.resolvedColor}}, {}, "resolved scene");
    ++m_setsMade;
}

void RenderTargets::resolve(GlFunctions& f) {
    const SceneSet& set = current();
    f.glBindFramebuffer(GL_READ_FRAMEBUFFER, set.scene);
    f.glBindFramebuffer(GL_DRAW_FRAMEBUFFER, set.resolved);
    f.glBlitFramebuffer(0, 0, set.width, set.height, 0, 0, set.width, set.height,
                        GL_COLOR_BUFFER_BIT, GL_NEAREST);
    f.glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

long long RenderTargets::pixelsHeld() const {
    long long pixels = 0;
    for (const SceneSet& set : m_sets)
        if (set.scene != 0) pixels += set.pixels();
    return pixels;
}

void RenderTargets::ensurePick(GlFunctions& f, int width, int height) {
    if (width == m_pickWidth && height == m_pickHeight && m_pick != 0) return;
    releasePick(f);
    m_pickWidth = width;
    m_pickHeight = height;
    m_pickIds = texture(f, GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, width, height);
    m_pickDepth = texture(f, GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT, GL_FLOAT, width, height);
    m_pick = framebuffer(f, {{GL_TEXTURE_2D, m_pickIds}}, {GL_TEXTURE_2D, m_pickDepth}, "picking");
}

void RenderTargets::releasePick(GlFunctions& f) {
    if (m_pick != 0) f.glDeleteFramebuffers(1, &m_pick);
    for (GLuint* t : {&m_pickIds, &m_pickDepth}) {
        if (*t != 0) f.glDeleteTextures(1, t);
        *t = 0;
    }
    m_pick = 0;
    m_pickWidth = m_pickHeight = 0;
}

void RenderTargets::releaseSet(GlFunctions& f, SceneSet& set) {
    for (GLuint* fbo : {&set.scene, &set.transparency, &set.resolved}) {
        if (*fbo != 0) f.glDeleteFramebuffers(1, fbo);
    }
    for (GLuint* r : {&set.color, &set.depth}) {
        if (*r != 0) f.glDeleteRenderbuffers(1, r);
    }
    for (GLuint* t : {&set.accumulation, &set.revealage, &set.resolvedColor}) {
        if (*t != 0) f.glDeleteTextures(1, t);
    }
    set = SceneSet{};
}

void RenderTargets::release(GlFunctions& f) {
    releasePick(f);
    for (SceneSet& set : m_sets) releaseSet(f, set);
}

}  // namespace ensil::gl

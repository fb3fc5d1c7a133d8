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

void RenderTargets::ensure(GlFunctions& f, int width, int height, int samples) {
    if (width == m_width && height == m_height && samples == m_requestedSamples && m_scene != 0) {
        return;
    }
    release(f);
    m_width = width;
    m_height = height;
    m_requestedSamples = samples;
    m_samples = supportedSamples(f, samples);
    m_color = renderbuffer(f, GL_RGBA8, m_samples, width, height);
    m_depth = renderbuffer(f, GL_DEPTH_COMPONENT24, m_samples, width, height);
    m_accumulation = multisampledTexture(f, GL_RGBA16F, m_samples, width, height);
    m_revealage = multisampledTexture(f, GL_R16F, m_samples, width, height);
    // Filtered: a scene drawn smaller than the frame is scaled up from it (Renderer::present).
    m_resolvedColor = texture(f, GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, width, height, GL_LINEAR);

    const Attachment depth{GL_RENDERBUFFER, m_depth};
    m_scene = framebuffer(f, {{GL_RENDERBUFFER, m_color}}, depth, "scene");
    // The transparent members test against the opaque scene's depth.
    m_transparency = framebuffer(
        f, {{GL_TEXTURE_2D_MULTISAMPLE, m_accumulation}, {GL_TEXTURE_2D_MULTISAMPLE, m_revealage}},
        depth, "transparency");
    m_resolved = framebuffer(f, {{GL_TEXTURE_2D, m_resolvedColor}}, {}, "resolved scene");
}

void RenderTargets::resolve(GlFunctions& f) {
    f.glBindFramebuffer(GL_READ_FRAMEBUFFER, m_scene);
    f.glBindFramebuffer(GL_DRAW_FRAMEBUFFER, m_resolved);
    f.glBlitFramebuffer(0, 0, m_width, m_height, 0, 0, m_width, m_height, GL_COLOR_BUFFER_BIT,
                        GL_NEAREST);
    f.glBindFramebuffer(GL_FRAMEBUFFER, 0);
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

void RenderTargets::release(GlFunctions& f) {
    releasePick(f);
    for (GLuint* fbo : {&m_scene, &m_transparency, &m_resolved}) {
        if (*fbo != 0) f.glDeleteFramebuffers(1, fbo);
        *fbo = 0;
    }
    for (GLuint* r : {&m_color, &m_depth}) {
        if (*r != 0) f.glDeleteRenderbuffers(1, r);
        *r = 0;
    }
    for (GLuint* t : {&m_accumulation, &m_revealage, &m_resolvedColor}) {
        if (*t != 0) f.glDeleteTextures(1, t);
        *t = 0;
    }
    m_width = m_height = m_requestedSamples = m_samples = 0;
}

}  // namespace ensil::gl

#include "gl/render_targets.h"

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

// A framebuffer drawing into these colour textures (attachments 0, 1, ...) with this depth.
GLuint framebuffer(GlFunctions& f, std::initializer_list<GLuint> colours, GLuint depth,
                   const char* what) {
    GLuint fbo = 0;
    f.glGenFramebuffers(1, &fbo);
    f.glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    std::vector<GLenum> buffers;
    for (const GLuint colour : colours) {
        const auto attachment = static_cast<GLenum>(GL_COLOR_ATTACHMENT0 + buffers.size());
        f.glFramebufferTexture2D(GL_FRAMEBUFFER, attachment, GL_TEXTURE_2D, colour, 0);
        buffers.push_back(attachment);
    }
    f.glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth, 0);
    f.glDrawBuffers(static_cast<GLsizei>(buffers.size()), buffers.data());
    if (f.glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        throw std::runtime_error(std::string("the OpenGL driver refused the ") + what +
                                 " framebuffer");
    }
    return fbo;
}
}  // namespace

void RenderTargets::ensure(GlFunctions& f, int width, int height) {
    if (width == m_width && height == m_height && m_scene != 0) return;
    release(f);
    m_width = width;
    m_height = height;
    // Filtered: a scene drawn smaller than the frame is scaled up from it (Renderer::present).
    m_color = texture(f, GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, width, height, GL_LINEAR);
    m_depth = texture(f, GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT, GL_FLOAT, width, height);
    m_accumulation = texture(f, GL_RGBA16F, GL_RGBA, GL_HALF_FLOAT, width, height);
    m_revealage = texture(f, GL_R16F, GL_RED, GL_HALF_FLOAT, width, height);

    m_scene = framebuffer(f, {m_color}, m_depth, "scene");
    // The transparent members test against the opaque scene's depth.
    m_transparency = framebuffer(f, {m_accumulation, m_revealage}, m_depth, "transparency");
}

void RenderTargets::ensurePick(GlFunctions& f, int width, int height) {
    if (width == m_pickWidth && height == m_pickHeight && m_pick != 0) return;
    releasePick(f);
    m_pickWidth = width;
    m_pickHeight = height;
    m_pickIds = texture(f, GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, width, height);
    m_pickDepth = texture(f, GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT, GL_FLOAT, width, height);
    m_pick = framebuffer(f, {m_pickIds}, m_pickDepth, "picking");
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
    if (m_scene != 0) f.glDeleteFramebuffers(1, &m_scene);
    if (m_transparency != 0) f.glDeleteFramebuffers(1, &m_transparency);
    for (GLuint* t : {&m_color, &m_depth, &m_accumulation, &m_revealage}) {
        if (*t != 0) f.glDeleteTextures(1, t);
        *t = 0;
    }
    m_scene = m_transparency = 0;
    m_width = m_height = 0;
}

}  // namespace ensil::gl

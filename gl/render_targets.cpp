#include "gl/render_targets.h"

#include <array>
#include <stdexcept>

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

void checkComplete(GlFunctions& f, const char* what) {
    if (f.glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        throw std::runtime_error(std::string("the OpenGL driver refused the ") + what +
                                 " framebuffer");
    }
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

    f.glGenFramebuffers(1, &m_scene);
    f.glBindFramebuffer(GL_FRAMEBUFFER, m_scene);
    f.glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, m_color, 0);
    f.glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, m_depth, 0);
    checkComplete(f, "scene");

    f.glGenFramebuffers(1, &m_transparency);
    f.glBindFramebuffer(GL_FRAMEBUFFER, m_transparency);
    f.glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, m_accumulation,
                             0);
    f.glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, m_revealage, 0);
    f.glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, m_depth, 0);
    const std::array<GLenum, 2> buffers{GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    f.glDrawBuffers(2, buffers.data());
    checkComplete(f, "transparency");
}

void RenderTargets::ensurePick(GlFunctions& f, int width, int height) {
    if (width == m_pickWidth && height == m_pickHeight && m_pick != 0) return;
    releasePick(f);
    m_pickWidth = width;
    m_pickHeight = height;
    m_pickIds = texture(f, GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, width, height);
    m_pickDepth = texture(f, GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT, GL_FLOAT, width, height);
    f.glGenFramebuffers(1, &m_pick);
    f.glBindFramebuffer(GL_FRAMEBUFFER, m_pick);
    f.glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, m_pickIds, 0);
    f.glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, m_pickDepth, 0);
    checkComplete(f, "picking");
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

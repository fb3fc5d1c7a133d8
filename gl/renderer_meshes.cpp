// The isosurface passes of the renderer: opaque (mean, selected members, spaghetti), then the
// translucent members into the order-independent transparency targets, then the composite.
#include <QOpenGLShaderProgram>
#include <algorithm>
#include <array>
#include <glm/gtc/type_ptr.hpp>

#include "gl/palette.h"
#include "gl/renderer_gpu.h"

namespace ensil::gl {
namespace {

enum ShaderMode { kShaded = 0, kSpaghetti = 1, kSurfaces = 2, kSolid = 3 };

void drawMesh(GlFunctions& f, QOpenGLShaderProgram& program, const GpuMesh& mesh) {
    if (mesh.vao == 0 || mesh.indexCount == 0) return;
    program.setUniformValue("u_boundsMin", mesh.boundsMin.x, mesh.boundsMin.y, mesh.boundsMin.z);
    program.setUniformValue("u_boundsMax", mesh.boundsMax.x, mesh.boundsMax.y, mesh.boundsMax.z);
    program.setUniformValue("u_outlyingnessScale", mesh.outlyingnessScale);
    f.glBindVertexArray(mesh.vao);
    f.glDrawElements(GL_TRIANGLES, mesh.indexCount, GL_UNSIGNED_INT, nullptr);
}

}  // namespace

void Renderer::setMeshes(std::shared_ptr<const data::MeshSet> meshes) {
    m_meshes = std::move(meshes);
    m_meshesDirty = true;
}

std::size_t Renderer::gpuBytes() const { return m_gpu ? m_gpu->meshes.bytes() : 0; }

void Renderer::uploadAxisTables() {
    m_axisTablesDirty = false;
    GlFunctions& f = *m_gpu->f;
    std::array<std::vector<double>, 3> tables{m_frame.axisTable(0), m_frame.axisTable(1),
                                              m_frame.axisTable(2)};
    const std::size_t width = std::max({tables[0].size(), tables[1].size(), tables[2].size()});
    std::vector<float> texels(width * 3, 0.0F);
    for (std::size_t a = 0; a < 3; ++a) {
        for (std::size_t i = 0; i < tables[a].size(); ++i) {
            texels[a * width + i] = static_cast<float>(tables[a][i]);
        }
    }
    m_gpu->axisSize = {static_cast<int>(tables[0].size()), static_cast<int>(tables[1].size()),
                       static_cast<int>(tables[2].size())};
    f.glBindTexture(GL_TEXTURE_2D, m_gpu->axisTables);
    f.glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    f.glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, static_cast<GLsizei>(width), 3, 0, GL_RED, GL_FLOAT,
                   texels.data());
    f.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    f.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

void Renderer::drawMeshes(const glm::mat4& viewProjection, int width, int height) {
    GlFunctions& f = *m_gpu->f;
    if (m_meshesDirty) {
        m_meshesDirty = false;
        if (m_meshes) {
            m_gpu->meshes.upload(f, *m_meshes);
        } else {
            m_gpu->meshes.release(f);
        }
    }
    const std::vector<GpuMesh>& members = m_gpu->meshes.members();
    if (members.empty() && m_gpu->meshes.mean().vao == 0) return;

    QOpenGLShaderProgram& program = m_gpu->shaders.program(QStringLiteral("surface"));
    program.bind();
    f.glUniformMatrix4fv(program.uniformLocation("u_viewProjection"), 1, GL_FALSE,
                         glm::value_ptr(viewProjection));
    const glm::vec3 eye = m_camera.eye();
    const glm::vec3 viewDirection = glm::normalize(m_camera.target() - eye);
    program.setUniformValue("u_eye", eye.x, eye.y, eye.z);
    program.setUniformValue("u_viewDirection", viewDirection.x, viewDirection.y, viewDirection.z);
    program.setUniformValue("u_orthographic",
                            m_camera.projection() == Camera::Projection::Orthographic);
    program.setUniformValue("u_tau", m_settings.thickness);
    program.setUniformValue("u_surfaceAlpha", m_settings.surfaceAlpha);
    program.setUniformValue("u_removal", m_settings.removal);
    program.setUniformValue("u_removalMin", m_settings.removalMin);
    program.setUniformValue("u_removalMax", m_settings.removalMax);
    program.setUniformValue("u_groupSize", m_settings.groupSize);
    program.setUniformValue("u_axisTables", 1);
    f.glUniform3i(program.uniformLocation("u_axisSize"), m_gpu->axisSize.x, m_gpu->axisSize.y,
                  m_gpu->axisSize.z);
    f.glActiveTexture(GL_TEXTURE1);
    f.glBindTexture(GL_TEXTURE_2D, m_gpu->axisTables);

    const auto appearance = [this](std::size_t m) {
        return m < m_appearance.size() ? m_appearance[m] : MemberAppearance{};
    };
    const auto setMember = [&](std::size_t m, int mode, const glm::vec3& colour) {
        program.setUniformValue("u_mode", mode);
        program.setUniformValue("u_memberIndex", static_cast<int>(m));
        program.setUniformValue("u_color", colour.x, colour.y, colour.z);
    };

    // Opaque: the mean, selected members as solid surfaces, and the spaghetti plot.
    f.glEnable(GL_DEPTH_TEST);
    f.glDepthMask(GL_TRUE);
    f.glDisable(GL_BLEND);
    if (m_settings.showMean) {
        setMember(0, kSolid, kMeanSurfaceColor);
        drawMesh(f, program, m_gpu->meshes.mean());
    }
    const bool translucent =
        m_settings.mode == RenderMode::ShadedSilhouettes || m_settings.mode == RenderMode::Surfaces;
    const int opaqueMode = m_settings.mode == RenderMode::Spaghetti ? kSpaghetti : kSolid;
    for (std::size_t m = 0; m < members.size(); ++m) {
        const MemberAppearance a = appearance(m);
        if (!a.visible) continue;
        if (a.selected || !translucent) {
            setMember(m, a.selected ? kSolid : opaqueMode, a.color);
            drawMesh(f, program, members[m]);
        }
    }

    if (translucent) {
        // Accumulate every unselected visible member, testing but not writing depth.
        f.glBindFramebuffer(GL_FRAMEBUFFER, m_gpu->targets.transparencyFramebuffer());
        f.glViewport(0, 0, width, height);
        const std::array<float, 4> zero{0, 0, 0, 0};
        const std::array<float, 4> one{1, 1, 1, 1};
        f.glClearBufferfv(GL_COLOR, 0, zero.data());
        f.glClearBufferfv(GL_COLOR, 1, one.data());
        f.glDepthMask(GL_FALSE);
        f.glEnable(GL_BLEND);
        f.glBlendFunci(0, GL_ONE, GL_ONE);
        f.glBlendFunci(1, GL_ZERO, GL_ONE_MINUS_SRC_COLOR);
        const int mode = m_settings.mode == RenderMode::Surfaces ? kSurfaces : kShaded;
        for (std::size_t m = 0; m < members.size(); ++m) {
            const MemberAppearance a = appearance(m);
            if (!a.visible || a.selected) continue;
            setMember(m, mode, a.color);
            drawMesh(f, program, members[m]);
        }
        f.glDepthMask(GL_TRUE);

        // Composite over the opaque scene.
        f.glBindFramebuffer(GL_FRAMEBUFFER, m_gpu->targets.sceneFramebuffer());
        f.glDisable(GL_DEPTH_TEST);
        f.glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        QOpenGLShaderProgram& composite = m_gpu->shaders.program(QStringLiteral("composite"));
        composite.bind();
        composite.setUniformValue("u_accumulation", 0);
        composite.setUniformValue("u_revealage", 1);
        f.glActiveTexture(GL_TEXTURE0);
        f.glBindTexture(GL_TEXTURE_2D, m_gpu->targets.accumulation());
        f.glActiveTexture(GL_TEXTURE1);
        f.glBindTexture(GL_TEXTURE_2D, m_gpu->targets.revealage());
        f.glBindVertexArray(m_gpu->emptyVao);
        f.glDrawArrays(GL_TRIANGLES, 0, 3);
        f.glDisable(GL_BLEND);
        f.glEnable(GL_DEPTH_TEST);
        f.glActiveTexture(GL_TEXTURE0);
    }
    f.glBindVertexArray(0);
    program.release();
}

}  // namespace ensil::gl

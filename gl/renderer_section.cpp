// The cutting plane's cut face filled with a field (CuttingPlane::fill, METHODS.md section 18),
// and the 3D fields behind it and behind the context surface's colour by the spread.
// The field lives on the GPU as a 3D texture of its grid values. Each fragment of the face
// finds its grid index through per-axis tables of the inverse of the display mapping, which is
// separable (data::DisplayFrame), and reads the texture trilinearly between grid points: the
// face shows what the value under the cursor (Renderer::sectionValueAt) says.
#include <cmath>
#include <glm/gtc/type_ptr.hpp>
#include <limits>

#include "data/field_sampling.h"
#include "gl/palette.h"
#include "gl/renderer.h"
#include "gl/renderer_gpu.h"

namespace ensil::gl {
namespace {

// Samples of each axis's inverse table across the box: finer than any grid ensil draws, so the
// face's grid index is off by less than a thousandth of the box.
constexpr int kSectionIndexSamples = 1024;

}  // namespace

void Renderer::setSectionVolume(SectionVolume volume) {
    m_scene.section = std::move(volume);
    m_sectionDirty = true;
}

bool Renderer::sectionShown() const {
    const CuttingPlane& plane = m_scene.settings.plane;
    return plane.enabled && plane.fill != SectionField::None && m_scene.hasGrid &&
           m_scene.grid.pointCount() > 0 &&
           m_scene.section.values.size() == m_scene.grid.pointCount();
}

float sectionValueAt(const SectionVolume& volume, const data::Grid& grid,
                     const data::DisplayFrame& frame, const glm::vec3& display) {
    if (volume.values.size() != grid.pointCount()) return std::numeric_limits<float>::quiet_NaN();
    return data::sampleTrilinear(grid, volume.values, frame.displayToIndex(display));
}

float Renderer::sectionValueAt(const glm::vec3& display) const {
    if (!sectionShown()) return std::numeric_limits<float>::quiet_NaN();
    return gl::sectionValueAt(m_scene.section, m_scene.grid, m_scene.frame, display);
}

void Renderer::setSpreadVolume(SectionVolume volume) {
    m_scene.spread = std::move(volume);
    m_spreadDirty = true;
}

bool Renderer::contextColouredBySpread() const {
    return m_scene.settings.contextBySpread && m_scene.hasGrid && m_scene.grid.pointCount() > 0 &&
           m_scene.spread.values.size() == m_scene.grid.pointCount();
}

bool Renderer::uploadFieldVolume(unsigned texture, const SectionVolume& volume) {
    if (!m_scene.hasGrid || m_scene.grid.pointCount() == 0 ||
        volume.values.size() != m_scene.grid.pointCount()) {
        return false;
    }
    GlFunctions& f = *m_gpu->f;
    const float span = volume.maximum - volume.minimum;
    std::vector<float> normalised(volume.values.size());
    for (std::size_t i = 0; i < normalised.size(); ++i) {
        const float v = volume.values[i];
        normalised[i] = std::isnan(v) ? -1.0F : (span > 0.0F ? (v - volume.minimum) / span : 0.5F);
    }
    f.glBindTexture(GL_TEXTURE_3D, texture);
    f.glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    f.glTexImage3D(GL_TEXTURE_3D, 0, GL_R32F, static_cast<GLsizei>(m_scene.grid.nx()),
                   static_cast<GLsizei>(m_scene.grid.ny()), static_cast<GLsizei>(m_scene.grid.nz()),
                   0, GL_RED, GL_FLOAT, normalised.data());
    f.glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    f.glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    for (const GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R}) {
        f.glTexParameteri(GL_TEXTURE_3D, wrap, GL_CLAMP_TO_EDGE);
    }
    f.glBindTexture(GL_TEXTURE_3D, 0);
    return true;
}

void Renderer::uploadSectionVolume() {
    m_sectionDirty = false;
    m_gpu->sectionUploaded = uploadFieldVolume(m_gpu->sectionTexture, m_scene.section);
}

void Renderer::setFieldUniforms(QOpenGLShaderProgram& program, unsigned texture, int volumeUnit,
                                int tablesUnit) {
    GlFunctions& f = *m_gpu->f;
    const glm::vec3 lo = m_scene.frame.boxMin(), hi = m_scene.frame.boxMax();
    program.setUniformValue("u_fieldBoxMin", lo.x, lo.y, lo.z);
    program.setUniformValue("u_fieldBoxMax", hi.x, hi.y, hi.z);
    program.setUniformValue("u_fieldGridSize", static_cast<float>(m_scene.grid.nx()),
                            static_cast<float>(m_scene.grid.ny()),
                            static_cast<float>(m_scene.grid.nz()));
    program.setUniformValue("u_fieldIndexSamples", kSectionIndexSamples);
    program.setUniformValue("u_fieldVolume", volumeUnit);
    program.setUniformValue("u_fieldIndexTables", tablesUnit);
    f.glUniform3fv(program.uniformLocation("u_viridis"),
                   static_cast<GLsizei>(kViridisCoefficients.size()),
                   glm::value_ptr(kViridisCoefficients.front()));
    f.glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(volumeUnit));
    f.glBindTexture(GL_TEXTURE_3D, texture);
    f.glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(tablesUnit));
    f.glBindTexture(GL_TEXTURE_2D, m_gpu->sectionIndexTables);
    f.glActiveTexture(GL_TEXTURE0);
}

void Renderer::uploadSectionIndexTables() {
    // Row a: the grid index along axis a at kSectionIndexSamples display coordinates evenly
    // across the box (the mapping is separable: the other two coordinates do not matter).
    const glm::vec3 lo = m_scene.frame.boxMin(), hi = m_scene.frame.boxMax();
    std::vector<float> texels(static_cast<std::size_t>(kSectionIndexSamples) * 3);
    for (int a = 0; a < 3; ++a) {
        for (int s = 0; s < kSectionIndexSamples; ++s) {
            glm::vec3 p = 0.5F * (lo + hi);
            p[a] = lo[a] + (hi[a] - lo[a]) * static_cast<float>(s) /
                               static_cast<float>(kSectionIndexSamples - 1);
            texels[static_cast<std::size_t>(a * kSectionIndexSamples + s)] =
                static_cast<float>(m_scene.frame.displayToIndex(p)[a]);
        }
    }
    GlFunctions& f = *m_gpu->f;
    f.glBindTexture(GL_TEXTURE_2D, m_gpu->sectionIndexTables);
    f.glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    f.glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, kSectionIndexSamples, 3, 0, GL_RED, GL_FLOAT,
                   texels.data());
    f.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    f.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    f.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    f.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    f.glBindTexture(GL_TEXTURE_2D, 0);
}

void Renderer::drawSection(const glm::mat4& viewProjection) {
    if (!sectionShown() || !m_gpu->sectionUploaded) return;
    // The face lies just behind the plane (kSectionFaceBehind): the members' curves stay in
    // front of it whole, and what lies behind the face is hidden by it, as behind a solid cut.
    CuttingPlane face = planeFacingViewer();
    face.offset -= kSectionFaceBehind * face.thickness;
    const std::vector<glm::vec3> polygon =
        planeBoxPolygon(face, m_scene.frame.boxMin(), m_scene.frame.boxMax());
    if (polygon.empty()) return;
    GlFunctions& f = *m_gpu->f;
    QOpenGLShaderProgram& program = m_gpu->shaders.program(QStringLiteral("section"));
    program.bind();
    f.glUniformMatrix4fv(program.uniformLocation("u_viewProjection"), 1, GL_FALSE,
                         glm::value_ptr(viewProjection));
    setFieldUniforms(program, m_gpu->sectionTexture, 0, 1);
    f.glEnable(GL_DEPTH_TEST);
    f.glDepthFunc(GL_LEQUAL);
    f.glDisable(GL_BLEND);
    f.glBindVertexArray(m_gpu->boxVao);
    f.glBindBuffer(GL_ARRAY_BUFFER, m_gpu->boxVbo);
    f.glBufferSubData(GL_ARRAY_BUFFER, 0,
                      static_cast<GLsizeiptr>(polygon.size() * sizeof(glm::vec3)), polygon.data());
    f.glDrawArrays(GL_TRIANGLE_FAN, 0, static_cast<GLsizei>(polygon.size()));
    f.glBindVertexArray(0);
    f.glActiveTexture(GL_TEXTURE1);
    f.glBindTexture(GL_TEXTURE_2D, 0);
    f.glActiveTexture(GL_TEXTURE0);
    f.glBindTexture(GL_TEXTURE_3D, 0);
    program.release();
}

}  // namespace ensil::gl

// The renderer's map lines: coastlines, borders and graticule on the floor of the box, each a
// light core over a dark casing so it reads over every floor colour and background; and the
// guides that show where the Sections dock's map and cross-section lie, drawn the same way.
#include <glm/gtc/type_ptr.hpp>

#include "gl/renderer.h"
#include "gl/renderer_gpu.h"

namespace ensil::gl {
namespace {

struct LineStyle {
    float casingHalfWidth;  // pixels; 0 for no casing
    glm::vec4 casing;
    float coreHalfWidth;
    glm::vec4 core;
};

// Coastlines strongest, borders lighter and thinner, the graticule a faint hairline.
LineStyle styleOf(geo::MapLineKind kind) {
    switch (kind) {
        case geo::MapLineKind::Coastline:
            return {1.6F, {0.04F, 0.04F, 0.05F, 0.85F}, 0.7F, Renderer::kCoastlineColor};
        case geo::MapLineKind::Border:
            return {1.1F, {0.04F, 0.04F, 0.05F, 0.6F}, 0.4F, {0.8F, 0.8F, 0.8F, 0.9F}};
        case geo::MapLineKind::Graticule:
            return {0.0F, {}, 0.45F, {1.0F, 1.0F, 1.0F, 0.45F}};
    }
    return {};
}

}  // namespace

void Renderer::setMapLines(std::shared_ptr<const std::vector<geo::MapLine>> lines) {
    m_scene.mapLines = std::move(lines);
    m_mapLinesDirty = true;
}

void Renderer::uploadMapLines() {
    m_mapLinesDirty = false;
    m_gpu->mapLineRanges = {};
    if (!m_scene.hasGrid || !m_scene.mapLines) return;
    // GL_LINES segments in display space, on the floor (z = 0), grouped by kind.
    std::vector<glm::vec3> vertices;
    const double floorZ = m_scene.grid.z().front();
    for (int kind = 0; kind < 3; ++kind) {
        const auto first = static_cast<int>(vertices.size());
        for (const geo::MapLine& line : *m_scene.mapLines) {
            if (static_cast<int>(line.kind) != kind) continue;
            for (std::size_t i = 1; i < line.points.size(); ++i) {
                for (const glm::dvec2& p : {line.points[i - 1], line.points[i]}) {
                    glm::vec3 v = m_scene.frame.toDisplay({p.x, p.y, floorZ});
                    v.z = m_scene.frame.boxMin().z;
                    vertices.push_back(v);
                }
            }
        }
        m_gpu->mapLineRanges[static_cast<std::size_t>(kind)] = {
            first, static_cast<int>(vertices.size()) - first};
    }
    GlFunctions& f = *m_gpu->f;
    f.glBindBuffer(GL_ARRAY_BUFFER, m_gpu->mapLinesVbo);
    f.glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(glm::vec3)),
                   vertices.data(), GL_STATIC_DRAW);
}

void Renderer::setSectionGuides(std::vector<std::vector<glm::dvec3>> polylines) {
    m_scene.sectionGuides = std::move(polylines);
    m_guidesBox = glm::vec3(0.0F);  // uploaded with the next frame
}

void Renderer::drawSectionGuides(const glm::mat4& viewProjection) {
    GlFunctions& f = *m_gpu->f;
    const glm::vec3 box = m_scene.frame.boxMax();
    // Uploaded when they change and when the box does (the vertical exaggeration).
    if (box != m_guidesBox) {
        m_guidesBox = box;
        std::vector<glm::vec3> vertices;
        for (const std::vector<glm::dvec3>& line : m_scene.sectionGuides) {
            for (std::size_t i = 1; i < line.size(); ++i) {
                vertices.push_back(glm::vec3(line[i - 1]) * box);
                vertices.push_back(glm::vec3(line[i]) * box);
            }
        }
        f.glBindBuffer(GL_ARRAY_BUFFER, m_gpu->guidesVbo);
        f.glBufferData(GL_ARRAY_BUFFER,
                       static_cast<GLsizeiptr>(vertices.size() * sizeof(glm::vec3)),
                       vertices.data(), GL_STATIC_DRAW);
        m_gpu->guideVertices = static_cast<int>(vertices.size());
    }
    if (m_gpu->guideVertices == 0) return;
    QOpenGLShaderProgram& program = bindScreenLines(viewProjection);
    f.glBindVertexArray(m_gpu->guidesVao);
    f.glEnable(GL_BLEND);
    f.glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    f.glDepthMask(GL_FALSE);
    for (const auto& [halfWidth, colour] : {std::pair{1.8F, glm::vec4(0.04F, 0.04F, 0.05F, 0.8F)},
                                            std::pair{0.8F, kSectionGuideColor}}) {
        program.setUniformValue("u_halfWidth", halfWidth * m_resolutionScale * m_lineScale);
        program.setUniformValue("u_color", colour.r, colour.g, colour.b, colour.a);
        f.glDrawArrays(GL_LINES, 0, m_gpu->guideVertices);
    }
    f.glDepthMask(GL_TRUE);
    f.glDisable(GL_BLEND);
    f.glBindVertexArray(0);
    program.release();
}

QOpenGLShaderProgram& Renderer::bindLinesProgram(const QString& name, const ShaderFiles& files,
                                                 const glm::mat4& viewProjection,
                                                 glm::ivec2 viewport) {
    GlFunctions& f = *m_gpu->f;
    QOpenGLShaderProgram& program = m_gpu->shaders.program(name, files);
    program.bind();
    f.glUniformMatrix4fv(program.uniformLocation("u_viewProjection"), 1, GL_FALSE,
                         glm::value_ptr(viewProjection));
    program.setUniformValue("u_viewport", static_cast<float>(viewport.x),
                            static_cast<float>(viewport.y));
    return program;
}

QOpenGLShaderProgram& Renderer::bindScreenLines(const glm::mat4& viewProjection) {
    return bindLinesProgram(QStringLiteral("map_lines"), kMapLineShaderFiles, viewProjection,
                            m_scene.sceneSize);
}

void Renderer::drawMapLines(const glm::mat4& viewProjection) {
    const RenderSettings& s = m_scene.settings;
    const std::array<bool, 3> shown{s.showCoastlines, s.showBorders, s.showGraticule};
    GlFunctions& f = *m_gpu->f;
    QOpenGLShaderProgram& program = bindScreenLines(viewProjection);
    f.glBindVertexArray(m_gpu->mapLinesVao);
    f.glEnable(GL_BLEND);
    f.glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    // Lines lie on the floor: tested against the surfaces' depth but not written, so a core
    // drawn over its casing at the same depth always shows.
    f.glDepthMask(GL_FALSE);
    const auto pass = [&](const glm::ivec2& range, float halfWidth, const glm::vec4& colour) {
        program.setUniformValue("u_halfWidth", halfWidth * m_resolutionScale * m_lineScale);
        program.setUniformValue("u_color", colour.r, colour.g, colour.b, colour.a);
        f.glDrawArrays(GL_LINES, range.x, range.y);
    };
    // Draw graticule first, coastlines last, so the coast is on top where lines cross.
    for (const geo::MapLineKind kind :
         {geo::MapLineKind::Graticule, geo::MapLineKind::Border, geo::MapLineKind::Coastline}) {
        const auto k = static_cast<std::size_t>(kind);
        const glm::ivec2 range = m_gpu->mapLineRanges[k];
        if (!shown[k] || range.y == 0) continue;
        const LineStyle style = styleOf(kind);
        if (style.casingHalfWidth > 0.0F) pass(range, style.casingHalfWidth, style.casing);
        pass(range, style.coreHalfWidth, style.core);
    }
    f.glDepthMask(GL_TRUE);
    f.glDisable(GL_BLEND);
    f.glBindVertexArray(0);
    program.release();
}

void Renderer::drawBoxBufferLines(unsigned mode, int count, const glm::mat4& viewProjection,
                                  float halfWidth, const glm::vec4& colour) {
    // Through the map lines' program: core profiles draw GL lines one aliased pixel wide.
    GlFunctions& f = *m_gpu->f;
    QOpenGLShaderProgram& program = bindScreenLines(viewProjection);
    program.setUniformValue("u_halfWidth", halfWidth * m_resolutionScale * m_lineScale);
    program.setUniformValue("u_color", colour.r, colour.g, colour.b, colour.a);
    f.glBindVertexArray(m_gpu->boxVao);
    f.glEnable(GL_BLEND);
    f.glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    f.glDepthMask(GL_FALSE);
    f.glDrawArrays(mode, 0, count);
    f.glDepthMask(GL_TRUE);
    f.glDisable(GL_BLEND);
    f.glBindVertexArray(0);
    program.release();
}

}  // namespace ensil::gl

// The isosurface passes of the renderer: opaque (mean, selected members, spaghetti), then the
// translucent members into the order-independent transparency targets, then the composite. The
// picking pass, which draws the same fragments as member ids, is in renderer_picking.cpp.
#include <QOpenGLShaderProgram>
#include <algorithm>
#include <array>
#include <cstdint>
#include <glm/common.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>
#include <glm/vector_relational.hpp>
#include <limits>

#include "gl/palette.h"
#include "gl/renderer_gpu.h"

namespace ensil::gl {
namespace {

enum ShaderMode { kShaded = 0, kSpaghetti = 1, kSurfaces = 2, kSolid = 3 };

// The culling program cuts triangles with gl_ClipDistance 0 to 3 (silhouette_cull.geom); they
// are enabled exactly while it is bound, as a shader that does not write them would be clipped
// by undefined values.
void setClipDistances(GlFunctions& f, bool on) {
    for (const GLenum distance :
         {GL_CLIP_DISTANCE0, GL_CLIP_DISTANCE1, GL_CLIP_DISTANCE2, GL_CLIP_DISTANCE3}) {
        if (on) {
            f.glEnable(distance);
        } else {
            f.glDisable(distance);
        }
    }
}

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
    m_scene.meshes = std::move(meshes);
    m_meshesDirty = true;
    setMotionMeshes(nullptr);
}

void Renderer::setMotionMeshes(std::shared_ptr<const data::MeshSet> meshes) {
    m_scene.motionMeshes = std::move(meshes);
    m_motionMeshesDirty = true;
}

std::size_t Renderer::gpuBytes() const { return m_gpu ? m_gpu->meshes.bytes() : 0; }

void Renderer::uploadAxisTables() {
    m_axisTablesDirty = false;
    GlFunctions& f = *m_gpu->f;
    std::array<std::vector<double>, 3> tables{
        m_scene.frame.axisTable(0), m_scene.frame.axisTable(1), m_scene.frame.axisTable(2)};
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
    uploadSectionIndexTables();  // the inverse of the same mapping
}

void Renderer::uploadMeshesIfChanged() {
    GlFunctions& f = *m_gpu->f;
    const glm::vec3 gridLast(static_cast<float>(m_scene.grid.nx() - 1),
                             static_cast<float>(m_scene.grid.ny() - 1),
                             static_cast<float>(m_scene.grid.nz() - 1));
    const auto upload = [&](bool& dirty, GpuMeshCache& cache, const data::MeshSet* meshes) {
        if (!dirty) return;
        dirty = false;
        if (meshes) {
            cache.upload(f, *meshes, gridLast);
        } else {
            cache.release(f);
        }
    };
    upload(m_meshesDirty, m_gpu->meshes, m_scene.meshes.get());
    upload(m_motionMeshesDirty, m_gpu->motionMeshes, m_scene.motionMeshes.get());
}

Renderer::Selection Renderer::selectionShown() const {
    if (m_animated >= 0) return {true, true};  // the animated member alone, solid
    int selected = 0;
    for (const MemberAppearance& a : m_scene.appearance) {
        if (a.selected && a.visible) ++selected;
    }
    // Opaque surfaces are solid, selected or not.
    const bool opaqueMode = m_scene.settings.mode == RenderMode::OpaqueSurfaces;
    return {selected > 0, opaqueMode || selected <= kMaxSolidSelection};
}

MemberAppearance Renderer::appearance(std::size_t member) const {
    return member < m_scene.appearance.size() ? m_scene.appearance[member] : MemberAppearance{};
}

Renderer::SurfacePrograms Renderer::bindSurfacePrograms(const glm::mat4& viewProjection,
                                                        glm::ivec2 viewport, bool pick, bool cull) {
    SurfacePrograms programs{
        &m_gpu->shaders.program(QStringLiteral("surface")),
        &m_gpu->shaders.program(QStringLiteral("silhouette"), kSilhouetteShaderFiles)};
    if (!cull || !m_scene.settings.silhouetteCulling) programs.culled = programs.full;
    programs.culled->bind();
    configureSurfaceProgram(*programs.culled, viewProjection, viewport, pick);
    if (programs.full != programs.culled) {
        programs.full->bind();
        configureSurfaceProgram(*programs.full, viewProjection, viewport, pick);
    }
    programs.bound = programs.full;
    return programs;
}

void Renderer::configureSurfaceProgram(QOpenGLShaderProgram& program,
                                       const glm::mat4& viewProjection, glm::ivec2 viewport,
                                       bool pick) {
    GlFunctions& f = *m_gpu->f;
    f.glUniformMatrix4fv(program.uniformLocation("u_viewProjection"), 1, GL_FALSE,
                         glm::value_ptr(viewProjection));
    const glm::vec3 eye = m_scene.camera.eye();
    const glm::vec3 viewDirection = glm::normalize(m_scene.camera.target() - eye);
    program.setUniformValue("u_eye", eye.x, eye.y, eye.z);
    program.setUniformValue("u_viewDirection", viewDirection.x, viewDirection.y, viewDirection.z);
    program.setUniformValue("u_orthographic",
                            m_scene.camera.projection() == Camera::Projection::Orthographic);
    program.setUniformValue("u_tau", m_scene.settings.thickness);
    program.setUniformValue("u_surfaceAlpha", m_scene.settings.surfaceAlpha);
    program.setUniformValue("u_removal", m_scene.settings.removal);
    program.setUniformValue("u_removalMin", m_scene.settings.removalMin);
    program.setUniformValue("u_removalMax", m_scene.settings.removalMax);
    program.setUniformValue("u_groupSize", m_scene.settings.groupSize);
    program.setUniformValue("u_pick", pick);
    // The culling shader's antialiasing fringe is in the pass's pixels.
    program.setUniformValue("u_viewportSize", static_cast<float>(viewport.x),
                            static_cast<float>(viewport.y));

    setPlaneUniforms(program);
    program.setUniformValue("u_planeEpsilon", m_scene.settings.plane.thickness);
    setAxisTableUniforms(program);
    // The spread the context surface may be coloured by (units 0 and 1 are taken).
    program.setUniformValue("u_colourByField", false);
    setFieldUniforms(program, m_gpu->spreadTexture, 2, 3);
}

void Renderer::setAxisTableUniforms(QOpenGLShaderProgram& program) {
    GlFunctions& f = *m_gpu->f;
    program.setUniformValue("u_axisTables", 1);
    f.glUniform3i(program.uniformLocation("u_axisSize"), m_gpu->axisSize.x, m_gpu->axisSize.y,
                  m_gpu->axisSize.z);
    f.glActiveTexture(GL_TEXTURE1);
    f.glBindTexture(GL_TEXTURE_2D, m_gpu->axisTables);
    f.glActiveTexture(GL_TEXTURE0);
}

CuttingPlane Renderer::planeFacingViewer() const {
    CuttingPlane plane = m_scene.settings.plane;
    const glm::vec3 eye = m_scene.camera.eye();
    const glm::vec3 viewerPoint =
        m_scene.camera.projection() == Camera::Projection::Orthographic
            ? m_scene.camera.target() - 1e3F * glm::normalize(m_scene.camera.target() - eye)
            : eye;
    if (glm::dot(plane.normal, viewerPoint) < plane.offset) {
        plane.normal = -plane.normal;
        plane.offset = -plane.offset;
    }
    return plane;
}

void Renderer::setPlaneUniforms(QOpenGLShaderProgram& program) const {
    // The plane's normal is turned towards the viewer, so the shaders discard n.p > offset.
    const CuttingPlane plane = planeFacingViewer();
    program.setUniformValue("u_planeEnabled", plane.enabled);
    program.setUniformValue("u_plane", plane.normal.x, plane.normal.y, plane.normal.z,
                            plane.offset);
}

glm::vec3 Renderer::memberColour(std::size_t member, const MemberAppearance& a,
                                 const Selection& selection) const {
    glm::vec3 colour = a.color;
    // With a selection, the others step back: their colour goes most of the way to the
    // background.
    if (selection.any && !a.selected) colour = steppedBack(colour, glm::vec3(m_background));
    // While the band is shown it and the outliers (dashed) are what the picture says; the
    // other members step back too, unless selected.
    if (m_scene.settings.showBand && !a.selected && !isOutlier(member)) {
        colour = steppedBack(colour, glm::vec3(m_background));
    }
    if (static_cast<int>(member) == m_highlighted)
        colour = glm::mix(colour, glm::vec3(1.0F), 0.55F);
    return colour;
}

bool Renderer::isOutlier(std::size_t member) const {
    if (!m_scene.meshes) return false;
    const std::vector<int>& outliers = m_scene.meshes->outliers;
    return std::find(outliers.begin(), outliers.end(), static_cast<int>(member)) != outliers.end();
}

void Renderer::drawRims(const glm::mat4& viewProjection, glm::ivec2 viewport, bool pick) {
    if (!m_scene.settings.showRims) return;
    GlFunctions& f = *m_gpu->f;
    QOpenGLShaderProgram& program = bindLinesProgram(QStringLiteral("rim_lines"),
                                                     kRimLineShaderFiles, viewProjection, viewport);
    setPlaneUniforms(program);
    setAxisTableUniforms(program);
    f.glEnable(GL_DEPTH_TEST);
    if (!pick) {
        f.glEnable(GL_BLEND);
        f.glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    }
    // Tested against the solid surfaces; not written, since a rim lies on its own surface's
    // edge, except by picking, whose depth gives the place under the cursor.
    f.glDepthMask(pick ? GL_TRUE : GL_FALSE);
    const float pixels = pick ? 1.0F : m_resolutionScale * m_lineScale;
    const auto draw = [&](const GpuMesh& mesh, const glm::vec3& colour, float halfWidth) {
        if (mesh.rimVao == 0) return;
        program.setUniformValue("u_boundsMin", mesh.boundsMin.x, mesh.boundsMin.y,
                                mesh.boundsMin.z);
        program.setUniformValue("u_boundsMax", mesh.boundsMax.x, mesh.boundsMax.y,
                                mesh.boundsMax.z);
        program.setUniformValue("u_halfWidth", halfWidth * pixels);
        program.setUniformValue("u_color", colour.r, colour.g, colour.b, 1.0F);
        f.glBindVertexArray(mesh.rimVao);
        f.glDrawElements(GL_LINES, mesh.rimIndexCount, GL_UNSIGNED_INT, nullptr);
    };
    // The id pass writes member + 1 as the colour, as surface.frag does.
    const auto pickColour = [](std::size_t member) {
        const auto id = static_cast<unsigned>(member + 1);
        return glm::vec3((id >> 16) & 255U, (id >> 8) & 255U, id & 255U) / 255.0F;
    };
    if (m_scene.settings.showMean && m_animated < 0 && !pick) {
        draw(contextMesh(), kMeanSurfaceColor, kRimHalfWidth);
    }
    const Selection selection = selectionShown();
    const std::vector<GpuMesh>& members = drawnMeshes().members();
    for (std::size_t m = 0; m < members.size(); ++m) {
        MemberAppearance a = appearance(m);
        const bool animated = static_cast<int>(m) == m_animated;
        if (m_animated >= 0) a.selected = animated;
        if ((!a.visible && !animated) || (m_animated >= 0 && !animated)) continue;
        draw(members[m], pick ? pickColour(m) : memberColour(m, a, selection),
             a.selected ? kSelectedRimHalfWidth : kRimHalfWidth);
    }
    f.glDepthMask(GL_TRUE);
    f.glDisable(GL_BLEND);
    f.glBindVertexArray(0);
    program.release();
}

glm::ivec4 Renderer::screenRectangle(const glm::mat4& viewProjection, int width, int height) const {
    const glm::vec3 lo = m_scene.frame.boxMin(), hi = m_scene.frame.boxMax();
    glm::vec2 minimum(std::numeric_limits<float>::max()), maximum(-minimum);
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec4 p =
            viewProjection * glm::vec4((corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y,
                                       (corner & 4) ? hi.z : lo.z, 1.0F);
        if (p.w <= 1e-6F) return {0, 0, width, height};  // the camera is inside the box
        const glm::vec2 pixel = (glm::vec2(p) / p.w * 0.5F + 0.5F) * glm::vec2(width, height);
        minimum = glm::min(minimum, pixel);
        maximum = glm::max(maximum, pixel);
    }
    // A pixel of margin for rounding; clamped to the frame.
    const glm::ivec2 lower =
        glm::clamp(glm::ivec2(glm::floor(minimum)) - 1, glm::ivec2(0), glm::ivec2(width, height));
    const glm::ivec2 upper =
        glm::clamp(glm::ivec2(glm::ceil(maximum)) + 1, glm::ivec2(0), glm::ivec2(width, height));
    return {lower.x, lower.y, upper.x - lower.x, upper.y - lower.y};
}

bool Renderer::translucentMode() const {
    return m_scene.settings.mode == RenderMode::ShadedSilhouettes ||
           m_scene.settings.mode == RenderMode::Surfaces;
}

void Renderer::drawMemberPass(SurfacePrograms& programs, MemberPass pass) {
    GlFunctions& f = *m_gpu->f;
    const std::vector<GpuMesh>& members = drawnMeshes().members();
    QOpenGLShaderProgram* program = programs.bound;
    // The silhouette modes draw through the culling geometry shader; solid and semi-transparent
    // surfaces need every triangle.
    const auto setMember = [&](int pickId, std::size_t m, int mode, const glm::vec3& colour,
                               bool emphasis = false) {
        QOpenGLShaderProgram* wanted =
            mode == kShaded || mode == kSpaghetti ? programs.culled : programs.full;
        if (wanted != program) {
            program = wanted;
            program->bind();
            programs.bound = program;
            setClipDistances(f, programs.clips());
        }
        program->setUniformValue("u_mode", mode);
        program->setUniformValue("u_memberIndex", static_cast<int>(m));
        program->setUniformValue("u_pickId", pickId);
        program->setUniformValue("u_color", colour.x, colour.y, colour.z);
        program->setUniformValue("u_emphasis", emphasis);
    };
    const bool translucent = translucentMode();
    const int translucentShaderMode =
        m_scene.settings.mode == RenderMode::Surfaces ? kSurfaces : kShaded;
    const int opaqueMode = m_scene.settings.mode == RenderMode::Spaghetti ? kSpaghetti : kSolid;
    const Selection selection = selectionShown();
    // A translucent mean is context: composited with the translucent members, and neither
    // hiding members from picking nor picked itself; a solid one is drawn with the opaque.
    const bool meanTranslucent = m_scene.settings.meanTranslucent();
    const bool meanHere =
        m_scene.settings.showMean &&
        (pass == MemberPass::All ? !meanTranslucent
                                 : (pass == MemberPass::Translucent) == meanTranslucent);
    if (meanHere) {
        // Pushed back a little in depth: where a member coincides with the mean (the animated
        // member, a solid selection), the member is seen, never a z-fighting mix of both.
        f.glEnable(GL_POLYGON_OFFSET_FILL);
        f.glPolygonOffset(1.0F, 2.0F);
        setMember(0, 0, meanTranslucent ? kSurfaces : kSolid, kMeanSurfaceColor);
        program->setUniformValue("u_surfaceAlpha", m_scene.settings.meanOpacity);
        program->setUniformValue("u_colourByField",
                                 contextColouredBySpread() && m_gpu->spreadUploaded);
        drawMesh(f, *program, contextMesh());
        program->setUniformValue("u_colourByField", false);
        program->setUniformValue("u_surfaceAlpha", m_scene.settings.surfaceAlpha);
        f.glDisable(GL_POLYGON_OFFSET_FILL);
    }
    // The 50 % band: a faint envelope (the union of the band members' insides) around a
    // stronger core (their intersection), both translucent and never picked.
    if (m_scene.settings.showBand && pass == MemberPass::Translucent) {
        setMember(0, 0, kSurfaces, kBandColor);
        for (const auto& [mesh, alpha] : {std::pair{&m_gpu->meshes.bandOuter(), kBandOuterAlpha},
                                          std::pair{&m_gpu->meshes.bandInner(), kBandInnerAlpha}}) {
            program->setUniformValue("u_surfaceAlpha", alpha);
            drawMesh(f, *program, *mesh);
        }
        program->setUniformValue("u_surfaceAlpha", m_scene.settings.surfaceAlpha);
    }
    for (std::size_t m = 0; m < members.size(); ++m) {
        MemberAppearance a = appearance(m);
        const bool animated = static_cast<int>(m) == m_animated;
        if (m_animated >= 0) a.selected = animated;
        if (!a.visible && !animated) continue;
        // A few selected members are solid surfaces, as in the paper; many are semi-transparent
        // surfaces, so a brushed crowd never becomes a wall.
        const bool solid = a.selected && selection.solid;
        const bool opaque = solid || (!translucent && !a.selected);
        if ((pass == MemberPass::Opaque && !opaque) ||
            (pass == MemberPass::Translucent && opaque)) {
            continue;
        }
        const int mode = solid        ? kSolid
                         : a.selected ? kSurfaces
                         : opaque     ? opaqueMode
                                      : translucentShaderMode;
        const glm::vec3 colour = memberColour(m, a, selection);
        // Selected members drawn as surfaces keep a thicker, opaque silhouette rim.
        setMember(static_cast<int>(m) + 1, m, mode, colour, mode == kSurfaces && a.selected);
        program->setUniformValue("u_dashed", m_scene.settings.showBand && isOutlier(m));
        drawMesh(f, *program, members[m]);
    }
    program->setUniformValue("u_dashed", false);
    setClipDistances(f, false);
}

const GpuMeshCache& Renderer::drawnMeshes() const { return *m_gpu->drawn; }

const GpuMesh& Renderer::contextMesh() const {
    const GpuMeshCache& meshes = drawnMeshes();
    switch (m_scene.settings.context) {
        case ContextSurface::Median: {
            const int median = m_scene.meshes ? m_scene.meshes->median : -1;
            if (median >= 0 && static_cast<std::size_t>(median) < meshes.members().size()) {
                return meshes.members()[static_cast<std::size_t>(median)];
            }
            break;
        }
        case ContextSurface::Probability:
            // The summaries have no reduced detail: the full meshes' always.
            if (m_gpu->meshes.probability().vao != 0) return m_gpu->meshes.probability();
            break;
        case ContextSurface::Mean:
            break;
    }
    return meshes.mean();
}

void Renderer::drawMeshes(const glm::mat4& viewProjection, int width, int height) {
    GlFunctions& f = *m_gpu->f;
    uploadMeshesIfChanged();
    const bool reduced = m_resolutionScale < 1.0F && m_scene.motionMeshes &&
                         m_gpu->motionMeshes.members().size() == m_gpu->meshes.members().size();
    m_gpu->drawn = reduced ? &m_gpu->motionMeshes : &m_gpu->meshes;
    if (m_gpu->meshes.members().empty() && m_gpu->meshes.mean().vao == 0) return;

    SurfacePrograms programs = bindSurfacePrograms(viewProjection, {width, height}, false, true);
    f.glEnable(GL_DEPTH_TEST);
    f.glDepthMask(GL_TRUE);
    f.glDisable(GL_BLEND);
    // Opaque silhouettes (spaghetti) are antialiased by writing their pixel coverage to that
    // share of the samples.
    f.glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    drawMemberPass(programs, MemberPass::Opaque);
    f.glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);

    const Selection selection = selectionShown();
    const bool translucentMean =
        m_scene.settings.showMean && m_scene.settings.meanTranslucent() && contextMesh().vao != 0;
    const bool band = m_scene.settings.showBand && m_gpu->meshes.bandOuter().vao != 0;
    if (translucentMode() || (selection.any && !selection.solid) || translucentMean || band) {
        // Every isosurface lies inside the data box: the transparency targets are drawn and
        // composited only over the box's rectangle on screen.
        const glm::ivec4 box = screenRectangle(viewProjection, width, height);
        // Accumulate every unselected visible member, testing but not writing depth.
        f.glBindFramebuffer(GL_FRAMEBUFFER, m_gpu->targets.transparencyFramebuffer());
        f.glViewport(0, 0, width, height);
        const std::array<float, 4> zero{0, 0, 0, 0};
        const std::array<float, 4> one{1, 1, 1, 1};
        // Cleared whole: with a scissor, llvmpipe left the multisampled targets' samples on
        // the rectangle's border uncleared, which the composite drew as a dark outline.
        f.glClearBufferfv(GL_COLOR, 0, zero.data());
        f.glClearBufferfv(GL_COLOR, 1, one.data());
        f.glEnable(GL_SCISSOR_TEST);
        f.glScissor(box.x, box.y, box.z, box.w);
        f.glDepthMask(GL_FALSE);
        f.glEnable(GL_BLEND);
        f.glBlendFunci(0, GL_ONE, GL_ONE);
        f.glBlendFunci(1, GL_ZERO, GL_ONE_MINUS_SRC_COLOR);
        programs.bound->bind();
        drawMemberPass(programs, MemberPass::Translucent);
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
        f.glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, m_gpu->targets.accumulation());
        f.glActiveTexture(GL_TEXTURE1);
        f.glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, m_gpu->targets.revealage());
        f.glBindVertexArray(m_gpu->emptyVao);
        f.glDrawArrays(GL_TRIANGLES, 0, 3);
        f.glDisable(GL_BLEND);
        f.glDisable(GL_SCISSOR_TEST);
        f.glEnable(GL_DEPTH_TEST);
        f.glActiveTexture(GL_TEXTURE0);
    }
    f.glBindVertexArray(0);
    programs.bound->release();
    drawRims(viewProjection, {width, height}, false);
}

}  // namespace ensil::gl

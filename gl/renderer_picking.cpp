// Picking: the member passes drawn again as member ids into a picking target, for the window
// under the cursor only, and read back; what lies under a point (a member, the cut face, the
// floor) and which members lie inside a rubber band. Part of Renderer.
#include <algorithm>
#include <cstdint>
#include <glm/common.hpp>
#include <glm/matrix.hpp>
#include <limits>
#include <vector>

#include "gl/renderer_gpu.h"

namespace ensil::gl {

std::vector<std::uint32_t> Renderer::drawIds(int x0, int y0, int w, int h) {
    GlFunctions& f = *m_gpu->f;
    const int width = m_scene.lastSize.x, height = m_scene.lastSize.y;
    uploadMeshesIfChanged();
    m_gpu->drawn = &m_gpu->meshes;  // picks answer for the full surfaces
    if (m_axisTablesDirty) uploadAxisTables();
    m_gpu->targets.ensurePick(f, width, height);
    // Only the window asked for is drawn: picking on hover stays cheap.
    f.glBindFramebuffer(GL_FRAMEBUFFER, m_gpu->targets.pickFramebuffer());
    f.glViewport(0, 0, width, height);
    f.glEnable(GL_SCISSOR_TEST);
    f.glScissor(x0, y0, w, h);
    f.glClearColor(0, 0, 0, 0);
    f.glClearDepth(1.0);
    f.glDepthMask(GL_TRUE);
    f.glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    f.glEnable(GL_DEPTH_TEST);
    f.glDepthFunc(GL_LEQUAL);
    f.glDisable(GL_BLEND);
    f.glDisable(GL_DITHER);
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    // The culling shader's work per triangle pays off over many pixels (a brush), not over the
    // few of a pick under the cursor, where it would double the time.
    const bool cull = static_cast<long long>(w) * h * 16 > static_cast<long long>(width) * height;
    SurfacePrograms programs =
        bindSurfacePrograms(m_scene.camera.viewProjection(aspect), {width, height}, true, cull);
    drawMemberPass(programs, MemberPass::All);
    f.glBindVertexArray(0);
    programs.bound->release();
    drawRims(m_scene.camera.viewProjection(aspect), {width, height}, true);

    std::vector<std::uint8_t> pixels(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 4);
    f.glPixelStorei(GL_PACK_ALIGNMENT, 1);
    f.glReadPixels(x0, y0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    f.glDisable(GL_SCISSOR_TEST);
    f.glEnable(GL_DITHER);
    f.glBindFramebuffer(GL_FRAMEBUFFER, 0);
    std::vector<std::uint32_t> ids(pixels.size() / 4);
    for (std::size_t i = 0; i < ids.size(); ++i) {
        ids[i] = (std::uint32_t{pixels[4 * i]} << 16) | (std::uint32_t{pixels[4 * i + 1]} << 8) |
                 std::uint32_t{pixels[4 * i + 2]};
    }
    return ids;
}

bool Renderer::canPick() const {
    return m_gpu && m_scene.hasGrid && m_scene.lastSize.x > 0 && m_scene.lastSize.y > 0;
}

PickResult Renderer::pick(int x, int y, int radius) {
    PickResult result;
    if (!canPick()) return result;
    const int width = m_scene.lastSize.x, height = m_scene.lastSize.y;
    if (x < 0 || y < 0 || x >= width || y >= height) return result;
    radius = std::max(radius, 0);
    const int glY = height - 1 - y;  // GL rows run bottom-up
    const int x0 = std::max(x - radius, 0), y0 = std::max(glY - radius, 0);
    const int w = std::min(x + radius, width - 1) - x0 + 1;
    const int h = std::min(glY + radius, height - 1) - y0 + 1;
    const std::vector<std::uint32_t> ids = drawIds(x0, y0, w, h);

    // The id nearest to the pixel wins; thin silhouettes need not be hit exactly.
    int bestDistance = std::numeric_limits<int>::max();
    glm::ivec2 bestPixel{x, glY};
    for (int row = 0; row < h; ++row) {
        for (int col = 0; col < w; ++col) {
            const std::uint32_t id =
                ids[static_cast<std::size_t>(row) * static_cast<std::size_t>(w) +
                    static_cast<std::size_t>(col)];
            if (id == 0) continue;
            const int dx = x0 + col - x, dy = y0 + row - glY;
            const int distance = dx * dx + dy * dy;
            if (distance < bestDistance) {
                bestDistance = distance;
                result.member = static_cast<int>(id) - 1;
                bestPixel = {x0 + col, y0 + row};
            }
        }
    }
    const glm::vec2 size{static_cast<float>(width), static_cast<float>(height)};
    const glm::mat4 inverse = glm::inverse(m_scene.camera.viewProjection(size.x / size.y));
    const auto unproject = [&](glm::ivec2 pixel, float depth) {
        const glm::vec2 centre = (glm::vec2(pixel) + 0.5F) / size * 2.0F - 1.0F;
        const glm::vec4 ndc{centre, depth * 2.0F - 1.0F, 1.0F};
        const glm::vec4 p = inverse * ndc;
        return glm::vec3(p) / p.w;
    };
    GlFunctions& f = *m_gpu->f;
    if (result.member >= 0) {
        result.cluster = appearance(static_cast<std::size_t>(result.member)).cluster;
        // The id pass wrote the surface's depth there: back through the camera to display space.
        float depth = 1.0F;
        f.glBindFramebuffer(GL_FRAMEBUFFER, m_gpu->targets.pickFramebuffer());
        f.glReadPixels(bestPixel.x, bestPixel.y, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &depth);
        f.glBindFramebuffer(GL_FRAMEBUFFER, 0);
        if (depth < 1.0F) result.surface = unproject(bestPixel, depth);
    }
    // The floor: the ray through the pixel, from the near to the far plane, at z = 0.
    const glm::vec3 nearPoint = unproject({x, glY}, 0.0F);
    const glm::vec3 farPoint = unproject({x, glY}, 1.0F);
    if (std::abs(farPoint.z - nearPoint.z) > 1e-9F) {
        const float t = (m_scene.frame.boxMin().z - nearPoint.z) / (farPoint.z - nearPoint.z);
        const glm::vec3 onFloor = nearPoint + t * (farPoint - nearPoint);
        const glm::vec3 lo = m_scene.frame.boxMin(), hi = m_scene.frame.boxMax();
        if (t >= 0.0F && t <= 1.0F && onFloor.x >= lo.x && onFloor.x <= hi.x && onFloor.y >= lo.y &&
            onFloor.y <= hi.y) {
            result.floor = onFloor;
        }
    }
    if (sectionShown()) {
        // The filled cut face: where the ray meets the plane inside the box. A surface behind
        // the face (by more than the curves' width) is hidden by it, so not picked.
        const CuttingPlane plane = planeFacingViewer();
        const float along = glm::dot(plane.normal, farPoint - nearPoint);
        if (std::abs(along) > 1e-9F) {
            const float t = (plane.offset - glm::dot(plane.normal, nearPoint)) / along;
            const glm::vec3 onPlane = nearPoint + t * (farPoint - nearPoint);
            const glm::vec3 lo = m_scene.frame.boxMin(), hi = m_scene.frame.boxMax();
            const glm::vec3 slack(1e-5F);
            if (t >= 0.0F && t <= 1.0F && glm::all(glm::greaterThanEqual(onPlane, lo - slack)) &&
                glm::all(glm::lessThanEqual(onPlane, hi + slack))) {
                result.section = onPlane;
                if (result.surface && glm::dot(plane.normal, *result.surface) <
                                          plane.offset - kSectionFaceBehind * plane.thickness) {
                    result.member = -1;
                    result.cluster = -1;
                    result.surface.reset();
                }
            }
        }
    }
    return result;
}

std::vector<int> Renderer::membersIn(int x0, int y0, int x1, int y1) {
    if (!canPick()) return {};
    const int width = m_scene.lastSize.x, height = m_scene.lastSize.y;
    const int left = std::clamp(std::min(x0, x1), 0, width - 1);
    const int right = std::clamp(std::max(x0, x1), 0, width - 1);
    const int top = std::clamp(std::min(y0, y1), 0, height - 1);
    const int bottom = std::clamp(std::max(y0, y1), 0, height - 1);
    const std::vector<std::uint32_t> ids =
        drawIds(left, height - 1 - bottom, right - left + 1, bottom - top + 1);
    std::vector<int> members;
    for (const std::uint32_t id : ids) {
        if (id != 0) members.push_back(static_cast<int>(id) - 1);
    }
    std::sort(members.begin(), members.end());
    members.erase(std::unique(members.begin(), members.end()), members.end());
    return members;
}

}  // namespace ensil::gl

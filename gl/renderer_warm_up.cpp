// Warming up the renderer: llvmpipe (and other drivers) compile a shader's machine code for each
// combination of pipeline state at its first draw, a few hundred milliseconds each time on a
// CPU. Drawing a tiny scene in every mode once, right after initialisation, moves that work to
// start-up, so the first frame of real surfaces (which arrives while the user works) does not
// stall the GUI thread.
#include <QOpenGLFramebufferObject>

#include "gl/renderer.h"
#include "gl/renderer_gpu.h"

namespace ensil::gl {
namespace {
// One triangle as a member mesh: enough to go through every pass.
data::PackedMesh triangle() {
    data::PackedMesh mesh;
    mesh.boundsMin = glm::vec3(0.0F);
    mesh.boundsMax = glm::vec3(1.0F);
    const std::uint16_t one = 65535;
    for (const auto& p :
         {std::array<std::uint16_t, 3>{0, 0, 0}, std::array<std::uint16_t, 3>{one, 0, 0},
          std::array<std::uint16_t, 3>{0, one, one}}) {
        data::PackedVertex v{};
        v.position[0] = p[0];
        v.position[1] = p[1];
        v.position[2] = p[2];
        v.normal[1] = 32767;
        v.direction[0] = 32767;
        mesh.vertices.push_back(v);
    }
    mesh.indices = {0, 1, 2};
    return mesh;
}
}  // namespace

void Renderer::warmUp() {
    if (!m_gpu) return;
    Scene saved = m_scene;  // put back afterwards

    setGrid(data::Grid(data::makeUniformAxis("x", "", 0, 1, 2),
                       data::makeUniformAxis("y", "", 0, 1, 2),
                       data::makeUniformAxis("z", "", 0, 1, 2)));
    setFloorMap(FloorMap::spanning({0.0F, 1.0F, 2.0F, 3.0F}));
    setSectionVolume({std::vector<float>(8, 0.5F), 0.0F, 1.0F, {}, {}});
    setSpreadVolume({std::vector<float>(8, 0.5F), 0.0F, 1.0F, {}, {}});
    setMapLines(std::make_shared<const std::vector<geo::MapLine>>(
        std::vector<geo::MapLine>{{geo::MapLineKind::Coastline, {{0.1, 0.1}, {0.9, 0.9}}, {}}}));
    auto set = std::make_shared<data::MeshSet>();
    set->members = {triangle(), triangle()};
    set->mean = triangle();
    setMeshes(set);
    m_scene.appearance = {{glm::vec3(1.0F), true, true, 0}, {glm::vec3(0.5F), true, false, 1}};
    {
        QOpenGLFramebufferObject target(8, 8, QOpenGLFramebufferObject::CombinedDepthStencil);
        for (const RenderMode mode : {RenderMode::ShadedSilhouettes, RenderMode::Spaghetti,
                                      RenderMode::Surfaces, RenderMode::OpaqueSurfaces}) {
            m_scene.settings.mode = mode;
            m_scene.settings.removal = mode == RenderMode::ShadedSilhouettes;
            m_scene.settings.plane.enabled = mode == RenderMode::Spaghetti;
            m_scene.settings.plane.fill = SectionField::Mean;
            m_scene.settings.contextBySpread = mode == RenderMode::Surfaces;
            render(target.handle(), 8, 8);
            (void)pick(4, 4);
        }
    }

    m_scene = std::move(saved);
    m_floorDirty = true;
    m_sectionDirty = true;
    m_spreadDirty = true;
    m_mapLinesDirty = true;
    m_axisTablesDirty = true;
    m_meshesDirty = true;
    m_motionMeshesDirty = true;
}

}  // namespace ensil::gl

// The renderer's GPU state, shared by its source files (renderer.cpp draws the frame, the box
// and the floor; renderer_meshes.cpp draws the isosurfaces). Internal to gl/.
#pragma once

#include <array>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "gl/gl_functions.h"
#include "gl/gpu_mesh_cache.h"
#include "gl/render_targets.h"
#include "gl/renderer.h"
#include "gl/shader_library.h"

namespace ensil::gl {

// The isosurface program of the silhouette modes: the surface shaders with the geometry shader
// that drops triangles far from any silhouette or plane curve.
inline const ShaderFiles kSilhouetteShaderFiles{
    QStringLiteral("surface"), QStringLiteral("silhouette_cull"), QStringLiteral("surface")};

// The map lines' program: segments widened on screen by a geometry shader.
inline const ShaderFiles kMapLineShaderFiles{
    QStringLiteral("map_lines"), QStringLiteral("map_lines"), QStringLiteral("map_lines")};

// The rims of the isosurfaces: packed vertices, widened and cut like the map lines.
inline const ShaderFiles kRimLineShaderFiles{
    QStringLiteral("rim_lines"), QStringLiteral("map_lines"), QStringLiteral("map_lines")};

struct Renderer::Gpu {
    GlFunctions* f = nullptr;
    ShaderLibrary shaders;
    GLuint boxVao = 0, boxVbo = 0;
    GLuint quadVao = 0, quadVbo = 0;
    GLuint emptyVao = 0;  // for the full-screen passes, which need no vertex data
    GLuint floorTexture = 0;
    GLuint mapLinesVao = 0, mapLinesVbo = 0;
    GLuint guidesVao = 0, guidesVbo = 0;
    int guideVertices = 0;  // GL_LINES vertices of the section guides
    // The segments of each geo::MapLineKind, in order: first vertex and vertex count.
    std::array<glm::ivec2, 3> mapLineRanges{};
    glm::ivec2 floorSize{0};
    // The section volume, normalised to [0, 1] (negative: missing), and per axis the grid
    // index at evenly spaced display coordinates (kSectionIndexSamples across the box).
    GLuint sectionTexture = 0;
    GLuint sectionIndexTables = 0;
    bool sectionUploaded = false;
    // The members' standard deviation, for the context surface's colour (same tables).
    GLuint spreadTexture = 0;
    bool spreadUploaded = false;
    GLuint axisTables = 0;  // row a: the display coordinate of every grid index along axis a
    glm::ivec3 axisSize{0};
    GpuMeshCache meshes;
    // The same surfaces in reduced detail (Renderer::setMotionMeshes), and which of the two the
    // frame being drawn takes its members and mean from.
    GpuMeshCache motionMeshes;
    const GpuMeshCache* drawn = &meshes;
    RenderTargets targets;
};

}  // namespace ensil::gl

#include "gl/renderer.h"

#include <QOpenGLContext>
#include <QOpenGLVersionFunctionsFactory>
#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <limits>
#include <stdexcept>

#include "gl/gl_functions.h"
#include "gl/palette.h"
#include "gl/renderer_gpu.h"
#include "gl/shader_library.h"

namespace ensil::gl {

FloorMap FloorMap::spanning(std::vector<float> values, QString caption) {
    FloorMap map;
    map.caption = std::move(caption);
    float lo = std::numeric_limits<float>::infinity(), hi = -lo;
    for (const float v : values) {
        if (!std::isnan(v)) {
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
    }
    map.values = std::move(values);
    if (lo <= hi) {
        map.minimum = lo;
        map.maximum = hi;
    }
    return map;
}

Renderer::Renderer() = default;
Renderer::~Renderer() = default;  // GPU objects are released by releaseGpuResources().

bool Renderer::isInitialized() const { return m_gpu != nullptr; }

void Renderer::initialize() {
    if (m_gpu) return;
    QOpenGLContext* context = QOpenGLContext::currentContext();
    if (context == nullptr) throw std::runtime_error("no current OpenGL context");
    const QSurfaceFormat format = context->format();
    if (format.version() < qMakePair(4, 1) || format.profile() != QSurfaceFormat::CoreProfile) {
        throw std::runtime_error("ensil needs OpenGL 4.1 core profile; this context is " +
                                 std::to_string(format.majorVersion()) + "." +
                                 std::to_string(format.minorVersion()));
    }
    auto gpu = std::make_unique<Gpu>();
    gpu->f = QOpenGLVersionFunctionsFactory::get<GlFunctions>(context);
    if (gpu->f == nullptr) throw std::runtime_error("cannot resolve OpenGL 4.1 core functions");
    GlFunctions& f = *gpu->f;
    // Compile now so a broken shader is reported at start-up, not at the first frame.
    gpu->shaders.program(QStringLiteral("lines"));
    gpu->shaders.program(QStringLiteral("floor_map"));
    gpu->shaders.program(QStringLiteral("section"));
    gpu->shaders.program(QStringLiteral("map_lines"), kMapLineShaderFiles);
    gpu->shaders.program(QStringLiteral("surface"));
    gpu->shaders.program(QStringLiteral("composite"));
    gpu->shaders.program(QStringLiteral("present"), {QStringLiteral("composite"), {}, {}});
    gpu->shaders.program(QStringLiteral("silhouette"), kSilhouetteShaderFiles);

    f.glGenVertexArrays(1, &gpu->boxVao);
    f.glGenBuffers(1, &gpu->boxVbo);
    f.glBindVertexArray(gpu->boxVao);
    f.glBindBuffer(GL_ARRAY_BUFFER, gpu->boxVbo);
    // 12 edges of the unit cube; scaled to the box in the vertex data at draw time.
    f.glBufferData(GL_ARRAY_BUFFER, 24 * sizeof(glm::vec3), nullptr, GL_DYNAMIC_DRAW);
    f.glEnableVertexAttribArray(0);
    f.glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);

    const std::array<float, 8> corners{0, 0, 1, 0, 0, 1, 1, 1};
    f.glGenVertexArrays(1, &gpu->quadVao);
    f.glGenBuffers(1, &gpu->quadVbo);
    f.glBindVertexArray(gpu->quadVao);
    f.glBindBuffer(GL_ARRAY_BUFFER, gpu->quadVbo);
    f.glBufferData(GL_ARRAY_BUFFER, sizeof(corners), corners.data(), GL_STATIC_DRAW);
    f.glEnableVertexAttribArray(0);
    f.glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), nullptr);
    f.glBindVertexArray(0);

    // Lines in display space, their vertices uploaded when they change.
    for (auto [vao, vbo] : {std::pair{&gpu->mapLinesVao, &gpu->mapLinesVbo},
                            std::pair{&gpu->guidesVao, &gpu->guidesVbo}}) {
        f.glGenVertexArrays(1, vao);
        f.glGenBuffers(1, vbo);
        f.glBindVertexArray(*vao);
        f.glBindBuffer(GL_ARRAY_BUFFER, *vbo);
        f.glEnableVertexAttribArray(0);
        f.glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
        f.glBindVertexArray(0);
    }

    f.glGenTextures(1, &gpu->floorTexture);
    f.glGenTextures(1, &gpu->axisTables);
    f.glGenTextures(1, &gpu->sectionTexture);
    f.glGenTextures(1, &gpu->sectionIndexTables);
    f.glGenTextures(1, &gpu->spreadTexture);
    f.glGenVertexArrays(1, &gpu->emptyVao);
    m_gpu = std::move(gpu);
    m_floorDirty = true;
    m_sectionDirty = true;
    m_spreadDirty = true;
    m_mapLinesDirty = true;
    m_guidesBox = glm::vec3(0.0F);
    m_axisTablesDirty = true;
    m_meshesDirty = true;
    m_motionMeshesDirty = true;
}

void Renderer::releaseGpuResources() {
    if (!m_gpu) return;
    GlFunctions& f = *m_gpu->f;
    f.glDeleteVertexArrays(1, &m_gpu->boxVao);
    f.glDeleteBuffers(1, &m_gpu->boxVbo);
    f.glDeleteVertexArrays(1, &m_gpu->quadVao);
    f.glDeleteBuffers(1, &m_gpu->quadVbo);
    f.glDeleteVertexArrays(1, &m_gpu->mapLinesVao);
    f.glDeleteBuffers(1, &m_gpu->mapLinesVbo);
    f.glDeleteVertexArrays(1, &m_gpu->guidesVao);
    f.glDeleteBuffers(1, &m_gpu->guidesVbo);
    f.glDeleteTextures(1, &m_gpu->floorTexture);
    f.glDeleteTextures(1, &m_gpu->axisTables);
    f.glDeleteTextures(1, &m_gpu->sectionTexture);
    f.glDeleteTextures(1, &m_gpu->sectionIndexTables);
    f.glDeleteTextures(1, &m_gpu->spreadTexture);
    f.glDeleteVertexArrays(1, &m_gpu->emptyVao);
    m_gpu->meshes.release(f);
    m_gpu->motionMeshes.release(f);
    m_gpu->targets.release(f);
    m_gpu->shaders.clear();
    m_gpu.reset();
}

ViewOverlay Renderer::overlay(int width, int height) const {
    OverlayInput in;
    in.grid = m_scene.hasGrid ? &m_scene.grid : nullptr;
    in.frame = &m_scene.frame;
    in.viewProjection = m_scene.camera.viewProjection(static_cast<float>(width) /
                                                      static_cast<float>(std::max(height, 1)));
    in.eye = m_scene.camera.eye();
    in.width = width;
    in.height = height;
    in.appearance = m_scene.meshes ? &m_scene.appearance : nullptr;
    in.showMean =
        m_scene.settings.showMean && m_scene.meshes && !m_scene.meshes->mean.vertices.empty();
    if (m_scene.meshes) {
        const data::MeshSet& meshes = *m_scene.meshes;
        // As contextMesh() chooses: the mean stands in for a summary that is not there.
        if (m_scene.settings.context == ContextSurface::Median && meshes.median >= 0) {
            in.contextName = QStringLiteral("Median member");
        } else if (m_scene.settings.context == ContextSurface::Probability &&
                   !meshes.probability.vertices.empty()) {
            in.contextName = QStringLiteral("Half the members exceed");
        }
        in.band = m_scene.settings.showBand && !meshes.bandOuter.vertices.empty();
        in.outliers = in.band ? static_cast<int>(meshes.outliers.size()) : 0;
        in.bandColor = kBandColor;
    }
    in.planeCurves =
        m_scene.settings.plane.enabled && m_scene.meshes &&
        m_scene.settings.mode != RenderMode::OpaqueSurfaces &&
        !planeBoxPolygon(m_scene.settings.plane, m_scene.frame.boxMin(), m_scene.frame.boxMax())
             .empty();
    in.planeColor = glm::vec3(kPlaneColor);
    in.showAxes = m_scene.settings.showAxes;
    in.showLegend = m_scene.settings.showLegend;
    if (m_scene.settings.showTitle) in.title = title();
    if (m_scene.settings.showGraticule && m_scene.mapLines && m_scene.hasGrid) {
        for (const geo::MapLine& line : *m_scene.mapLines) {
            if (line.label.empty() || line.points.empty()) continue;
            glm::vec3 p = m_scene.frame.toDisplay(
                {line.points.front().x, line.points.front().y, m_scene.grid.z().front()});
            p.z = m_scene.frame.boxMin().z;
            in.floorLabels.emplace_back(p, QString::fromStdString(line.label));
        }
    }
    if (m_scene.settings.showLegend && m_scene.hasGrid &&
        m_scene.floor.values.size() == m_scene.grid.nx() * m_scene.grid.ny() &&
        !m_scene.floor.caption.isEmpty()) {
        in.colourScales.push_back(
            ColourScale{m_scene.floor.caption, m_scene.floor.minimum, m_scene.floor.maximum});
    }
    if (m_scene.settings.showLegend && contextColouredBySpread() && in.showMean) {
        in.colourScales.push_back(ColourScale{
            QStringLiteral("context: ") + m_scene.spread.quantity +
                (m_scene.spread.units.isEmpty()
                     ? QString()
                     : QStringLiteral(" [") + m_scene.spread.units + QStringLiteral("]")),
            m_scene.spread.minimum, m_scene.spread.maximum});
    }
    if (m_scene.settings.showLegend && sectionShown() && !m_scene.section.quantity.isEmpty()) {
        in.colourScales.push_back(ColourScale{m_scene.section.caption(), m_scene.section.minimum,
                                              m_scene.section.maximum});
    }
    in.background = glm::vec3(m_background);
    return computeOverlay(in);
}

void Renderer::setGrid(const data::Grid& grid) {
    m_scene.grid = grid;
    m_scene.hasGrid = true;
    m_scene.frame = data::DisplayFrame(grid, m_scene.frame.verticalExaggeration(),
                                       m_scene.settings.verticalAxis);
    m_axisTablesDirty = true;
    m_mapLinesDirty = true;
    m_meshesDirty = true;  // the rims lie on the box's faces
    m_motionMeshesDirty = true;
    resetCamera();
}

void Renderer::setVerticalExaggeration(float exaggeration) {
    if (m_scene.hasGrid) {
        m_scene.frame =
            data::DisplayFrame(m_scene.grid, exaggeration, m_scene.settings.verticalAxis);
        m_axisTablesDirty = true;
        frameTheBox();
    }
}

void Renderer::setVerticalAxis(data::VerticalAxis axis) {
    m_scene.settings.verticalAxis = axis;
    if (m_scene.hasGrid) {
        m_scene.frame =
            data::DisplayFrame(m_scene.grid, m_scene.frame.verticalExaggeration(), axis);
        m_axisTablesDirty = true;  // all that moves: meshes and rims are in grid indices
    }
}

void Renderer::frameTheBox() {
    const glm::vec3 lo = m_scene.frame.boxMin(), hi = m_scene.frame.boxMax();
    m_scene.camera.frameBox(lo, hi, viewAspect());
    // Where the legend or the colour bar would cover the box (a small view, a map seen from
    // the top that fills it), the box is framed into what the panels leave: beside a strip
    // on the right for both, or the legend on the right and the colour bar below, whichever
    // leaves the box larger.
    const glm::ivec2 size = m_scene.viewSize;
    if (m_scene.hasGrid && size.x > 0 && size.y > 0) {
        const QSizeF logical(static_cast<double>(size.x) / m_lineScale,
                             static_cast<double>(size.y) / m_lineScale);
        const ViewOverlay shown = overlay(size.x, size.y);
        const PanelRoom room = panelRoom(shown, logical.width());
        const auto covered = [&] {
            const QRectF box(shown.box.topLeft() / m_lineScale, shown.box.size() / m_lineScale);
            const PanelPlaces places = placePanels(shown, logical, box);
            // The box with its tick values and axis titles around it.
            const QRectF labelled =
                box.adjusted(-room.axisLabels, 0.0, room.axisLabels, room.axisLabels);
            return places.legend.intersects(labelled) || places.colourBar.intersects(labelled) ||
                   (!shown.colourScales.empty() && places.colourBar.isEmpty());
        };
        if (covered()) {
            const auto region = [&](double right, double bottom) {
                // Logical pixels from each edge to NDC, y up.
                return Camera::NdcRegion{
                    {-1.0F, static_cast<float>(-1.0 + 2.0 * bottom / logical.height())},
                    {static_cast<float>(1.0 - 2.0 * right / logical.width()),
                     static_cast<float>(1.0 - 2.0 * room.top / logical.height())}};
            };
            const double strip = room.margin * 2;
            const double stackedHeight =
                room.top + room.legend.height() + room.colourBar.height() + 3 * room.margin;
            std::vector<Camera::NdcRegion> candidates;
            if (stackedHeight <= logical.height()) {
                candidates.push_back(
                    region(std::max(room.legend.width(), room.colourBar.width()) + strip,
                           room.axisLabels));
            }
            // Below the box its tick values and axis title come before the colour bar.
            candidates.push_back(region(room.legend.width() + (room.legend.isEmpty() ? 0 : strip),
                                        room.colourBar.height() + room.axisLabels +
                                            (room.colourBar.isEmpty() ? 0 : strip)));
            // The share of the view the box's rectangle takes with this camera.
            const auto boxShare = [&](const Camera& camera) {
                const glm::ivec4 r =
                    screenRectangle(camera.viewProjection(viewAspect()), size.x, size.y);
                return static_cast<double>(r.z) * r.w / (static_cast<double>(size.x) * size.y);
            };
            // Not at any price: in a view smaller than ensil supports (480 x 320) the room
            // would leave a box too small to read, and the panels cover it as before.
            Camera best = m_scene.camera;
            double bestShare = kLeastBoxShareBesidePanels;
            for (const Camera::NdcRegion& r : candidates) {
                if (r.max.x <= r.min.x + 0.2F || r.max.y <= r.min.y + 0.2F) continue;
                Camera trial = m_scene.camera;
                trial.frameBox(lo, hi, viewAspect(), 0.8F, r);
                if (const double share = boxShare(trial); share > bestShare) {
                    bestShare = share;
                    best = trial;
                }
            }
            m_scene.camera = best;
        }
    }
    m_framedCamera = m_scene.camera;
}

void Renderer::resetCamera() {
    m_scene.camera.reset(m_scene.frame.center(), 0.5F * glm::length(m_scene.frame.boxMax()));
    frameTheBox();
}

void Renderer::lookFrom(float azimuth, float elevation) {
    resetCamera();
    m_scene.camera.setAngles(azimuth, elevation);
    frameTheBox();
}

void Renderer::setViewSize(int width, int height) {
    if (width <= 0 || height <= 0) return;
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    const bool resized = m_scene.viewSize != glm::ivec2(width, height);
    m_scene.viewSize = {width, height};
    if (aspect == m_scene.viewAspect && !resized) return;
    m_scene.viewAspect = aspect;
    // A camera still where the last reset or preset put it was framed for another shape: the
    // box would stick out of a narrower view. Framed again; a camera the user moved stays.
    if (m_scene.hasGrid && m_framedCamera == m_scene.camera) frameTheBox();
}

void Renderer::setFloorMap(FloorMap map) {
    m_scene.floor = std::move(map);
    m_floorDirty = true;
}

void Renderer::uploadFloorMap() {
    m_floorDirty = false;
    if (!m_scene.hasGrid || m_scene.floor.values.size() != m_scene.grid.nx() * m_scene.grid.ny()) {
        m_gpu->floorSize = {0, 0};
        return;
    }
    // Normalise on the CPU, with -1 marking missing values: linear filtering of NaN would
    // smear gaps into their neighbours.
    // Texture rows and columns run from the smallest coordinate up, as display space does;
    // many files store latitude from north to south.
    const float span = m_scene.floor.maximum - m_scene.floor.minimum;
    const std::size_t nx = m_scene.grid.nx(), ny = m_scene.grid.ny();
    const bool flipX = m_scene.grid.x().back() < m_scene.grid.x().front();
    const bool flipY = m_scene.grid.y().back() < m_scene.grid.y().front();
    std::vector<float> normalised(m_scene.floor.values.size());
    for (std::size_t j = 0; j < ny; ++j) {
        for (std::size_t i = 0; i < nx; ++i) {
            const float v =
                m_scene.floor.values[(flipX ? nx - 1 - i : i) + nx * (flipY ? ny - 1 - j : j)];
            normalised[i + nx * j] =
                std::isnan(v) ? -1.0F : (span > 0 ? (v - m_scene.floor.minimum) / span : 0.5F);
        }
    }
    GlFunctions& f = *m_gpu->f;
    m_gpu->floorSize = {static_cast<int>(m_scene.grid.nx()), static_cast<int>(m_scene.grid.ny())};
    f.glBindTexture(GL_TEXTURE_2D, m_gpu->floorTexture);
    f.glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    f.glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, m_gpu->floorSize.x, m_gpu->floorSize.y, 0, GL_RED,
                   GL_FLOAT, normalised.data());
    f.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    f.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    f.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    f.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

void Renderer::setResolutionScale(float scale) {
    m_resolutionScale = std::clamp(scale, kMinimumResolutionScale, 1.0F);
}

void Renderer::render(unsigned framebuffer, int width, int height) {
    if (!m_gpu) throw std::runtime_error("Renderer::render before initialize");
    if (width <= 0 || height <= 0) return;
    m_scene.lastSize = {width, height};
    // The frame's shape, without framing the camera again: a picture exported at another
    // shape shows the view's camera, as the project saved with it does (setViewSize, called on
    // the view's resize, is what frames again).
    m_scene.viewAspect = static_cast<float>(width) / static_cast<float>(height);
    // The scene is drawn at its own size, the same shape as the frame.
    const auto scaled = [&](int size) {
        return std::max(
            1, static_cast<int>(std::lround(static_cast<float>(size) * m_resolutionScale)));
    };
    m_scene.sceneSize = {scaled(width), scaled(height)};
    const int sceneWidth = m_scene.sceneSize.x, sceneHeight = m_scene.sceneSize.y;
    GlFunctions& f = *m_gpu->f;
    m_gpu->targets.ensure(f, sceneWidth, sceneHeight, kSceneSamples, m_resolutionScale < 1.0F);
    f.glBindFramebuffer(GL_FRAMEBUFFER, m_gpu->targets.sceneFramebuffer());
    f.glViewport(0, 0, sceneWidth, sceneHeight);
    f.glClearColor(m_background.r, m_background.g, m_background.b, m_background.a);
    f.glClearDepth(1.0);
    f.glDepthMask(GL_TRUE);
    f.glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (m_scene.hasGrid) {
        if (m_floorDirty) uploadFloorMap();
        if (m_sectionDirty) uploadSectionVolume();
        if (m_spreadDirty) {
            m_spreadDirty = false;
            m_gpu->spreadUploaded = uploadFieldVolume(m_gpu->spreadTexture, m_scene.spread);
        }
        if (m_mapLinesDirty) uploadMapLines();
        if (m_axisTablesDirty) uploadAxisTables();
        const float aspect = static_cast<float>(width) / static_cast<float>(height);
        const glm::mat4 viewProjection = m_scene.camera.viewProjection(aspect);
        drawFloorAndBox(viewProjection);
        drawSection(viewProjection);
        drawMeshes(viewProjection, sceneWidth, sceneHeight);
        if (m_scene.settings.plane.enabled) drawPlaneOutline(viewProjection);
    }
    f.glDisable(GL_SCISSOR_TEST);
    m_gpu->targets.resolve(f);
    present(framebuffer, width, height);
}

void Renderer::present(unsigned framebuffer, int width, int height) {
    GlFunctions& f = *m_gpu->f;
    f.glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    f.glViewport(0, 0, width, height);
    f.glDisable(GL_DEPTH_TEST);
    f.glDisable(GL_BLEND);
    QOpenGLShaderProgram& program = m_gpu->shaders.program(QStringLiteral("present"));
    program.bind();
    program.setUniformValue("u_scene", 0);
    // Pixel for pixel at full resolution; a smaller scene is scaled up, filtered.
    program.setUniformValue("u_scaled", m_scene.sceneSize != m_scene.lastSize);
    program.setUniformValue("u_frameSize", static_cast<float>(width), static_cast<float>(height));
    f.glActiveTexture(GL_TEXTURE0);
    f.glBindTexture(GL_TEXTURE_2D, m_gpu->targets.sceneColor());
    f.glBindVertexArray(m_gpu->emptyVao);
    f.glDrawArrays(GL_TRIANGLES, 0, 3);
    f.glBindVertexArray(0);
    program.release();
}

void Renderer::drawFloorAndBox(const glm::mat4& viewProjection) {
    GlFunctions& f = *m_gpu->f;
    f.glEnable(GL_DEPTH_TEST);
    f.glDepthFunc(GL_LEQUAL);
    const glm::vec3 lo = m_scene.frame.boxMin();
    const glm::vec3 hi = m_scene.frame.boxMax();
    if (m_gpu->floorSize.x > 0) {
        QOpenGLShaderProgram& floor = m_gpu->shaders.program(QStringLiteral("floor_map"));
        floor.bind();
        f.glUniformMatrix4fv(floor.uniformLocation("u_viewProjection"), 1, GL_FALSE,
                             glm::value_ptr(viewProjection));
        floor.setUniformValue("u_boxMin", lo.x, lo.y, lo.z);
        floor.setUniformValue("u_boxMax", hi.x, hi.y, hi.z);
        floor.setUniformValue("u_texelInset", 0.5F / static_cast<float>(m_gpu->floorSize.x),
                              0.5F / static_cast<float>(m_gpu->floorSize.y));
        floor.setUniformValue("u_opacity", 1.0F);
        floor.setUniformValue("u_map", 0);
        f.glUniform3fv(floor.uniformLocation("u_viridis"),
                       static_cast<GLsizei>(kViridisCoefficients.size()),
                       glm::value_ptr(kViridisCoefficients.front()));
        f.glActiveTexture(GL_TEXTURE0);
        f.glBindTexture(GL_TEXTURE_2D, m_gpu->floorTexture);
        f.glBindVertexArray(m_gpu->quadVao);
        // Push the floor back a little so the box edges lying on it stay visible.
        f.glEnable(GL_POLYGON_OFFSET_FILL);
        f.glPolygonOffset(1.0F, 1.0F);
        f.glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
        f.glDisable(GL_POLYGON_OFFSET_FILL);
    }
    drawMapLines(viewProjection);
    drawSectionGuides(viewProjection);

    const std::array<glm::vec3, 8> c{
        glm::vec3{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z},
        {lo.x, lo.y, hi.z},          {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
    const std::array<glm::vec3, 24> edges{c[0], c[1], c[1], c[2], c[2], c[3], c[3], c[0],
                                          c[4], c[5], c[5], c[6], c[6], c[7], c[7], c[4],
                                          c[0], c[4], c[1], c[5], c[2], c[6], c[3], c[7]};
    f.glBindBuffer(GL_ARRAY_BUFFER, m_gpu->boxVbo);
    f.glBufferSubData(GL_ARRAY_BUFFER, 0, sizeof(edges), edges.data());
    drawBoxBufferLines(GL_LINES, static_cast<int>(edges.size()), viewProjection, kBoxHalfWidth,
                       kBoxColor);
}

std::vector<glm::vec3> planeBoxPolygon(const CuttingPlane& plane, const glm::vec3& lo,
                                       const glm::vec3& hi) {
    std::vector<glm::vec3> points;
    const std::array<glm::vec3, 8> c{
        glm::vec3{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z},
        glm::vec3{lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
    constexpr std::array<std::array<int, 2>, 12> edges{{{0, 1},
                                                        {1, 2},
                                                        {2, 3},
                                                        {3, 0},
                                                        {4, 5},
                                                        {5, 6},
                                                        {6, 7},
                                                        {7, 4},
                                                        {0, 4},
                                                        {1, 5},
                                                        {2, 6},
                                                        {3, 7}}};
    for (const auto& [a, b] : edges) {
        const float da = glm::dot(plane.normal, c[a]) - plane.offset;
        const float db = glm::dot(plane.normal, c[b]) - plane.offset;
        if ((da < 0.0F) == (db < 0.0F) || da == db) continue;
        points.push_back(c[a] + (da / (da - db)) * (c[b] - c[a]));
    }
    if (points.size() < 3) return {};
    // In order around their centre, in the plane's own two axes.
    glm::vec3 centre(0.0F);
    for (const glm::vec3& p : points) centre += p;
    centre /= static_cast<float>(points.size());
    const glm::vec3 u = glm::normalize(points.front() - centre);
    const glm::vec3 v = glm::cross(plane.normal, u);
    std::sort(points.begin(), points.end(), [&](const glm::vec3& p, const glm::vec3& q) {
        return std::atan2(glm::dot(p - centre, v), glm::dot(p - centre, u)) <
               std::atan2(glm::dot(q - centre, v), glm::dot(q - centre, u));
    });
    return points;
}

void Renderer::drawPlaneOutline(const glm::mat4& viewProjection) {
    const std::vector<glm::vec3> polygon =
        planeBoxPolygon(m_scene.settings.plane, m_scene.frame.boxMin(), m_scene.frame.boxMax());
    if (polygon.empty()) return;
    // Seen edge-on the plane is a line through its own curves: leave it out then.
    const glm::vec3 sight = glm::normalize(m_scene.camera.target() - m_scene.camera.eye());
    if (std::abs(glm::dot(sight, m_scene.settings.plane.normal)) < 0.15F) return;
    GlFunctions& f = *m_gpu->f;
    QOpenGLShaderProgram& lines = m_gpu->shaders.program(QStringLiteral("lines"));
    lines.bind();
    f.glUniformMatrix4fv(lines.uniformLocation("u_viewProjection"), 1, GL_FALSE,
                         glm::value_ptr(viewProjection));
    f.glBindVertexArray(m_gpu->boxVao);
    f.glBindBuffer(GL_ARRAY_BUFFER, m_gpu->boxVbo);
    f.glBufferSubData(GL_ARRAY_BUFFER, 0,
                      static_cast<GLsizeiptr>(polygon.size() * sizeof(glm::vec3)), polygon.data());
    f.glEnable(GL_BLEND);
    f.glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    f.glDepthMask(GL_FALSE);
    // Where the plane lies, faintly: the surfaces behind it stay readable; its outline says
    // where it meets the box. A filled face (drawSection) needs no tint.
    if (!sectionShown()) {
        lines.setUniformValue("u_color", kPlaneColor.r, kPlaneColor.g, kPlaneColor.b, 0.08F);
        f.glDrawArrays(GL_TRIANGLE_FAN, 0, static_cast<GLsizei>(polygon.size()));
    }
    f.glDepthMask(GL_TRUE);
    f.glDisable(GL_BLEND);
    f.glBindVertexArray(0);
    lines.release();
    drawBoxBufferLines(GL_LINE_LOOP, static_cast<int>(polygon.size()), viewProjection,
                       kBoxHalfWidth, {kPlaneColor.r, kPlaneColor.g, kPlaneColor.b, 0.7F});
}

}  // namespace ensil::gl

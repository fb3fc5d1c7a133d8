// Draws the 3D scene into whatever framebuffer is bound (a window's, or an offscreen one for
// tests and `ensil render`): the data box with its edges, a map of the mean's column maximum on
// its floor, the mean isosurface as a solid gray surface, and every member's isosurface as
// shaded silhouettes, a 3D spaghetti plot or semi-transparent surfaces (RenderSettings).
// Translucent members are composited with weighted blended order-independent transparency, so
// the image does not depend on the order members are drawn in. The scene is drawn into the
// renderer's own targets first and then copied to the caller's framebuffer.
// Threading: setters may be called at any time on the GUI thread; initialize(), render() and
// releaseGpuResources() need the owning OpenGL context current. The renderer owns its GL
// objects and must release them before that context dies (QOpenGLContext::aboutToBeDestroyed).
#pragma once

#include <QString>
#include <algorithm>
#include <cstdint>
#include <functional>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>
#include <memory>
#include <optional>
#include <vector>

#include "data/display_frame.h"
#include "data/grid.h"
#include "data/packed_mesh.h"
#include "geo/map_lines.h"
#include "gl/camera.h"
#include "gl/render_settings.h"
#include "gl/view_overlay.h"

class QOpenGLShaderProgram;

namespace ensil::gl {

struct GpuMesh;
class GpuMeshCache;
struct ShaderFiles;

// What lies under a pixel: the member (-1 for none) and its cluster (-1 when unknown).
// Where a plane cuts a box: the polygon's corners in order around it (3 to 6 of them), or none
// when the plane misses the box. Display space.
std::vector<glm::vec3> planeBoxPolygon(const CuttingPlane& plane, const glm::vec3& boxMin,
                                       const glm::vec3& boxMax);

struct PickResult {
    int member = -1;
    int cluster = -1;
    // Where the picked member's surface lies under the pixel, in display space.
    std::optional<glm::vec3> surface;
    // Where the view ray through the pixel meets the box's floor, in display space (none when
    // it misses the floor): what the floor map shows there.
    std::optional<glm::vec3> floor;
    // Where it meets the filled cut face (Renderer::sectionShown), in display space. A member
    // hidden behind the face is not picked.
    std::optional<glm::vec3> section;
};

// A 2D field drawn on the box floor: nx * ny values (x fastest), NaN where missing.
struct FloorMap {
    std::vector<float> values;
    float minimum = 0.0F;
    float maximum = 1.0F;
    // What the map shows, for the colour bar: "column maximum of the mean t [K]".
    QString caption;

    // A map whose colour range spans its own valid values.
    static FloorMap spanning(std::vector<float> values, QString caption = {});
};

// A 3D field the cutting plane's cut face shows (CuttingPlane::fill): one value per grid point
// (x fastest), NaN where missing, coloured over [minimum, maximum] with a colour bar.
struct SectionVolume {
    std::vector<float> values;
    float minimum = 0.0F;
    float maximum = 1.0F;
    // What a value is ("standard deviation of z", "P(t > 260 K)") and its units (empty for a
    // probability), for the colour bar and the value under the cursor.
    QString quantity;
    QString units;
    // The colour bar's caption: "section: standard deviation of z [m2 s-2]".
    [[nodiscard]] QString caption() const {
        return QStringLiteral("section: ") + quantity +
               (units.isEmpty() ? QString() : QStringLiteral(" [") + units + QStringLiteral("]"));
    }
};

// The volume's value at a display-space point of this grid and frame (trilinear, NaN where
// missing or when the volume does not fit the grid): what the filled cut face shows there.
float sectionValueAt(const SectionVolume& volume, const data::Grid& grid,
                     const data::DisplayFrame& frame, const glm::vec3& display);

class Renderer {
public:
    Renderer();
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // Compiles shaders and creates GL objects. Throws ShaderError, or std::runtime_error when the
    // context is not OpenGL 4.1 core or newer.
    void initialize();
    void releaseGpuResources();
    // Draws a tiny scene in every mode once so the driver compiles its shader variants now
    // rather than at the first real frame (renderer_warm_up.cpp); leaves the scene as it was.
    // Context current; costs a fraction of a second on llvmpipe.
    void warmUp();
    [[nodiscard]] bool isInitialized() const;

    // Draws into the framebuffer object `framebuffer` (0 = the default) of the given pixel size.
    void render(unsigned framebuffer, int width, int height);
    // The fraction of the framebuffer's size the scene is drawn at, then scaled up to fill it
    // (1: full resolution, the default; clamped to [kMinimumResolutionScale, 1]). A software
    // renderer's time goes with the pixels drawn, so the view lowers it while the camera moves.
    void setResolutionScale(float scale);
    [[nodiscard]] float resolutionScale() const { return m_resolutionScale; }
    // The size the last frame's scene was drawn at, in pixels.
    [[nodiscard]] glm::ivec2 sceneSize() const { return m_scene.sceneSize; }
    static constexpr float kMinimumResolutionScale = 0.25F;
    // Samples per pixel of the scene (multisample antialiasing; the driver may offer fewer).
    static constexpr int kSceneSamples = 4;
    // Map lines' widths are multiplied by this: an exported picture larger than the view draws
    // them as the view would at that zoom (gl::exportTextScale for the overlay's text).
    void setLineScale(float scale) { m_lineScale = std::max(scale, 0.1F); }

    // The member drawn at pixel (x, y) of the last frame (origin top left, framebuffer pixels):
    // the member whose fragment is nearest to the pixel within `radius` pixels, the front-most
    // where several overlap. Draws an id pass into the renderer's own framebuffer, limited to
    // the pixels searched; leaves framebuffer 0 bound. Context current.
    [[nodiscard]] PickResult pick(int x, int y, int radius = 3);
    // Every member drawn in the rectangle between two corners (inclusive, clamped to the
    // frame), front-most at each pixel: what brushing selects. Sorted, no repeats.
    [[nodiscard]] std::vector<int> membersIn(int x0, int y0, int x1, int y1);
    // A member to emphasise (hover): drawn lighter. -1 for none.
    void setHighlightedMember(int member) { m_highlighted = member; }
    [[nodiscard]] int highlightedMember() const { return m_highlighted; }

    // The line above the picture saying what it shows (variable, isovalue, time, members);
    // painted with the overlay when RenderSettings::showTitle. Either fixed, or made from the
    // isovalue of the meshes drawn (setTitleOf), so that a view still drawing the last
    // surfaces while the next ones are built (seconds for large data) names what it draws.
    void setTitle(QString title) {
        m_title = std::move(title);
        m_titleOf = {};
    }
    void setTitleOf(std::function<QString(float isovalue)> titleOf) {
        m_title.clear();
        m_titleOf = std::move(titleOf);
    }
    [[nodiscard]] QString title() const {
        return m_titleOf && m_scene.meshes ? m_titleOf(m_scene.meshes->isovalue) : m_title;
    }
    // The labels and legend to paint over a frame of this size (see gl/view_overlay.h).
    [[nodiscard]] ViewOverlay overlay(int width, int height) const;

    // The member the animation shows (-1: none): drawn as a solid surface while the selection
    // is drawn as silhouettes, so one solid member is seen at a time.
    void setAnimatedMember(int member) { m_animated = member; }
    [[nodiscard]] int animatedMember() const { return m_animated; }
    // How the selection is drawn: up to kMaxSolidSelection selected members as solid surfaces,
    // more as semi-transparent ones; the unselected dimmed while any is selected.
    struct Selection {
        bool any = false;
        bool solid = true;
    };
    static constexpr int kMaxSolidSelection = 3;
    // The rims where the surfaces meet the box (gl/mesh_rims.h), in pixels to either side of
    // the line: about the width of a silhouette at the default tau, wider when selected.
    static constexpr float kRimHalfWidth = 0.9F;
    static constexpr float kSelectedRimHalfWidth = 1.6F;
    // Framed beside the panels, the box's rectangle must still take this share of the view;
    // where it would not (views smaller than 480 x 320), the panels cover the box instead.
    static constexpr double kLeastBoxShareBesidePanels = 0.09;
    [[nodiscard]] Selection selectionShown() const;

    [[nodiscard]] bool hasGrid() const { return m_scene.hasGrid; }
    // The grid frames the scene; setting it refits the camera.
    void setGrid(const data::Grid& grid);
    void setFloorMap(FloorMap map);
    // The field the cut face shows when the plane is on and its fill is not None.
    void setSectionVolume(SectionVolume volume);
    [[nodiscard]] const SectionVolume& sectionVolume() const { return m_scene.section; }
    // Whether the cut face is filled with the section volume in the next frame.
    [[nodiscard]] bool sectionShown() const;
    // The members' standard deviation, which the context surface is coloured by when
    // RenderSettings::contextBySpread.
    void setSpreadVolume(SectionVolume volume);
    [[nodiscard]] bool contextColouredBySpread() const;
    // The section volume's value at a display-space point (trilinear, NaN where missing or
    // when no section is shown): what the cut face shows there.
    [[nodiscard]] float sectionValueAt(const glm::vec3& display) const;
    // Coastlines, borders and graticule on the floor, in the grid's axis coordinates (from
    // geo::mapLinesFor, for the grid set here); each kind drawn as RenderSettings says. Null
    // or empty: none.
    void setMapLines(std::shared_ptr<const std::vector<geo::MapLine>> lines);
    [[nodiscard]] const std::shared_ptr<const std::vector<geo::MapLine>>& mapLines() const {
        return m_scene.mapLines;
    }
    // Where the Sections dock's map and cross-section lie, as polylines in the box's unit cube
    // (x and y across the floor, z up the box, 0 to 1 each): a map's outline at its level and a
    // cross-section's curtain. Drawn as light lines over a dark casing. Empty: none.
    void setSectionGuides(std::vector<std::vector<glm::dvec3>> polylines);
    [[nodiscard]] const std::vector<std::vector<glm::dvec3>>& sectionGuides() const {
        return m_scene.sectionGuides;
    }
    static constexpr glm::vec4 kSectionGuideColor{1.0F, 0.85F, 0.35F, 1.0F};
    // How a coastline is drawn, for tests that look for it: a light core over a dark casing.
    static constexpr glm::vec4 kCoastlineColor{0.97F, 0.97F, 0.97F, 1.0F};
    void setVerticalExaggeration(float exaggeration);
    // Draws a pressure axis through log-pressure, linearly or at standard-atmosphere heights
    // (settings().verticalAxis): only the axis tables change; the meshes and their rims stay
    // uploaded (their vertices are grid indices, which the tables map into the box).
    void setVerticalAxis(data::VerticalAxis axis);
    // The meshes of the current isovalue (uploaded at the next frame); null clears them, and
    // their motion meshes too.
    void setMeshes(std::shared_ptr<const data::MeshSet> meshes);
    // The same members and mean in reduced detail (preprocessing/preview_meshes.h), drawn in
    // their place in frames below full resolution (camera motion, a step passing): with a
    // software OpenGL a frame of many small triangles costs by the triangle, not only by the
    // pixel. The context surfaces, the median and outliers and picking stay the full meshes'.
    // Null, or a different member count: the full meshes in every frame.
    void setMotionMeshes(std::shared_ptr<const data::MeshSet> meshes);
    [[nodiscard]] const std::shared_ptr<const data::MeshSet>& motionMeshes() const {
        return m_scene.motionMeshes;
    }
    [[nodiscard]] const std::shared_ptr<const data::MeshSet>& meshes() const {
        return m_scene.meshes;
    }
    // One entry per member; members without an entry are drawn light gray.
    void setAppearance(std::vector<MemberAppearance> appearance) {
        m_scene.appearance = std::move(appearance);
    }
    [[nodiscard]] const std::vector<MemberAppearance>& appearances() const {
        return m_scene.appearance;
    }
    [[nodiscard]] RenderSettings& settings() { return m_scene.settings; }
    [[nodiscard]] const RenderSettings& settings() const { return m_scene.settings; }
    // Bytes of mesh data on the GPU now.
    [[nodiscard]] std::size_t gpuBytes() const;
    void setBackground(const glm::vec4& color) { m_background = color; }

    [[nodiscard]] const data::DisplayFrame& frame() const { return m_scene.frame; }
    [[nodiscard]] Camera& camera() { return m_scene.camera; }
    [[nodiscard]] const Camera& camera() const { return m_scene.camera; }
    void resetCamera();
    // Fits the camera to the box at the view's size, from its angles, and remembers it; where
    // the legend or colour bar would cover the box, into the part of the view they leave.
    void frameTheBox();
    // Looks from these angles (degrees; see Camera), fitted to the data box like resetCamera.
    void lookFrom(float azimuth, float elevation);
    // The shape of the frames to come (a window's resize), which the camera is fitted to; a
    // camera still as the last reset or preset framed it is framed again for the new shape.
    void setViewSize(int width, int height);

    static constexpr glm::vec4 kDefaultBackground{0.11F, 0.12F, 0.14F, 1.0F};
    static constexpr glm::vec4 kBoxColor{0.85F, 0.85F, 0.85F, 1.0F};
    static constexpr float kBoxHalfWidth = 0.75F;  // pixels either side of the box's edges
    // The cutting plane's outline and faint fill (a warm tone apart from the cluster palette).
    static constexpr glm::vec4 kPlaneColor{1.0F, 0.85F, 0.55F, 1.0F};
    // The contour boxplot's 50 % band: a pale blue-gray, apart from the cluster palette and
    // the context's gray; its outer surface fainter than its inner one.
    static constexpr glm::vec3 kBandColor{0.70F, 0.80F, 0.95F};
    static constexpr float kBandOuterAlpha = 0.12F;
    // The filled cut face lies this many curve widths eps behind the plane: the curves are
    // drawn where a surface is within eps of it, and filtered over up to another eps where
    // the surface is seen edge-on, so all of each curve stays in front of the face.
    static constexpr float kSectionFaceBehind = 2.5F;
    static constexpr float kBandInnerAlpha = 0.22F;

private:
    struct Gpu;
    enum class MemberPass { Opaque, Translucent, All };
    void uploadMeshesIfChanged();
    [[nodiscard]] MemberAppearance appearance(std::size_t member) const;
    [[nodiscard]] bool translucentMode() const;
    [[nodiscard]] float viewAspect() const { return m_scene.viewAspect; }
    // The data box's bounding rectangle on screen (x, y, width, height in GL pixels, clamped to
    // the frame); the whole frame when the camera is inside the box.
    [[nodiscard]] glm::ivec4 screenRectangle(const glm::mat4& viewProjection, int width,
                                             int height) const;
    // The two isosurface programs, both set up for this frame: every triangle, and only the
    // parts that may hold a silhouette (the same one when culling is off); `bound` is the one
    // in use.
    struct SurfacePrograms {
        QOpenGLShaderProgram* full;
        QOpenGLShaderProgram* culled;
        QOpenGLShaderProgram* bound = nullptr;
        [[nodiscard]] bool clips() const { return bound == culled && culled != full; }
    };
    // `cull`: whether the silhouette modes may use the culling program (if the settings let it).
    // `viewport`: the pass's size in pixels.
    SurfacePrograms bindSurfacePrograms(const glm::mat4& viewProjection, glm::ivec2 viewport,
                                        bool pick, bool cull);
    void configureSurfaceProgram(QOpenGLShaderProgram& program, const glm::mat4& viewProjection,
                                 glm::ivec2 viewport, bool pick);
    void drawMemberPass(SurfacePrograms& programs, MemberPass pass);
    // The cutting plane with its normal turned to the viewer: the half it removes is
    // dot(normal, p) > offset.
    [[nodiscard]] CuttingPlane planeFacingViewer() const;
    // The cutting plane's uniforms (u_planeEnabled, u_plane), its normal turned to the viewer.
    void setPlaneUniforms(QOpenGLShaderProgram& program) const;
    // Whether the contour boxplot counts this member an outlier.
    [[nodiscard]] bool isOutlier(std::size_t member) const;
    // A member's colour as drawn: dimmed when others are selected (or, with the band shown,
    // when it is no outlier), lightened when highlighted.
    [[nodiscard]] glm::vec3 memberColour(std::size_t member, const MemberAppearance& a,
                                         const Selection& selection) const;
    // The context surface RenderSettings::context asks for (the mean's when that one is not
    // there).
    [[nodiscard]] const GpuMesh& contextMesh() const;
    // The members and mean this frame draws: the motion meshes in a frame below full
    // resolution when there are any, else the full ones.
    [[nodiscard]] const GpuMeshCache& drawnMeshes() const;
    // Every shown member's rims (and the mean's), after the surfaces (RenderSettings::showRims);
    // with `pick`, the members' ids into the id pass instead. `viewport`: the pass's pixels.
    void drawRims(const glm::mat4& viewProjection, glm::ivec2 viewport, bool pick);
    [[nodiscard]] bool canPick() const;
    // Draws the id pass into the window (GL pixel rows, bottom-up) and reads the ids back,
    // row by row: 0 for nothing, member + 1 otherwise.
    std::vector<std::uint32_t> drawIds(int x0, int y0, int w, int h);
    void uploadFloorMap();
    void uploadMapLines();
    void drawMapLines(const glm::mat4& viewProjection);
    void drawSectionGuides(const glm::mat4& viewProjection);
    // Binds the program that widens lines on screen (the map lines' and the box's), with the
    // view and the scene's size set.
    QOpenGLShaderProgram& bindScreenLines(const glm::mat4& viewProjection);
    // Binds a program of lines widened on screen (map_lines.geom), with the view and the
    // pass's size in pixels set.
    QOpenGLShaderProgram& bindLinesProgram(const QString& name, const ShaderFiles& files,
                                           const glm::mat4& viewProjection, glm::ivec2 viewport);
    // The grid-to-display tables (grid_display.glsl) on texture unit 1.
    void setAxisTableUniforms(QOpenGLShaderProgram& program);
    // The box's vertex buffer's first `count` points as antialiased lines `halfWidth` pixels
    // to either side (mode GL_LINES or GL_LINE_LOOP), blended, depth-tested but not written.
    void drawBoxBufferLines(unsigned mode, int count, const glm::mat4& viewProjection,
                            float halfWidth, const glm::vec4& colour);
    void uploadAxisTables();
    void drawFloorAndBox(const glm::mat4& viewProjection);
    // The cutting plane itself: its cut through the box as a faint fill with an outline.
    void drawPlaneOutline(const glm::mat4& viewProjection);
    // The cut face filled with the section volume (renderer_section.cpp), before the members
    // so that their curves on the plane are drawn over it.
    void uploadSectionVolume();
    void uploadSectionIndexTables();
    // Uploads a field to a 3D texture normalised to its range; false when it does not fit the
    // grid. And the uniforms of gl/shaders/field_lookup.glsl, the volume and the index tables
    // bound to these texture units.
    bool uploadFieldVolume(unsigned texture, const SectionVolume& volume);
    void setFieldUniforms(QOpenGLShaderProgram& program, unsigned texture, int volumeUnit,
                          int tablesUnit);
    void drawSection(const glm::mat4& viewProjection);
    void drawMeshes(const glm::mat4& viewProjection, int width, int height);
    void present(unsigned framebuffer, int width, int height);

    // What is drawn and from where: everything warmUp() puts aside while it draws its own.
    struct Scene {
        data::Grid grid;
        bool hasGrid = false;
        data::DisplayFrame frame;
        Camera camera;
        FloorMap floor;
        SectionVolume section;
        SectionVolume spread;
        std::shared_ptr<const std::vector<geo::MapLine>> mapLines;
        std::vector<std::vector<glm::dvec3>> sectionGuides;
        std::shared_ptr<const data::MeshSet> meshes;
        std::shared_ptr<const data::MeshSet> motionMeshes;
        std::vector<MemberAppearance> appearance;
        RenderSettings settings;
        glm::ivec2 lastSize{0};   // the last frame's size, which picking draws at
        glm::ivec2 sceneSize{0};  // the size its scene was drawn at (lastSize times the scale)
        float viewAspect = 1.6F;  // before the first frame: the usual window's shape
        glm::ivec2 viewSize{0};   // setViewSize's pixels; the panels' room depends on them
    };

    std::unique_ptr<Gpu> m_gpu;
    Scene m_scene;
    // What has changed in the scene since it was last uploaded.
    bool m_floorDirty = false;
    bool m_sectionDirty = false;
    bool m_spreadDirty = false;
    bool m_mapLinesDirty = false;
    // The box the section guides were uploaded for (they scale with it); zero: upload anew.
    glm::vec3 m_guidesBox{0.0F};
    bool m_axisTablesDirty = false;
    bool m_meshesDirty = false;
    bool m_motionMeshesDirty = false;
    glm::vec4 m_background = kDefaultBackground;
    float m_resolutionScale = 1.0F;
    // The camera as the last framing left it: still so, it is framed again when the view's
    // shape changes.
    std::optional<Camera> m_framedCamera;
    float m_lineScale = 1.0F;
    int m_highlighted = -1;
    QString m_title;
    std::function<QString(float)> m_titleOf;
    int m_animated = -1;
};

}  // namespace ensil::gl

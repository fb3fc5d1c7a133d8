// How the ensemble is drawn: the mode, silhouette thickness, density-based removal, the mean
// surface, and each member's colour, visibility and selection. A value type; GUI thread.
#pragma once

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <vector>

#include "data/display_frame.h"

namespace ensil::gl {

// OpaqueSurfaces draws every member as a solid lit isosurface (a reference; occludes).
enum class RenderMode { ShadedSilhouettes, Spaghetti, Surfaces, OpaqueSurfaces };

// What the cutting plane's cut face is filled with (METHODS.md section 18): nothing but a faint
// tint, the values of the hovered (else the first selected) member, the mean, the members'
// sample standard deviation, or the probability P(f > c) of exceeding the isovalue.
enum class SectionField { None, Member, Mean, StandardDeviation, Probability };

// A plane that cuts the scene (METHODS.md section 11): points p with dot(normal, p) > offset,
// in display space, are removed when they lie on the viewer's side; where each member's
// isosurface crosses the plane, its intersection curve is drawn `thickness` wide.
struct CuttingPlane {
    bool enabled = false;
    glm::vec3 normal{0.0F, 0.0F, 1.0F};      // unit length, display space
    float offset = 0.0F;                     // display units
    float thickness = 0.004F;                // eps, display units
    SectionField fill = SectionField::None;  // the cut face, coloured with a colour bar

    // The plane with this normal through the given display-space point.
    static CuttingPlane through(const glm::vec3& normal, const glm::vec3& point) {
        CuttingPlane plane;
        plane.enabled = true;
        plane.normal = glm::normalize(normal);
        plane.offset = glm::dot(plane.normal, point);
        return plane;
    }
    // The plane with this normal placed across a box: position -1 touches the box's corner
    // furthest against the normal, 0 passes through its centre, +1 touches the furthest corner
    // along it. Unit-free, so it means the same for every grid and every normal.
    static CuttingPlane acrossBox(const glm::vec3& normal, float position, const glm::vec3& boxMin,
                                  const glm::vec3& boxMax) {
        const glm::vec3 n = glm::normalize(normal);
        const glm::vec3 halfSize = 0.5F * (boxMax - boxMin);
        const float reach = glm::dot(glm::abs(n), halfSize);
        return through(n, 0.5F * (boxMin + boxMax) + position * reach * n);
    }
    // Where this plane lies across the box, as acrossBox's position.
    [[nodiscard]] float positionAcross(const glm::vec3& boxMin, const glm::vec3& boxMax) const {
        const glm::vec3 halfSize = 0.5F * (boxMax - boxMin);
        const float reach = glm::dot(glm::abs(normal), halfSize);
        const float centre = glm::dot(normal, 0.5F * (boxMin + boxMax));
        return reach > 0.0F ? (offset - centre) / reach : 0.0F;
    }

    bool operator==(const CuttingPlane&) const = default;
};

// What the box's floor shows (METHODS.md section 15): nothing, the mean's column maximum, the
// mean at one level (RenderSettings::floorLevel, a grid index), the column maximum of the
// members' standard deviation, or of the probability that the isovalue is exceeded (section 17).
enum class FloorContent { None, ColumnMaximum, MeanAtLevel, SpreadMaximum, ProbabilityMaximum };

// The gray surface drawn for context (METHODS.md section 17): the mean member's isosurface,
// the contour boxplot's median member's, or where half the members exceed the isovalue.
enum class ContextSurface { Mean, Median, Probability };

struct RenderSettings {
    RenderMode mode = RenderMode::ShadedSilhouettes;
    float thickness = 0.006F;   // tau, in display units (the data box is about 1 wide)
    float surfaceAlpha = 0.2F;  // for RenderMode::Surfaces
    bool showMean = true;       // the context surface (below), gray
    ContextSurface context = ContextSurface::Mean;
    // The context surface coloured by the members' standard deviation where it lies, with a
    // colour bar (Renderer::setSpreadVolume), instead of gray.
    bool contextBySpread = false;
    // The contour boxplot's 50 % band as a translucent envelope, outliers dashed.
    bool showBand = false;
    // The mean's opacity: below 1 it is a translucent context surface that never hides the
    // members behind it (and is not picked); 1 draws it solid, as the paper does.
    float meanOpacity = 0.3F;
    [[nodiscard]] bool meanTranslucent() const { return meanOpacity < 1.0F; }
    bool removal = false;     // density-based silhouette removal (METHODS.md section 10)
    float removalMin = 0.0F;  // o*_min, in the variable's units squared
    float removalMax = 1.0F;  // o*_max
    int groupSize = 4;        // s_G
    CuttingPlane plane;
    bool showAxes = true;    // tick labels in data units along the box (gl/view_overlay.h)
    bool showLegend = true;  // the cluster colours
    bool showTitle = true;   // the title line (Renderer::setTitle) above the picture
    FloorContent floor = FloorContent::ColumnMaximum;
    int floorLevel = 0;  // for FloorContent::MeanAtLevel: the vertical grid index
    // The map lines on the floor (Renderer::setMapLines), each switchable.
    bool showCoastlines = true;
    bool showBorders = true;
    bool showGraticule = true;
    // The rims where each surface meets the box (gl/mesh_rims.h): on the top and bottom faces,
    // each member's contour line at that level.
    bool showRims = true;
    // Silhouette modes skip, in a geometry shader, the triangles that cannot hold a silhouette:
    // the same picture, drawn faster. Off only to measure what it saves.
    bool silhouetteCulling = true;
    // How a pressure axis is drawn (data::VerticalAxis): applied by Renderer::setVerticalAxis,
    // since the box's frame follows it.
    data::VerticalAxis verticalAxis = data::VerticalAxis::LogPressure;

    // Whether the picture shows a context surface of the ensemble's own (the band's two, or
    // P = 0.5), which the workbench then has made (workbench/isovalue_session.h).
    [[nodiscard]] bool drawsContextSurfaces() const {
        return showBand || (showMean && context == ContextSurface::Probability);
    }

    bool operator==(const RenderSettings&) const = default;
};

struct MemberAppearance {
    glm::vec3 color{0.8F};
    bool visible = true;
    bool selected = false;  // drawn as a solid lit isosurface
    int cluster = -1;       // reported by picking; -1 when the members are not clustered
};

}  // namespace ensil::gl

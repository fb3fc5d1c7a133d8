#include "geo/map_projection.h"

#include <proj.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <limits>
#include <string_view>

#include "data/error.h"
#include "data/proj_definition.h"

namespace ensil::geo {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

template <std::size_t N>
bool oneOf(const std::string& value, const std::array<std::string_view, N>& options) {
    return std::find(options.begin(), options.end(), value) != options.end();
}

double metresPerUnit(const std::string& units) {
    const std::string u = lower(units);
    if (oneOf(u, std::array<std::string_view, 5>{"km", "kilometre", "kilometres", "kilometer",
                                                 "kilometers"})) {
        return 1000.0;
    }
    return 1.0;  // CF projection coordinates are in metres unless they say otherwise
}

}  // namespace

struct MapProjection::Proj {
    PJ_CONTEXT* context = nullptr;
    PJ* transformation = nullptr;
    Proj() = default;
    Proj(const Proj&) = delete;
    Proj& operator=(const Proj&) = delete;
    ~Proj() {
        if (transformation != nullptr) proj_destroy(transformation);
        if (context != nullptr) proj_context_destroy(context);
    }
    // Transforms in place; PROJ marks a point it cannot transform with HUGE_VAL.
    void transform(std::vector<glm::dvec2>& points, PJ_DIRECTION direction) const {
        if (points.empty()) return;
        proj_trans_generic(transformation, direction, &points[0].x, sizeof(glm::dvec2),
                           points.size(), &points[0].y, sizeof(glm::dvec2), points.size(), nullptr,
                           0, 0, nullptr, 0, 0);
        for (glm::dvec2& p : points) {
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || std::abs(p.x) >= HUGE_VAL) {
                p = glm::dvec2(kNaN);
            }
        }
    }
};

MapProjection::MapProjection(MapProjection&&) noexcept = default;
MapProjection& MapProjection::operator=(MapProjection&&) noexcept = default;
MapProjection::~MapProjection() = default;

MapProjection MapProjection::forGrid(const data::Grid& grid, const data::GridMapping& mapping) {
    MapProjection result;
    result.m_xMiddle = 0.5 * (grid.x().minValue() + grid.x().maxValue());
    if (mapping.empty() || mapping.name == "latitude_longitude") {
        if (data::isLongitudeAxis(grid.x()) && data::isLatitudeAxis(grid.y())) {
            result.m_kind = Kind::LonLat;
        } else {
            result.m_reason = "the horizontal axes ('" + grid.x().name + "', '" + grid.y().name +
                              "') are not longitude and latitude, and no grid_mapping says "
                              "where they lie";
        }
        return result;
    }
    try {
        result.m_projString = data::projStringFor(mapping);
    } catch (const data::Error& e) {
        result.m_reason = e.what();
        return result;
    }
    const bool rotated = mapping.name == "rotated_latitude_longitude";
    // PROJ's projection steps take radians; a rotated grid's coordinates come back in radians
    // too and are turned into degrees, the units of its axes.
    const std::string pipeline =
        "+proj=pipeline +step +proj=unitconvert +xy_in=deg +xy_out=rad "
        "+step " +
        result.m_projString + (rotated ? " +step +proj=unitconvert +xy_in=rad +xy_out=deg" : "");
    auto proj = std::make_unique<Proj>();
    proj->context = proj_context_create();
    proj->transformation = proj_create(proj->context, pipeline.c_str());
    if (proj->transformation == nullptr) {
        result.m_reason =
            "PROJ cannot use grid mapping '" + mapping.name + "' (" +
            proj_context_errno_string(proj->context, proj_context_errno(proj->context)) + ")";
        return result;
    }
    result.m_proj = std::move(proj);
    result.m_kind = rotated ? Kind::Rotated : Kind::Projected;
    result.m_metresPerUnit = rotated ? 1.0 : metresPerUnit(grid.x().units);
    return result;
}

void MapProjection::wrapX(std::vector<glm::dvec2>& points) const {
    for (glm::dvec2& p : points) p.x = m_xMiddle + std::remainder(p.x - m_xMiddle, 360.0);
}

void MapProjection::toGrid(std::vector<glm::dvec2>& points) const {
    switch (m_kind) {
        case Kind::None:
            std::fill(points.begin(), points.end(), glm::dvec2(kNaN));
            return;
        case Kind::LonLat:
            wrapX(points);
            return;
        case Kind::Rotated:
            m_proj->transform(points, PJ_FWD);
            wrapX(points);
            return;
        case Kind::Projected:
            m_proj->transform(points, PJ_FWD);
            for (glm::dvec2& p : points) p /= m_metresPerUnit;
            return;
    }
}

void MapProjection::toLonLat(std::vector<glm::dvec2>& points) const {
    switch (m_kind) {
        case Kind::None:
            std::fill(points.begin(), points.end(), glm::dvec2(kNaN));
            return;
        case Kind::LonLat:
            return;
        case Kind::Rotated:
            m_proj->transform(points, PJ_INV);
            return;
        case Kind::Projected:
            for (glm::dvec2& p : points) p *= m_metresPerUnit;
            m_proj->transform(points, PJ_INV);
            return;
    }
}

}  // namespace ensil::geo

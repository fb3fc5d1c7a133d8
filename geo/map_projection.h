// Where a grid's horizontal coordinates lie on the Earth: longitude/latitude in degrees to the
// grid's own x and y (axis units: degrees, rotated degrees, metres or kilometres) and back,
// through PROJ. The CF grid mapping's attributes become a PROJ string (data/proj_definition.h,
// METHODS.md section 16); the projection formulas themselves are PROJ's. A grid without a grid
// mapping whose axes are longitude and latitude maps onto itself, longitudes wrapped into its
// range. Move-only (it owns a PROJ context); use one object from one thread at a time.
#pragma once

#include <glm/vec2.hpp>
#include <memory>
#include <string>
#include <vector>

#include "data/grid.h"
#include "data/grid_mapping.h"

namespace ensil::geo {

class MapProjection {
public:
    enum class Kind {
        None,       // no geography: grid indices, or a mapping ensil cannot use (reason())
        LonLat,     // the axes are longitude and latitude
        Rotated,    // rotated longitude and latitude (CF rotated_latitude_longitude)
        Projected,  // map coordinates in metres or kilometres (Lambert, stereographic, ...)
    };

    // The grid's geography. Never throws: a mapping that cannot be used is Kind::None, with
    // reason() saying why.
    static MapProjection forGrid(const data::Grid& grid, const data::GridMapping& mapping);

    MapProjection(MapProjection&&) noexcept;
    MapProjection& operator=(MapProjection&&) noexcept;
    ~MapProjection();

    [[nodiscard]] Kind kind() const { return m_kind; }
    [[nodiscard]] bool hasGeography() const { return m_kind != Kind::None; }
    // Why there is no geography (empty when there is): "grid mapping 'sinusoidal' is not one
    // ensil reads", "the axes are not longitude and latitude".
    [[nodiscard]] const std::string& reason() const { return m_reason; }
    // The PROJ string the transformation was made from; empty for LonLat and None.
    [[nodiscard]] const std::string& projString() const { return m_projString; }
    // Whether x is an angle that wraps every 360 (LonLat, Rotated).
    [[nodiscard]] bool xWraps() const { return m_kind == Kind::LonLat || m_kind == Kind::Rotated; }

    // Longitude/latitude (degrees) to the grid's x, y in place; NaN where it has none. Wrapping
    // x is put within 180 of the grid's middle, so a line across the grid's edge breaks outside.
    void toGrid(std::vector<glm::dvec2>& points) const;
    // The grid's x, y to longitude/latitude (degrees, longitude in [-180, 180] except for LonLat,
    // which keeps the grid's own longitudes); NaN where it has none.
    void toLonLat(std::vector<glm::dvec2>& points) const;

private:
    MapProjection() = default;
    struct Proj;
    void wrapX(std::vector<glm::dvec2>& points) const;

    Kind m_kind = Kind::None;
    std::string m_reason;
    std::string m_projString;
    double m_xMiddle = 0.0;
    double m_metresPerUnit = 1.0;  // projected axes in kilometres: 1000
    std::unique_ptr<Proj> m_proj;
};

}  // namespace ensil::geo

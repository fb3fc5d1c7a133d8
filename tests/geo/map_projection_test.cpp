// MapProjection: CF grid mappings through PROJ, checked against values computed without PROJ
// (the rotated pole written out with vectors; Snyder's worked examples for the conformal
// projections) and round trips; clear reasons where there is no geography.
#include "geo/map_projection.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "data/error.h"
#include "tests/geo/rotated_pole.h"

using namespace ensil;
using geo::MapProjection;

namespace {

data::Grid lonLatGrid(double lon0, double lon1) {
    return data::Grid(data::makeUniformAxis("lon", "degrees_east", lon0, lon1, 10),
                      data::makeUniformAxis("lat", "degrees_north", -90.0, 90.0, 10),
                      data::makeUniformAxis("plev", "hPa", 1000.0, 100.0, 3));
}

data::Grid projectedGrid(const char* units) {
    return data::Grid(data::makeUniformAxis("x", units, -1.0e6, 1.0e6, 10),
                      data::makeUniformAxis("y", units, -1.0e6, 1.0e6, 10),
                      data::makeUniformAxis("z", "m", 0.0, 1.0e4, 3));
}

data::GridMapping mapping(std::string name,
                          std::vector<std::pair<std::string, std::vector<double>>> parameters) {
    return data::GridMapping{std::move(name), std::move(parameters)};
}

glm::dvec2 toGrid(const MapProjection& p, glm::dvec2 lonLat) {
    std::vector<glm::dvec2> points{lonLat};
    p.toGrid(points);
    return points.front();
}

glm::dvec2 toLonLat(const MapProjection& p, glm::dvec2 xy) {
    std::vector<glm::dvec2> points{xy};
    p.toLonLat(points);
    return points.front();
}

data::GridMapping ukRotatedPole() {
    return mapping("rotated_latitude_longitude",
                   {{"grid_north_pole_latitude", {37.5}}, {"grid_north_pole_longitude", {177.5}}});
}

data::Grid rotatedGrid() {
    return data::Grid(data::makeUniformAxis("grid_longitude", "degrees", 357.5, 360.0, 10),
                      data::makeUniformAxis("grid_latitude", "degrees", 0.1, 2.9, 10),
                      data::makeUniformAxis("level", "m", 0.0, 1.0e4, 3));
}

}  // namespace

TEST(MapProjection, LongitudeLatitudeAxesMapOntoThemselvesWrappedIntoTheGrid) {
    const MapProjection era5 = MapProjection::forGrid(lonLatGrid(0.0, 357.0), {});
    ASSERT_EQ(era5.kind(), MapProjection::Kind::LonLat);
    EXPECT_TRUE(era5.xWraps());
    EXPECT_NEAR(toGrid(era5, {-10.0, 45.0}).x, 350.0, 1e-9);
    EXPECT_NEAR(toGrid(era5, {-10.0, 45.0}).y, 45.0, 1e-9);
    const MapProjection atlantic = MapProjection::forGrid(lonLatGrid(-180.0, 179.0), {});
    EXPECT_NEAR(toGrid(atlantic, {350.0, 45.0}).x, -10.0, 1e-9);
}

TEST(MapProjection, RotatedPoleAgreesWithTheTransformationWrittenOut) {
    const MapProjection rotated = MapProjection::forGrid(rotatedGrid(), ukRotatedPole());
    ASSERT_EQ(rotated.kind(), MapProjection::Kind::Rotated) << rotated.reason();
    const test::RotatedPole reference(177.5, 37.5);
    for (const glm::dvec2 place : {glm::dvec2{-6.26, 53.35}, glm::dvec2{-1.55, 53.8},
                                   glm::dvec2{-3.19, 55.95}, glm::dvec2{10.0, 60.0}}) {
        const glm::dvec2 expected = reference.toRotated(place);
        const glm::dvec2 got = toGrid(rotated, place);
        // The grid's longitudes run 357.5 to 360: PROJ's -2.5 is the grid's 357.5.
        EXPECT_NEAR(std::remainder(got.x - expected.x, 360.0), 0.0, 1e-9) << place.x;
        EXPECT_NEAR(got.y, expected.y, 1e-9) << place.x;
        const glm::dvec2 back = toLonLat(rotated, got);
        EXPECT_NEAR(back.x, place.x, 1e-9);
        EXPECT_NEAR(back.y, place.y, 1e-9);
    }
    // The rotated origin lies at 52.5 N 2.5 W for a pole at 37.5 N 177.5 E.
    const glm::dvec2 origin = toLonLat(rotated, {360.0, 0.0});
    EXPECT_NEAR(origin.x, -2.5, 1e-9);
    EXPECT_NEAR(origin.y, 52.5, 1e-9);
}

TEST(MapProjection, LambertConformalConicMatchesSnydersWorkedExample) {
    // Snyder, Map Projections: A Working Manual (USGS 1395), p. 296: Clarke 1866, standard
    // parallels 33 and 45 N, origin 23 N 96 W; 35 N 75 W is at x 1894410.9 m, y 1564649.5 m.
    const MapProjection lcc = MapProjection::forGrid(
        projectedGrid("m"),
        mapping("lambert_conformal_conic", {{"standard_parallel", {33.0, 45.0}},
                                            {"latitude_of_projection_origin", {23.0}},
                                            {"longitude_of_central_meridian", {-96.0}},
                                            {"semi_major_axis", {6378206.4}},
                                            {"inverse_flattening", {294.9786982}}}));
    ASSERT_EQ(lcc.kind(), MapProjection::Kind::Projected) << lcc.reason();
    EXPECT_FALSE(lcc.xWraps());
    const glm::dvec2 xy = toGrid(lcc, {-75.0, 35.0});
    EXPECT_NEAR(xy.x, 1894410.9, 0.5);
    EXPECT_NEAR(xy.y, 1564649.5, 0.5);
    const glm::dvec2 back = toLonLat(lcc, xy);
    EXPECT_NEAR(back.x, -75.0, 1e-8);
    EXPECT_NEAR(back.y, 35.0, 1e-8);
}

TEST(MapProjection, PolarStereographicMatchesSnydersWorkedExampleInKilometres) {
    // Snyder p. 317: International ellipsoid, true scale at 71 S, central meridian 100 W;
    // 75 S 150 E is at x -1540033.6 m, y -560526.4 m. Axes in km divide by 1000.
    const MapProjection stere = MapProjection::forGrid(
        projectedGrid("km"),
        mapping("polar_stereographic", {{"latitude_of_projection_origin", {-90.0}},
                                        {"straight_vertical_longitude_from_pole", {-100.0}},
                                        {"standard_parallel", {-71.0}},
                                        {"semi_major_axis", {6378388.0}},
                                        {"inverse_flattening", {297.0}}}));
    ASSERT_EQ(stere.kind(), MapProjection::Kind::Projected) << stere.reason();
    const glm::dvec2 xy = toGrid(stere, {150.0, -75.0});
    EXPECT_NEAR(xy.x, -1540.0336, 0.001);
    EXPECT_NEAR(xy.y, -560.5264, 0.001);
}

TEST(MapProjection, MercatorAndTransverseMercatorRoundTrip) {
    for (const auto& m :
         {mapping("mercator",
                  {{"longitude_of_projection_origin", {10.0}}, {"standard_parallel", {20.0}}}),
          mapping("transverse_mercator", {{"longitude_of_central_meridian", {-2.0}},
                                          {"latitude_of_projection_origin", {49.0}},
                                          {"scale_factor_at_central_meridian", {0.9996012717}},
                                          {"false_easting", {400000.0}},
                                          {"false_northing", {-100000.0}}})}) {
        const MapProjection p = MapProjection::forGrid(projectedGrid("m"), m);
        ASSERT_EQ(p.kind(), MapProjection::Kind::Projected) << p.reason();
        const glm::dvec2 back = toLonLat(p, toGrid(p, {1.5, 51.0}));
        EXPECT_NEAR(back.x, 1.5, 1e-8) << m.name;
        EXPECT_NEAR(back.y, 51.0, 1e-8) << m.name;
    }
}

TEST(MapProjection, SaysWhyAGridHasNoGeography) {
    const MapProjection plain = MapProjection::forGrid(projectedGrid("m"), {});
    EXPECT_EQ(plain.kind(), MapProjection::Kind::None);
    EXPECT_THAT(plain.reason(), testing::HasSubstr("are not longitude and latitude"));
    EXPECT_TRUE(std::isnan(toGrid(plain, {0.0, 0.0}).x));

    const MapProjection unknown =
        MapProjection::forGrid(projectedGrid("m"), mapping("sinusoidal", {}));
    EXPECT_EQ(unknown.kind(), MapProjection::Kind::None);
    EXPECT_THAT(unknown.reason(), testing::HasSubstr("'sinusoidal' is not one ensil reads"));

    const MapProjection incomplete = MapProjection::forGrid(
        rotatedGrid(),
        mapping("rotated_latitude_longitude", {{"grid_north_pole_latitude", {37.5}}}));
    EXPECT_EQ(incomplete.kind(), MapProjection::Kind::None);
    EXPECT_THAT(incomplete.reason(), testing::HasSubstr("'grid_north_pole_longitude'"));
}

// Lambert azimuthal equal-area (the Met Office's UK and IMPROVER grids): on a sphere, PROJ's
// result equals Snyder's formulas (24-2 to 24-4, p. 185) written out here; on an ellipsoid it
// round-trips. Albers equal-area matches Snyder's worked example (p. 292).
TEST(MapProjection, LambertAzimuthalEqualAreaMatchesSnydersSphereFormulas) {
    constexpr double kRadius = 6371229.0;  // the Met Office's sphere
    constexpr double kLat0 = 54.9, kLon0 = -2.5, kDegree = 3.14159265358979323846 / 180.0;
    const MapProjection laea = MapProjection::forGrid(
        projectedGrid("m"),
        mapping("lambert_azimuthal_equal_area", {{"latitude_of_projection_origin", {kLat0}},
                                                 {"longitude_of_projection_origin", {kLon0}},
                                                 {"false_easting", {0.0}},
                                                 {"false_northing", {0.0}},
                                                 {"earth_radius", {kRadius}}}));
    ASSERT_EQ(laea.kind(), MapProjection::Kind::Projected) << laea.reason();
    for (const glm::dvec2 lonLat : {glm::dvec2{-10.0, 50.0}, glm::dvec2{1.7, 60.2},
                                    glm::dvec2{-2.5, 54.9}, glm::dvec2{5.0, 49.0}}) {
        const double phi = lonLat.y * kDegree, lambda = (lonLat.x - kLon0) * kDegree;
        const double phi0 = kLat0 * kDegree;
        const double k = std::sqrt(2.0 / (1.0 + std::sin(phi0) * std::sin(phi) +
                                          std::cos(phi0) * std::cos(phi) * std::cos(lambda)));
        const double x = kRadius * k * std::cos(phi) * std::sin(lambda);
        const double y =
            kRadius * k *
            (std::cos(phi0) * std::sin(phi) - std::sin(phi0) * std::cos(phi) * std::cos(lambda));
        const glm::dvec2 xy = toGrid(laea, lonLat);
        EXPECT_NEAR(xy.x, x, 1e-3) << lonLat.x << " " << lonLat.y;
        EXPECT_NEAR(xy.y, y, 1e-3) << lonLat.x << " " << lonLat.y;
        const glm::dvec2 back = toLonLat(laea, xy);
        EXPECT_NEAR(back.x, lonLat.x, 1e-8);
        EXPECT_NEAR(back.y, lonLat.y, 1e-8);
    }
    // ETRS89-LAEA (EPSG:3035) on GRS 80 with its false origin: a round trip.
    const MapProjection etrs = MapProjection::forGrid(
        projectedGrid("m"),
        mapping("lambert_azimuthal_equal_area", {{"latitude_of_projection_origin", {52.0}},
                                                 {"longitude_of_projection_origin", {10.0}},
                                                 {"false_easting", {4321000.0}},
                                                 {"false_northing", {3210000.0}},
                                                 {"semi_major_axis", {6378137.0}},
                                                 {"inverse_flattening", {298.257222101}}}));
    ASSERT_EQ(etrs.kind(), MapProjection::Kind::Projected) << etrs.reason();
    const glm::dvec2 centre = toGrid(etrs, {10.0, 52.0});
    EXPECT_NEAR(centre.x, 4321000.0, 1e-6);
    EXPECT_NEAR(centre.y, 3210000.0, 1e-6);

    const MapProjection albers = MapProjection::forGrid(
        projectedGrid("m"),
        mapping("albers_conical_equal_area", {{"standard_parallel", {29.5, 45.5}},
                                              {"latitude_of_projection_origin", {23.0}},
                                              {"longitude_of_central_meridian", {-96.0}},
                                              {"semi_major_axis", {6378206.4}},
                                              {"inverse_flattening", {294.9786982}}}));
    ASSERT_EQ(albers.kind(), MapProjection::Kind::Projected) << albers.reason();
    const glm::dvec2 xy = toGrid(albers, {-75.0, 35.0});
    EXPECT_NEAR(xy.x, 1885472.7, 0.5);
    EXPECT_NEAR(xy.y, 1535925.0, 0.5);
}

// WRF output's map attributes (MAP_PROJ, TRUELAT1/2, STAND_LON, CEN_LAT, CEN_LON, DX, DY):
// small WRF-like files whose XLAT and XLONG come from the projections' inverses on WRF's sphere
// written out here after Snyder (Map Projections: A Working Manual, 1987, sections 15, 21 and
// 7), independent of PROJ; ensil's bounds and mapped points must agree with them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "data/ensemble_reader.h"
#include "geo/domain_bounds.h"
#include "geo/map_projection.h"
#include "tests/data/netcdf_test_file.h"
#include "tests/support/temp_dir.h"

using namespace ensil;

namespace {

constexpr double kR = 6370000.0;  // WRF's sphere
constexpr double kPi = std::numbers::pi;
double rad(double d) { return d * kPi / 180.0; }
double deg(double r) { return r * 180.0 / kPi; }

struct LonLat {
    double lon, lat;
};

// One projection: forward (lon, lat) -> (x, y) metres and its inverse, both written out.
struct Projection {
    std::function<glm::dvec2(LonLat)> forward;
    std::function<LonLat(glm::dvec2)> inverse;
};

// Lambert conformal conic on a sphere, Snyder (15-1) to (15-5) and (15-8) to (15-11), origin
// (lon0, lat1).
Projection lambert(double lat1, double lat2, double lon0) {
    const double p1 = rad(lat1);
    const double p2 = rad(lat2);
    const double n = lat1 == lat2
                         ? std::sin(p1)
                         : std::log(std::cos(p1) / std::cos(p2)) /
                               std::log(std::tan(kPi / 4 + p2 / 2) / std::tan(kPi / 4 + p1 / 2));
    const double f = std::cos(p1) * std::pow(std::tan(kPi / 4 + p1 / 2), n) / n;
    const double rho0 = kR * f / std::pow(std::tan(kPi / 4 + p1 / 2), n);
    return {[=](LonLat q) {
                const double rho = kR * f / std::pow(std::tan(kPi / 4 + rad(q.lat) / 2), n);
                const double theta = n * rad(q.lon - lon0);
                return glm::dvec2(rho * std::sin(theta), rho0 - rho * std::cos(theta));
            },
            [=](glm::dvec2 p) {
                const double rho = std::copysign(std::hypot(p.x, rho0 - p.y), n);
                const double theta = std::atan2(p.x, rho0 - p.y);
                return LonLat{lon0 + deg(theta / n),
                              deg(2 * std::atan(std::pow(kR * f / rho, 1 / n)) - kPi / 2)};
            }};
}

// North polar stereographic on a sphere true at latTs, Snyder (21-5) to (21-7), (20-18).
Projection polarStereographic(double latTs, double lon0) {
    const double scale = kR * (1 + std::sin(rad(latTs)));
    return {[=](LonLat q) {
                const double rho = scale * std::tan(kPi / 4 - rad(q.lat) / 2);
                return glm::dvec2(rho * std::sin(rad(q.lon - lon0)),
                                  -rho * std::cos(rad(q.lon - lon0)));
            },
            [=](glm::dvec2 p) {
                const double rho = std::hypot(p.x, p.y);
                return LonLat{lon0 + deg(std::atan2(p.x, -p.y)),
                              deg(kPi / 2 - 2 * std::atan(rho / scale))};
            }};
}

// Mercator on a sphere true at latTs, Snyder (7-1), (7-2), (7-4), (7-5).
Projection mercator(double latTs, double lon0) {
    const double r = kR * std::cos(rad(latTs));
    return {[=](LonLat q) {
                return glm::dvec2(r * rad(q.lon - lon0),
                                  r * std::log(std::tan(kPi / 4 + rad(q.lat) / 2)));
            },
            [=](glm::dvec2 p) {
                return LonLat{lon0 + deg(p.x / r), deg(2 * std::atan(std::exp(p.y / r)) - kPi / 2)};
            }};
}

// Cylindrical equidistant on WRF's sphere (MAP_PROJ 6): metres along the equator and meridians.
Projection plateCarree() {
    return {[](LonLat q) { return glm::dvec2(kR * rad(q.lon), kR * rad(q.lat)); },
            [](glm::dvec2 p) {
                return LonLat{deg(p.x / kR), deg(p.y / kR)};
            }};
}

struct WrfCase {
    int mapProj = 1;
    double truelat1 = 30, truelat2 = 60, standLon = -98, cenLat = 39, cenLon = -98;
    std::size_t nx = 40, ny = 30, nz = 5;
    double dx = 12000, dy = 12000;
    // The whole domain's mass points (WEST-EAST_GRID_DIMENSION - 1, ...; 0: the file's own) and
    // where the file's first point lies in it: a file may hold only part of its domain.
    std::size_t domainNx = 0, domainNy = 0, firstI = 0, firstJ = 0;
    bool writeXlatXlong = true;
};

struct WrfFiles {
    std::vector<std::string> paths;
    std::vector<double> xlat, xlong;  // (south_north, west_east), x fastest
};

// Three member files, each T(Time, bottom_top, south_north, west_east) with XLAT and XLONG
// from `projection` (null: filled with zeros) and WRF's global attributes as floats.
WrfFiles writeWrf(const test::TempDir& dir, const WrfCase& c, const Projection* projection) {
    WrfFiles files;
    files.xlat.assign(c.nx * c.ny, 0.0);
    files.xlong.assign(c.nx * c.ny, 0.0);
    const std::size_t domainNx = c.domainNx == 0 ? c.nx : c.domainNx;
    const std::size_t domainNy = c.domainNy == 0 ? c.ny : c.domainNy;
    if (projection != nullptr) {
        const glm::dvec2 centre = projection->forward({c.cenLon, c.cenLat});
        for (std::size_t j = 0; j < c.ny; ++j) {
            for (std::size_t i = 0; i < c.nx; ++i) {
                const double di = static_cast<double>(c.firstI + i);
                const double dj = static_cast<double>(c.firstJ + j);
                const glm::dvec2 p{
                    centre.x + (di - 0.5 * static_cast<double>(domainNx - 1)) * c.dx,
                    centre.y + (dj - 0.5 * static_cast<double>(domainNy - 1)) * c.dy};
                const LonLat q = projection->inverse(p);
                files.xlat[j * c.nx + i] = q.lat;
                files.xlong[j * c.nx + i] = std::remainder(q.lon, 360.0);
            }
        }
    }
    for (int m = 0; m < 3; ++m) {
        const std::string path = dir.file("wrfout_d01_member" + std::to_string(m) + ".nc");
        test::NcTestFile f(path);
        const int t = f.dim("Time", 1);
        const int z = f.dim("bottom_top", c.nz);
        const int y = f.dim("south_north", c.ny);
        const int x = f.dim("west_east", c.nx);
        const int xStag = f.dim("west_east_stag", c.nx + 1);
        const int lat = c.writeXlatXlong ? f.variable("XLAT", NC_FLOAT, {t, y, x}) : -1;
        const int lon = c.writeXlatXlong ? f.variable("XLONG", NC_FLOAT, {t, y, x}) : -1;
        if (c.writeXlatXlong) {
            f.text(lat, "units", "degree_north");
            f.text(lon, "units", "degree_east");
        }
        const int temperature = f.variable("T", NC_FLOAT, {t, z, y, x});
        f.text(temperature, "units", "K");
        const int wind = f.variable("U", NC_FLOAT, {t, z, y, xStag});
        f.text(wind, "units", "m s-1");
        const auto global = [&](const char* name, double value) {
            f.number(NC_GLOBAL, name, NC_FLOAT, {value});
        };
        f.number(NC_GLOBAL, "MAP_PROJ", NC_INT, {static_cast<double>(c.mapProj)});
        global("TRUELAT1", c.truelat1);
        global("TRUELAT2", c.truelat2);
        global("STAND_LON", c.standLon);
        global("CEN_LAT", c.cenLat);
        global("CEN_LON", c.cenLon);
        global("DX", c.dx);
        global("DY", c.dy);
        global("POLE_LAT", 90.0);
        global("POLE_LON", 0.0);
        f.number(NC_GLOBAL, "WEST-EAST_GRID_DIMENSION", NC_INT,
                 {static_cast<double>(domainNx + 1)});
        f.number(NC_GLOBAL, "SOUTH-NORTH_GRID_DIMENSION", NC_INT,
                 {static_cast<double>(domainNy + 1)});
        if (c.writeXlatXlong) {
            f.write(lat, files.xlat.size(), [&](std::size_t n) { return files.xlat[n]; });
            f.write(lon, files.xlong.size(), [&](std::size_t n) { return files.xlong[n]; });
        }
        const std::size_t plane = c.nx * c.ny;
        f.write(temperature, plane * c.nz, [&](std::size_t n) {
            return 280.0 + static_cast<double>(m) + std::sin(0.3 * static_cast<double>(n % c.nx)) +
                   static_cast<double>(n / plane);
        });
        f.write(wind, (c.nx + 1) * c.ny * c.nz, [&](std::size_t n) {
            return static_cast<double>(m) + std::cos(0.2 * static_cast<double>(n % (c.nx + 1)));
        });
        files.paths.push_back(path);
    }
    return files;
}

data::EnsembleDescription describe(const WrfFiles& files) {
    return data::describeEnsemble({.paths = files.paths, .variable = "T"});
}

// The largest distance in degrees (longitude scaled by cos latitude) between ensil's image of
// every grid point and XLAT/XLONG; also checks the corners and the centre one by one.
double largestError(const data::Grid& grid, const geo::MapProjection& projection,
                    const WrfFiles& files) {
    std::vector<glm::dvec2> points;
    for (std::size_t j = 0; j < grid.ny(); ++j) {
        for (std::size_t i = 0; i < grid.nx(); ++i) {
            points.emplace_back(grid.x().values[i], grid.y().values[j]);
        }
    }
    projection.toLonLat(points);
    double worst = 0.0;
    for (std::size_t n = 0; n < points.size(); ++n) {
        const double dLon =
            std::remainder(points[n].x - files.xlong[n], 360.0) * std::cos(rad(files.xlat[n]));
        worst = std::max(worst, std::hypot(dLon, points[n].y - files.xlat[n]));
    }
    const std::size_t nx = grid.nx();
    const std::size_t ny = grid.ny();
    for (const std::size_t n :
         {std::size_t{0}, nx - 1, (ny - 1) * nx, ny * nx - 1, (ny / 2) * nx + nx / 2}) {
        EXPECT_NEAR(std::remainder(points[n].x - files.xlong[n], 360.0), 0.0, 0.05) << n;
        EXPECT_NEAR(points[n].y, files.xlat[n], 0.05) << n;
    }
    return worst;
}

void expectBoundsOfXlatXlong(const geo::LonLatBounds& bounds, const WrfFiles& files) {
    const auto [latMin, latMax] = std::minmax_element(files.xlat.begin(), files.xlat.end());
    const auto [lonMin, lonMax] = std::minmax_element(files.xlong.begin(), files.xlong.end());
    EXPECT_NEAR(bounds.lonMin, *lonMin, 0.05);
    EXPECT_NEAR(bounds.lonMax, *lonMax, 0.05);
    EXPECT_NEAR(bounds.latMin, *latMin, 0.05);
    EXPECT_NEAR(bounds.latMax, *latMax, 0.05);
}

}  // namespace

namespace {
// The files' grid has this mapping, its bounds are XLAT's and XLONG's, and every point lies
// where they say.
void expectTheGridWhereXlatAndXlongSay(const WrfFiles& files, const std::string& mapping) {
    const data::EnsembleDescription d = describe(files);
    ASSERT_EQ(d.gridMapping.name, mapping);
    const geo::MapProjection map = geo::MapProjection::forGrid(d.grid, d.gridMapping);
    ASSERT_EQ(map.kind(), geo::MapProjection::Kind::Projected) << map.reason();
    const auto bounds = geo::lonLatBounds(d.grid, map);
    ASSERT_TRUE(bounds.has_value());
    expectBoundsOfXlatXlong(*bounds, files);
    const double worst = largestError(d.grid, map, files);
    EXPECT_LT(worst, 1e-4);
    std::printf("%s: largest error %.3g degrees\n", mapping.c_str(), worst);
}
}  // namespace

TEST(WrfProjection, LambertConformalGridLiesWhereItsXlatAndXlongSay) {
    const test::TempDir dir;
    const WrfCase c;
    const Projection projection = lambert(c.truelat1, c.truelat2, c.standLon);
    const WrfFiles files = writeWrf(dir, c, &projection);
    const data::EnsembleDescription d = describe(files);
    EXPECT_EQ(d.members, 3u);
    ASSERT_EQ(d.gridMapping.name, "lambert_conformal_conic");
    EXPECT_EQ(d.gridMapping.parameter("standard_parallel", 0), 30.0);
    EXPECT_EQ(d.gridMapping.parameter("standard_parallel", 1), 60.0);
    EXPECT_EQ(d.gridMapping.parameter("earth_radius"), 6370000.0);
    // The axes are map metres from the file's first point, 12 km apart.
    EXPECT_EQ(d.grid.x().units, "m");
    EXPECT_DOUBLE_EQ(d.grid.x().front(), 0.0);
    EXPECT_DOUBLE_EQ(d.grid.y().back(), 29.0 * 12000.0);
    EXPECT_DOUBLE_EQ(d.grid.z().back(), 4.0);  // bottom_top stays in indices

    const geo::MapProjection map = geo::MapProjection::forGrid(d.grid, d.gridMapping);
    ASSERT_EQ(map.kind(), geo::MapProjection::Kind::Projected) << map.reason();
    EXPECT_NE(map.projString().find("+proj=lcc"), std::string::npos);
    const auto bounds = geo::lonLatBounds(d.grid, map);
    ASSERT_TRUE(bounds.has_value());
    expectBoundsOfXlatXlong(*bounds, files);
    const double worst = largestError(d.grid, map, files);
    EXPECT_LT(worst, 1e-4);
    RecordProperty("largest_error_degrees", std::to_string(worst));
    std::printf("Lambert: largest error %.3g degrees\n", worst);
}

TEST(WrfProjection, PolarStereographicGridLiesWhereItsXlatAndXlongSay) {
    const test::TempDir dir;
    WrfCase c;
    c.mapProj = 2;
    c.truelat1 = 60;
    c.truelat2 = 90;
    c.standLon = -45;
    c.cenLat = 72;
    c.cenLon = -40;
    c.dx = c.dy = 25000;
    const Projection projection = polarStereographic(c.truelat1, c.standLon);
    const WrfFiles files = writeWrf(dir, c, &projection);
    expectTheGridWhereXlatAndXlongSay(files, "polar_stereographic");
}

TEST(WrfProjection, MercatorGridLiesWhereItsXlatAndXlongSay) {
    const test::TempDir dir;
    WrfCase c;
    c.mapProj = 3;
    c.truelat1 = 20;
    c.truelat2 = 0;
    c.standLon = 120;
    c.cenLat = 15;
    c.cenLon = 125;
    c.dx = c.dy = 30000;
    const Projection projection = mercator(c.truelat1, c.standLon);
    const WrfFiles files = writeWrf(dir, c, &projection);
    expectTheGridWhereXlatAndXlongSay(files, "mercator");
}

TEST(WrfProjection, UnrotatedLatLonGridGetsLongitudeAndLatitudeAxes) {
    const test::TempDir dir;
    WrfCase c;
    c.mapProj = 6;
    c.cenLat = 10;
    c.cenLon = 20;
    c.dx = c.dy = kR * kPi / 180.0 * 0.5;  // half a degree along the equator
    const Projection projection = plateCarree();
    const WrfFiles files = writeWrf(dir, c, &projection);
    const data::EnsembleDescription d = describe(files);
    ASSERT_EQ(d.gridMapping.name, "latitude_longitude");
    EXPECT_EQ(d.grid.x().units, "degrees_east");
    EXPECT_NEAR(d.grid.x().front(), 20.0 - 19.5 * 0.5, 1e-4);
    EXPECT_NEAR(d.grid.y().back(), 10.0 + 14.5 * 0.5, 1e-4);
    const geo::MapProjection map = geo::MapProjection::forGrid(d.grid, d.gridMapping);
    EXPECT_EQ(map.kind(), geo::MapProjection::Kind::LonLat) << map.reason();
}

namespace {
// The files' grid keeps index axes (x from 0 to nx - 1), has no geography, and the reason
// holds each phrase.
void expectIndexAxesAndAReasonSaying(const WrfFiles& files, std::size_t nx,
                                     const std::vector<std::string>& phrases) {
    const data::EnsembleDescription d = describe(files);
    EXPECT_DOUBLE_EQ(d.grid.x().front(), 0.0);
    EXPECT_DOUBLE_EQ(d.grid.x().back(), static_cast<double>(nx - 1));
    const geo::MapProjection map = geo::MapProjection::forGrid(d.grid, d.gridMapping);
    EXPECT_EQ(map.kind(), geo::MapProjection::Kind::None);
    for (const std::string& phrase : phrases) {
        EXPECT_NE(map.reason().find(phrase), std::string::npos) << map.reason();
    }
    EXPECT_FALSE(geo::lonLatBounds(d.grid, map).has_value());
}
}  // namespace

TEST(WrfProjection, AnUnknownMapProjKeepsIndicesAndSaysWhy) {
    const test::TempDir dir;
    WrfCase c;
    c.mapProj = 4;  // WRF's Gaussian grid
    const WrfFiles files = writeWrf(dir, c, nullptr);
    EXPECT_EQ(describe(files).gridMapping.name, "WRF MAP_PROJ = 4");
    expectIndexAxesAndAReasonSaying(files, c.nx, {"MAP_PROJ 1 (Lambert conformal)"});
}

// A wrfout that holds part of its domain (as WRF's split output and cropped files do): CEN_LAT
// and CEN_LON are the whole domain's centre, not the file's, so only XLAT/XLONG place it. The
// piece below lies about 290 km south-west of where the domain's centre would put it.
TEST(WrfProjection, PartOfADomainLiesWhereItsXlatAndXlongSayNotAroundTheDomainsCentre) {
    const test::TempDir dir;
    WrfCase c;
    c.truelat1 = 20;
    c.truelat2 = 30;
    c.standLon = -88;
    c.cenLat = 25;
    c.cenLon = -88;
    c.nx = c.ny = 48;
    c.domainNx = c.domainNy = 96;
    c.firstI = 2;
    c.firstJ = 5;
    const Projection projection = lambert(c.truelat1, c.truelat2, c.standLon);
    const WrfFiles files = writeWrf(dir, c, &projection);
    expectTheGridWhereXlatAndXlongSay(files, "lambert_conformal_conic");

    // U on west_east_stag: its points lie half a cell west of the mass points.
    const data::EnsembleDescription u =
        data::describeEnsemble({.paths = files.paths, .variable = "U"});
    ASSERT_EQ(u.grid.nx(), 49u);
    EXPECT_DOUBLE_EQ(u.grid.x().front(), -0.5 * c.dx);
    EXPECT_DOUBLE_EQ(u.grid.x().back(), 47.5 * c.dx);
    EXPECT_DOUBLE_EQ(u.grid.y().back(), 47.0 * c.dy);
}

// XLAT/XLONG that the map attributes cannot reproduce (here written for another central
// meridian) mean one of them is wrong: the grid is not placed on the map, and the reason names
// the point and how far off it is.
TEST(WrfProjection, XlatAndXlongThatContradictTheMapAttributesLeaveTheGridUnplacedAndSayWhy) {
    const test::TempDir dir;
    const WrfCase c;
    const Projection elsewhere = lambert(c.truelat1, c.truelat2, c.standLon + 3.0);
    const WrfFiles files = writeWrf(dir, c, &elsewhere);
    expectIndexAxesAndAReasonSaying(
        files, c.nx, {"XLAT/XLONG at point (", "cells from where its map attributes"});
}

// Without XLAT/XLONG the domain's centre places a file only when it holds the whole domain.
TEST(WrfProjection, PartOfADomainWithoutXlatAndXlongIsNotPlacedAndTheWholeDomainIs) {
    const test::TempDir dir;
    WrfCase c;
    c.writeXlatXlong = false;
    c.domainNx = 80;
    c.domainNy = 60;
    const WrfFiles part = writeWrf(dir, c, nullptr);
    expectIndexAxesAndAReasonSaying(part, c.nx, {"holds 40 x 30 points of its domain's 80 x 60"});

    const test::TempDir wholeDir;
    c.domainNx = c.domainNy = 0;
    const WrfFiles whole = writeWrf(wholeDir, c, nullptr);
    const data::EnsembleDescription w = describe(whole);
    EXPECT_DOUBLE_EQ(w.grid.x().front(), -19.5 * c.dx);  // around the domain's centre
    const geo::MapProjection wholeMap = geo::MapProjection::forGrid(w.grid, w.gridMapping);
    ASSERT_EQ(wholeMap.kind(), geo::MapProjection::Kind::Projected) << wholeMap.reason();
    std::vector<glm::dvec2> centre{{c.cenLon, c.cenLat}};
    wholeMap.toGrid(centre);
    EXPECT_NEAR(centre[0].x, 0.0, 1e-3);
    EXPECT_NEAR(centre[0].y, 0.0, 1e-3);
}

// The embedded Natural Earth lines: both scales and features are there, in range, without the
// antimeridian and pole cuts, and the coast runs where coasts are.
#include "geo/natural_earth.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <limits>

using namespace ensil::geo;

namespace {

std::size_t pointCount(const std::vector<LonLatLine>& lines) {
    std::size_t n = 0;
    for (const auto& line : lines) n += line.size();
    return n;
}

double nearestDistance(const std::vector<LonLatLine>& lines, glm::dvec2 place) {
    double nearest = std::numeric_limits<double>::infinity();
    for (const auto& line : lines) {
        for (const glm::dvec2& p : line) nearest = std::min(nearest, glm::distance(p, place));
    }
    return nearest;
}

}  // namespace

TEST(NaturalEarth, HoldsCoastlinesAndBordersAtBothScales) {
    for (const MapFeature feature : {MapFeature::Coastlines, MapFeature::Borders}) {
        const auto& coarse = naturalEarthLines(feature, MapScale::Small110m);
        const auto& medium = naturalEarthLines(feature, MapScale::Medium50m);
        EXPECT_GT(coarse.size(), 100U);
        EXPECT_GT(pointCount(medium), 3 * pointCount(coarse)) << "1:50m is the finer scale";
        for (const auto* lines : {&coarse, &medium}) {
            for (const auto& line : *lines) {
                ASSERT_GE(line.size(), 2U);
                for (const glm::dvec2& p : line) {
                    ASSERT_LE(std::abs(p.x), 180.0);
                    ASSERT_LE(std::abs(p.y), 90.0);
                }
            }
        }
    }
}

TEST(NaturalEarth, HasNoLinesAlongTheAntimeridianOrTheSouthPole) {
    for (const MapScale scale : {MapScale::Small110m, MapScale::Medium50m}) {
        for (const auto& line : naturalEarthLines(MapFeature::Coastlines, scale)) {
            for (std::size_t i = 1; i < line.size(); ++i) {
                const bool alongAntimeridian =
                    std::abs(line[i].x) > 179.99 && std::abs(line[i - 1].x) > 179.99;
                const bool alongPole = line[i].y < -89.99 && line[i - 1].y < -89.99;
                ASSERT_FALSE(alongAntimeridian || alongPole) << line[i].x << ", " << line[i].y;
            }
        }
    }
}

TEST(NaturalEarth, TheCoastRunsPastKnownCoastalPlacesAndNotThroughDeserts) {
    const auto& coast = naturalEarthLines(MapFeature::Coastlines, MapScale::Medium50m);
    EXPECT_LT(nearestDistance(coast, {18.47, -34.36}), 0.1) << "Cape of Good Hope";
    EXPECT_LT(nearestDistance(coast, {-5.61, 36.01}), 0.1) << "Tarifa, Strait of Gibraltar";
    EXPECT_LT(nearestDistance(coast, {-3.02, 58.64}), 0.1) << "Duncansby Head, Scotland";
    EXPECT_GT(nearestDistance(coast, {15.0, 23.0}), 5.0) << "central Sahara";
    EXPECT_GT(nearestDistance(coast, {-100.0, 40.0}), 5.0) << "Kansas";
}

TEST(NaturalEarth, ScaleFollowsTheDomainsExtent) {
    EXPECT_EQ(scaleForExtent(357.0), MapScale::Small110m);
    EXPECT_EQ(scaleForExtent(12.0), MapScale::Medium50m);
}

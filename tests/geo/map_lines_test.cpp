// The floor's map lines: clipping to the grid's rectangle, breaks across wraps and gaps, and
// the lines of the real ERA5 and uk_hires grids.
#include "geo/map_lines.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <set>
#include <string>

#include "data/ensemble_reader.h"
#include "tests/support/shared_data.h"

using namespace ensil;
using geo::MapLineKind;

namespace {
using test::sharedDataFile;

std::vector<std::vector<glm::dvec2>> clip(const std::vector<glm::dvec2>& line,
                                          double longestStep = 100.0) {
    std::vector<std::vector<glm::dvec2>> out;
    geo::clipToRectangle(line, {0.0, 0.0}, {10.0, 10.0}, longestStep, out);
    return out;
}

std::size_t count(const std::vector<geo::MapLine>& lines, MapLineKind kind) {
    std::size_t n = 0;
    for (const auto& l : lines) n += l.kind == kind ? 1 : 0;
    return n;
}

struct Opened {
    data::EnsembleDescription d;
    std::vector<geo::MapLine> lines;
};

Opened linesOf(const char* file, const char* memberDim = "") {
    Opened o{
        data::describeEnsemble({.paths = {sharedDataFile(file)}, .memberDimension = memberDim}),
        {}};
    o.lines = geo::mapLinesFor(o.d.grid, geo::MapProjection::forGrid(o.d.grid, o.d.gridMapping));
    return o;
}

}  // namespace

TEST(ClipToRectangle, KeepsThePartInsideAndCutsAtTheEdges) {
    const auto pieces = clip({{-5.0, 5.0}, {5.0, 5.0}, {15.0, 5.0}});
    ASSERT_EQ(pieces.size(), 1U);
    ASSERT_EQ(pieces[0].size(), 3U);
    EXPECT_EQ(pieces[0].front(), glm::dvec2(0.0, 5.0));
    EXPECT_EQ(pieces[0][1], glm::dvec2(5.0, 5.0));
    EXPECT_EQ(pieces[0].back(), glm::dvec2(10.0, 5.0));
}

TEST(ClipToRectangle, ALineThatLeavesAndReturnsIsTwoPieces) {
    const auto pieces = clip({{2.0, 5.0}, {2.0, 15.0}, {8.0, 15.0}, {8.0, 5.0}});
    ASSERT_EQ(pieces.size(), 2U);
    EXPECT_EQ(pieces[0].back(), glm::dvec2(2.0, 10.0));
    EXPECT_EQ(pieces[1].front(), glm::dvec2(8.0, 10.0));
}

TEST(ClipToRectangle, BreaksAtMissingPointsAndAcrossLongSteps) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(clip({{1.0, 1.0}, {2.0, 2.0}, {nan, nan}, {3.0, 3.0}, {4.0, 4.0}}).size(), 2U);
    // A wrap around the globe shows as a step across the whole domain.
    EXPECT_EQ(clip({{1.0, 1.0}, {9.5, 1.0}, {9.6, 2.0}}, 5.0).size(), 1U);
    EXPECT_EQ(clip({{1.0, 1.0}, {9.5, 1.0}, {9.6, 2.0}}, 5.0).front().size(), 2U);
    EXPECT_TRUE(clip({{20.0, 20.0}, {30.0, 30.0}}).empty());
}

TEST(MapLines, Era5GlobeHasCoastsAndBordersInsideItsGridAndNoGraticule) {
    const Opened era5 = linesOf("era5_eda_members.nc");
    EXPECT_GT(count(era5.lines, MapLineKind::Coastline), 100U);
    EXPECT_GT(count(era5.lines, MapLineKind::Border), 100U);
    EXPECT_EQ(count(era5.lines, MapLineKind::Graticule), 0U) << "its axes read in degrees";
    const data::Grid& g = era5.d.grid;
    for (const auto& line : era5.lines) {
        for (const glm::dvec2& p : line.points) {
            ASSERT_GE(p.x, g.x().minValue());
            ASSERT_LE(p.x, g.x().maxValue());
            ASSERT_GE(p.y, g.y().minValue());
            ASSERT_LE(p.y, g.y().maxValue());
        }
    }
}

TEST(MapLines, UkHiresRotatedGridGetsTheDetailedCoastAndATrueGraticule) {
    const Opened uk = linesOf("uk_hires.nc", "time");
    ASSERT_GT(count(uk.lines, MapLineKind::Coastline), 0U);
    EXPECT_GT(count(uk.lines, MapLineKind::Graticule), 2U);
    // Graticule lines say their true degrees; coastlines say nothing.
    std::set<std::string> labels;
    for (const auto& line : uk.lines) {
        if (line.kind == MapLineKind::Graticule) {
            labels.insert(line.label);
        } else {
            EXPECT_TRUE(line.label.empty());
        }
    }
    EXPECT_TRUE(labels.count("54\u00b0N")) << "the 54th parallel crosses the domain";
    EXPECT_TRUE(labels.count("4\u00b0W")) << "and the 4th meridian west";
    std::size_t coastPoints = 0;
    for (const auto& line : uk.lines) {
        if (line.kind == MapLineKind::Coastline) coastPoints += line.points.size();
    }
    EXPECT_GT(coastPoints, 150U) << "the 1:50m coast (1:110m has about 20 points here)";
    // Dublin Bay lies on the coast: some coastline point within 0.1 rotated degrees of it.
    std::vector<glm::dvec2> dublin{{-6.2, 53.34}};
    geo::MapProjection::forGrid(uk.d.grid, uk.d.gridMapping).toGrid(dublin);
    double nearest = std::numeric_limits<double>::infinity();
    for (const auto& line : uk.lines) {
        if (line.kind != MapLineKind::Coastline) continue;
        for (const glm::dvec2& p : line.points) {
            nearest = std::min(nearest, glm::distance(p, dublin.front()));
        }
    }
    EXPECT_LT(nearest, 0.1);
}

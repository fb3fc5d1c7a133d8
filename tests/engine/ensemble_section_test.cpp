// Maps and cross-sections (engine/ensemble_section.h, engine/section_place.h) of ensembles
// whose every value is a formula here: where a section lies, what fills it, and that each
// member's contour is exactly where its isosurface crosses the section.
#include "engine/ensemble_section.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "data/ensemble_reader.h"
#include "data/error.h"
#include "engine/section_place.h"

using namespace ensil;

namespace {

// Longitude/latitude axes (a map), pressure levels in Pa falling upward.
data::Grid lonLatGrid() {
    data::Axis plev{"plev", "Pa", "air_pressure", {100000.0, 85000.0, 50000.0, 25000.0}, false};
    data::Axis lon = data::makeUniformAxis("lon", "degrees_east", 0.0, 40.0, 41);
    lon.standardName = "longitude";
    data::Axis lat = data::makeUniformAxis("lat", "degrees_north", 30.0, 60.0, 31);
    lat.standardName = "latitude";
    return data::Grid(lon, lat, plev);
}

// Member m: the distance (in grid cells) from a centre that moves with m, plus 100 per level,
// so each member's contour at c on a level is a circle of radius c - 100 k about its centre.
glm::dvec2 centreOf(std::size_t m) { return {15.3 + 2.0 * static_cast<double>(m), 44.6}; }

data::Ensemble circles(std::size_t members) {
    data::Ensemble e;
    e.variable = "d";
    e.units = "1";
    e.grid = lonLatGrid();
    for (std::size_t m = 0; m < members; ++m) {
        data::FieldValues values(e.grid.pointCount());
        const glm::dvec2 c = centreOf(m);
        for (std::size_t k = 0; k < e.grid.nz(); ++k) {
            for (std::size_t j = 0; j < e.grid.ny(); ++j) {
                for (std::size_t i = 0; i < e.grid.nx(); ++i) {
                    const double d =
                        std::hypot(e.grid.x().values[i] - c.x, e.grid.y().values[j] - c.y);
                    values[e.grid.index(i, j, k)] =
                        static_cast<float>(d + 100.0 * static_cast<double>(k));
                }
            }
        }
        e.members.push_back({"member " + std::to_string(m), std::move(values)});
    }
    return e;
}

engine::SectionRequest mapAt(const std::string& level, float isovalue) {
    std::string problem;
    engine::SectionRequest r;
    r.place = *engine::parseLevel(level, problem);
    r.isovalue = isovalue;
    return r;
}

}  // namespace

TEST(EnsembleSection, EachMembersContourIsWhereItsSurfaceCrossesTheMap) {
    const data::Ensemble e = circles(3);
    // 500 hPa is the third level (index 2): the contour at 208 is the circle of radius 8.
    engine::SectionRequest request = mapAt("500hPa", 208.0F);
    request.memberColours = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const engine::SectionView view = engine::buildSection(e, request);
    EXPECT_EQ(view.placeText, "500 hPa");
    EXPECT_EQ(view.title, "d at 500 hPa");
    ASSERT_EQ(view.members.size(), 3U);
    for (const engine::MemberContour& c : view.members) {
        ASSERT_EQ(c.lines.size(), 1U);
        EXPECT_TRUE(c.lines[0].closed);
        EXPECT_EQ(c.colour, request.memberColours[c.member]);
        // Back from the plot's unit square to degrees: every point on the true circle.
        for (const glm::dvec2& p : c.lines[0].points) {
            const glm::dvec2 degrees{40.0 * p.x, 30.0 + 30.0 * p.y};
            EXPECT_NEAR(glm::distance(degrees, centreOf(c.member)), 8.0, 0.05);
        }
    }
    // The map keeps the data's proportions: 40 degrees across, 30 up.
    EXPECT_NEAR(view.aspect, 40.0 / 30.0, 1e-6);
}

TEST(EnsembleSection, LevelIsTakenInItsOwnUnitsAndBetweenLevelsLinearly) {
    const data::Ensemble e = circles(2);
    // 675 hPa lies halfway between 850 and 500 hPa (indices 1 and 2): 150 added to distance.
    engine::SectionRequest request = mapAt("675 hPa", 0.0F);
    request.fill = engine::SectionFill::Member;
    request.member = 1;
    const engine::SectionView view = engine::buildSection(e, request);
    ASSERT_EQ(view.fill.size(), 41U * 31U);
    const glm::dvec2 c = centreOf(1);
    const std::size_t i = 20, j = 10;  // 20 E, 40 N
    EXPECT_NEAR(view.fill[i + 41 * j], std::hypot(20.0 - c.x, 40.0 - c.y) + 150.0, 1e-3);
    // An index picks the level itself; Pa are taken as Pa.
    EXPECT_EQ(engine::buildSection(e, mapAt("index:3", 0.0F)).placeText, "level 3 (plev 25000 Pa)");
    EXPECT_EQ(engine::buildSection(e, mapAt("85000Pa", 0.0F)).placeText, "85000 Pa");
}

TEST(EnsembleSection, PlacesOutsideTheDataAreRefusedNamingTheRange) {
    const data::Ensemble e = circles(2);
    try {
        engine::buildSection(e, mapAt("1100hPa", 0.0F));
        FAIL() << "a level below the data was taken";
    } catch (const data::Error& error) {
        EXPECT_NE(std::string(error.what()).find("plev runs from 100000 to 25000"),
                  std::string::npos)
            << error.what();
    }
    EXPECT_THROW(engine::buildSection(e, mapAt("5km", 0.0F)), data::Error);  // not a pressure
    EXPECT_THROW(engine::buildSection(e, mapAt("index:4", 0.0F)), data::Error);
    std::string problem;
    engine::SectionRequest north;
    north.place = *engine::parseLatitude("75N", problem);
    try {
        engine::buildSection(e, north);
        ADD_FAILURE() << "a latitude north of the data was taken";
    } catch (const data::Error& error) {
        // The extent in true degrees, as a user would check it.
        EXPECT_NE(std::string(error.what()).find("which lie from 30°N to 60°N and from 0° to 40°E"),
                  std::string::npos)
            << error.what();
    }
    engine::SectionRequest member = mapAt("500hPa", 0.0F);
    member.fill = engine::SectionFill::Anomaly;
    member.member = 2;  // of 2
    EXPECT_THROW(engine::buildSection(e, member), data::Error);
}

TEST(EnsembleSection, CrossSectionAlongALatitudeHasEveryLevelAndTheMembersStatistics) {
    const data::Ensemble e = circles(4);
    std::string problem;
    engine::SectionRequest request;
    request.place = *engine::parseLatitude("40N", problem);
    request.isovalue = 150.0F;
    request.fill = engine::SectionFill::Spread;
    const engine::SectionView view = engine::buildSection(e, request);
    EXPECT_EQ(view.title, "d along 40°N");
    ASSERT_EQ(view.columns, 41U);  // the grid's own longitudes
    ASSERT_EQ(view.rows, 4U);
    // The sample standard deviation of the four members at 10 E, 850 hPa.
    double sum = 0, squares = 0;
    std::vector<double> values;
    for (std::size_t m = 0; m < 4; ++m) {
        values.push_back(std::hypot(10.0 - centreOf(m).x, 40.0 - centreOf(m).y) + 100.0);
        sum += values.back();
    }
    for (const double v : values) squares += (v - sum / 4) * (v - sum / 4);
    EXPECT_NEAR(view.fill[10 + 41 * 1], std::sqrt(squares / 3), 1e-3);
    EXPECT_EQ(view.fillMinimum, 0.0F);  // a spread's scale starts at 0
    // Pressure falls upward: 1000 hPa at the bottom, 250 hPa at the top.
    EXPECT_DOUBLE_EQ(view.rowPositions.front(), 0.0);
    EXPECT_DOUBLE_EQ(view.rowPositions.back(), 1.0);
    ASSERT_FALSE(view.bottom.ticks.empty());
    EXPECT_EQ(view.bottom.ticks.front().label, "0°");
    EXPECT_EQ(view.bottom.ticks.back().label, "40°E");
    ASSERT_FALSE(view.left.ticks.empty());
}

// A cross-section's pressure axis goes up as the 3D view's vertical axis does (the setting
// "vertical_axis"): 500 hPa of a 1000-250 hPa section lies at ln 2 / ln 4 of its height through
// log-pressure, at 500/750 linearly in pressure, and at the ICAO standard atmosphere's heights
// (h = T0/L (1 - (p/p0)^(R L / g)): 110.9 m, 5574.4 m and 10362.7 m) otherwise; its tick too.
TEST(EnsembleSection, APressureAxisGoesUpAsTheVerticalAxisSettingSays) {
    const data::Ensemble e = circles(2);
    const auto heightOf = [](double hPa) {
        return 288.15 / 0.0065 * (1.0 - std::pow(hPa / 1013.25, 0.190263));
    };
    const std::pair<data::VerticalAxis, double> expected[] = {
        {data::VerticalAxis::LogPressure, std::log(2.0) / std::log(4.0)},
        {data::VerticalAxis::Pressure, 500.0 / 750.0},
        {data::VerticalAxis::StandardHeight,
         (heightOf(500) - heightOf(1000)) / (heightOf(250) - heightOf(1000))},
    };
    for (const auto& [axis, position] : expected) {
        std::string problem;
        engine::SectionRequest request;
        request.place = *engine::parseLatitude("40N", problem);
        request.place.verticalAxis = axis;
        request.isovalue = 150.0F;
        const engine::SectionView view = engine::buildSection(e, request);
        ASSERT_EQ(view.rows, 4U);
        EXPECT_NEAR(view.rowPositions[2], position, 1e-3) << static_cast<int>(axis);
        const auto tick =
            std::find_if(view.left.ticks.begin(), view.left.ticks.end(),
                         [](const engine::SectionTick& t) { return t.label == "500"; });
        ASSERT_NE(tick, view.left.ticks.end());
        EXPECT_NEAR(tick->position, position, 1e-3) << static_cast<int>(axis);
    }
}

TEST(EnsembleSection, PathFollowsTheGreatCircleAndMeasuresItInKilometres) {
    const data::Ensemble e = circles(2);
    std::string problem;
    engine::SectionRequest request;
    request.place = *engine::parsePath("5,45:35,45", problem);
    request.fill = engine::SectionFill::Probability;
    request.isovalue = 120.0F;
    const engine::SectionView view = engine::buildSection(e, request);
    EXPECT_EQ(view.title, "d from 5°E 45°N to 35°E 45°N");
    EXPECT_EQ(view.fillMinimum, 0.0F);
    EXPECT_EQ(view.fillMaximum, 1.0F);
    for (const float p : view.fill) EXPECT_TRUE(p == 0.0F || p == 0.5F || p == 1.0F) << p;
    // The path's length by the spherical law of cosines (R = 6371 km), not by the haversine
    // steps the section sums: about 2,347 km, shorter than the parallel's 2,359.
    const double phi = 45.0 * std::numbers::pi / 180.0;
    const double length = 6371.0 * std::acos(std::sin(phi) * std::sin(phi) +
                                             std::cos(phi) * std::cos(phi) *
                                                 std::cos(30.0 * std::numbers::pi / 180.0));
    ASSERT_GE(view.bottom.ticks.size(), 2U);
    EXPECT_EQ(view.bottom.title, "distance along the path (km)");
    const double lastTick = std::stod(view.bottom.ticks.back().label);
    EXPECT_NEAR(view.bottom.ticks.back().position, lastTick / length, 1e-4);
    // The great circle bows poleward of the parallel: its middle lies north of 45 N.
    EXPECT_THROW(
        {
            engine::SectionRequest outside = request;
            outside.place = *engine::parsePath("5,45:55,45", problem);
            engine::buildSection(e, outside);
        },
        data::Error);
}

TEST(EnsembleSection, AnomalyIsTheMemberLessTheMeanOnAScaleCentredOnZero) {
    const data::Ensemble e = circles(3);
    engine::SectionRequest request = mapAt("index:0", 5.0F);
    request.fill = engine::SectionFill::Anomaly;
    request.member = 0;
    const engine::SectionView view = engine::buildSection(e, request);
    EXPECT_EQ(view.colourMap, engine::SectionColourMap::RdBu);
    EXPECT_FLOAT_EQ(view.fillMinimum, -view.fillMaximum);
    const std::size_t s = 7 + 41 * 12;
    const float mean =
        (e.members[0].values[s] + e.members[1].values[s] + e.members[2].values[s]) / 3;
    EXPECT_NEAR(view.fill[s], e.members[0].values[s] - mean, 1e-4);
}

// The session's colour settings reach the view: a map chosen over the fill's own, a fixed range
// over the section's values (ticks inside it), and an empty range refused before any sampling.
TEST(EnsembleSection, AChosenColourMapAndFixedRangeOverrideTheFillsOwn) {
    const data::Ensemble e = circles(3);
    engine::SectionRequest request = mapAt("index:0", 5.0F);
    request.fill = engine::SectionFill::Probability;
    EXPECT_EQ(engine::buildSection(e, request).colourMap, engine::SectionColourMap::YlGnBu);
    session::SectionsColours colours;
    colours.map = session::SectionsColourMap::Greys;
    colours.fixedRange = true;
    colours.minimum = 0.25;
    colours.maximum = 0.75;
    engine::applySectionColours(request, colours);
    const engine::SectionView view = engine::buildSection(e, request);
    EXPECT_EQ(view.colourMap, engine::SectionColourMap::Greys);
    EXPECT_FLOAT_EQ(view.fillMinimum, 0.25F);
    EXPECT_FLOAT_EQ(view.fillMaximum, 0.75F);
    ASSERT_FALSE(view.colourTicks.empty());
    for (const double t : view.colourTicks) {
        EXPECT_GE(t, 0.25);
        EXPECT_LE(t, 0.75);
    }
    // Back to automatic: the probability's own 0 to 1 and map.
    engine::applySectionColours(request, session::SectionsColours{});
    const engine::SectionView automatic = engine::buildSection(e, request);
    EXPECT_EQ(automatic.colourMap, engine::SectionColourMap::YlGnBu);
    EXPECT_FLOAT_EQ(automatic.fillMinimum, 0.0F);
    EXPECT_FLOAT_EQ(automatic.fillMaximum, 1.0F);

    request.range = std::pair{3.0, 3.0};
    try {
        engine::buildSection(e, request);
        ADD_FAILURE() << "an empty range was drawn";
    } catch (const data::Error& error) {
        EXPECT_NE(std::string(error.what()).find("the fixed colour range 3 to 3 is refused"),
                  std::string::npos)
            << error.what();
    }
}

TEST(SectionPlace, ReadsPlacesAsTyped) {
    std::string problem;
    EXPECT_EQ(engine::parseLevel("850 hPa", problem)->levelUnits, "hPa");
    EXPECT_EQ(engine::parseLevel("1500m", problem)->level, 1500.0);
    EXPECT_EQ(engine::parseLevel("index:3", problem)->levelUnits, "index");
    EXPECT_FALSE(engine::parseLevel("5 parsecs", problem));
    EXPECT_NE(problem.find("500hPa"), std::string::npos);
    EXPECT_FALSE(engine::parseLevel("index:1.5", problem));
    EXPECT_EQ(engine::parseLatitude("45S", problem)->latitude, -45.0);
    EXPECT_FALSE(engine::parseLatitude("95", problem));
    EXPECT_EQ(engine::parseLongitude("75w", problem)->longitude, -75.0);
    EXPECT_FALSE(engine::parseLongitude("10N", problem));
    const auto path = engine::parsePath("-10,50:20,40", problem);
    ASSERT_TRUE(path);
    EXPECT_EQ(path->from, glm::dvec2(-10.0, 50.0));
    EXPECT_EQ(path->to, glm::dvec2(20.0, 40.0));
    EXPECT_FALSE(engine::parsePath("-10,50", problem));
    EXPECT_FALSE(engine::parsePath("1,2:1,2", problem));
    EXPECT_EQ(engine::degreesText(-10.0, false), "10°W");
    EXPECT_EQ(engine::degreesText(190.0, false), "170°W");
    EXPECT_EQ(engine::degreesText(180.0, false), "180°");
    EXPECT_EQ(engine::degreesText(-45.5, true), "45.5°S");
    EXPECT_EQ(engine::degreesText(0.0, true), "0°");
}

TEST(EnsembleSection, ARotatedPoleMapNamesItsTrueMeridiansAndParallels) {
    // The Met Office's UK grid (rotated pole): its axes are not degrees of the Earth, so the
    // map carries a graticule of true ones, each named where it enters the map.
    data::DataSelection selection;
    selection.paths = {ENSIL_SHARED_DATA_DIR "/uk_hires.nc"};
    selection.memberDimension = "time";
    const data::Ensemble uk = data::openEnsemble(selection);
    engine::SectionRequest request;
    std::string problem;
    request.place = *engine::parseLevel("index:2", problem);
    request.fill = engine::SectionFill::None;
    request.isovalue = 290.0F;
    const engine::SectionView view = engine::buildSection(uk, request);
    ASSERT_FALSE(view.graticule.empty());
    ASSERT_FALSE(view.graticuleLabels.empty());
    bool north = false, west = false;
    for (const auto& label : view.graticuleLabels) {
        north = north || label.text.ends_with("N");
        west = west || label.text.ends_with("W");
        EXPECT_GE(label.at.x, -1e-9);
        EXPECT_LE(label.at.x, 1.0 + 1e-9);
    }
    EXPECT_TRUE(north);
    EXPECT_TRUE(west);
}

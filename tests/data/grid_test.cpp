#include "data/grid.h"

#include <gtest/gtest.h>

#include <cmath>

#include "data/error.h"

using namespace ensil::data;

namespace {
Axis axisOf(std::string name, std::vector<double> values) {
    Axis a;
    a.name = std::move(name);
    a.values = std::move(values);
    return a;
}
}  // namespace

TEST(Axis, UniformAxisIsEvenAndInclusive) {
    const Axis a = makeUniformAxis("lon", "degrees_east", -80.0, 40.0, 7);
    ASSERT_EQ(a.size(), 7u);
    EXPECT_DOUBLE_EQ(a.front(), -80.0);
    EXPECT_DOUBLE_EQ(a.back(), 40.0);
    EXPECT_DOUBLE_EQ(a.values[1] - a.values[0], 20.0);
    EXPECT_TRUE(a.isUniform());
}

TEST(Axis, PressureLevelsAreNotUniformAndDecreasingRangeIsOrdered) {
    const Axis a = axisOf("plev", {1000, 850, 700, 500, 300, 250, 200});
    EXPECT_FALSE(a.isUniform());
    EXPECT_DOUBLE_EQ(a.minValue(), 200.0);
    EXPECT_DOUBLE_EQ(a.maxValue(), 1000.0);
}

TEST(Grid, IndexIsXFastestLikeNetcdfCOrder) {
    const Grid g(makeUniformAxis("x", "", 0, 1, 4), makeUniformAxis("y", "", 0, 1, 3),
                 makeUniformAxis("z", "", 0, 1, 2));
    EXPECT_EQ(g.pointCount(), 24u);
    EXPECT_EQ(g.index(0, 0, 0), 0u);
    EXPECT_EQ(g.index(1, 0, 0), 1u);
    EXPECT_EQ(g.index(0, 1, 0), 4u);
    EXPECT_EQ(g.index(0, 0, 1), 12u);
    EXPECT_EQ(g.index(3, 2, 1), 23u);
}

TEST(Grid, RejectsSinglePointAxisNamingIt) {
    try {
        Grid g(makeUniformAxis("lon", "", 0, 1, 4), makeUniformAxis("lat", "", 0, 1, 4),
               axisOf("level", {500}));
        FAIL() << "a one-level grid was accepted";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::InvalidArgument);
        EXPECT_NE(std::string(e.what()).find("'level'"), std::string::npos) << e.what();
    }
}

TEST(Grid, RejectsNonMonotonicAxis) {
    EXPECT_THROW(Grid(axisOf("lon", {0, 1, 1, 2}), makeUniformAxis("lat", "", 0, 1, 2),
                      makeUniformAxis("z", "", 0, 1, 2)),
                 Error);
    EXPECT_THROW(Grid(axisOf("lon", {0, 2, 1}), makeUniformAxis("lat", "", 0, 1, 2),
                      makeUniformAxis("z", "", 0, 1, 2)),
                 Error);
}

TEST(Grid, SameShapeAndCoordinatesComparesValues) {
    const Grid a(makeUniformAxis("x", "", 0, 1, 4), makeUniformAxis("y", "", 0, 1, 3),
                 axisOf("z", {1000, 500}));
    const Grid same(makeUniformAxis("x", "", 0, 1, 4), makeUniformAxis("y", "", 0, 1, 3),
                    axisOf("z", {1000, 500}));
    const Grid shifted(makeUniformAxis("x", "", 0, 1, 4), makeUniformAxis("y", "", 0, 1, 3),
                       axisOf("z", {1000, 400}));
    const Grid larger(makeUniformAxis("x", "", 0, 1, 5), makeUniformAxis("y", "", 0, 1, 3),
                      axisOf("z", {1000, 500}));
    EXPECT_TRUE(a.sameShapeAndCoordinates(same));
    EXPECT_FALSE(a.sameShapeAndCoordinates(shifted));
    EXPECT_FALSE(a.sameShapeAndCoordinates(larger));
}

TEST(Grid, FewLevelsAreSaidWithWhatTheyMean) {
    const Grid two(makeUniformAxis("x", "", 0, 1, 4), makeUniformAxis("y", "", 0, 1, 3),
                   makeUniformAxis("plev", "hPa", 500, 850, 2));
    const auto warning = fewLevelsWarning(two);
    ASSERT_TRUE(warning);
    EXPECT_NE(warning->find("only 2 levels along plev"), std::string::npos) << *warning;
    EXPECT_NE(warning->find("at most 1 cell thick"), std::string::npos) << *warning;
    const Grid four(makeUniformAxis("x", "", 0, 1, 4), makeUniformAxis("y", "", 0, 1, 3),
                    makeUniformAxis("z", "", 0, 1, kFewLevels));
    EXPECT_FALSE(fewLevelsWarning(four));
}

TEST(Axis, IndexOfIsTheInverseOfValueAt) {
    // Pressure levels fall: the index still rises with them.
    const Axis levels = axisOf("plev", {1000.0, 850.0, 500.0, 250.0});
    EXPECT_DOUBLE_EQ(levels.indexOf(1000.0), 0.0);
    EXPECT_DOUBLE_EQ(levels.indexOf(500.0), 2.0);
    EXPECT_DOUBLE_EQ(levels.indexOf(675.0), 1.5);
    EXPECT_DOUBLE_EQ(levels.indexOf(250.0), 3.0);
    for (const double index : {0.25, 1.0, 1.8, 2.5}) {
        EXPECT_NEAR(levels.indexOf(levels.valueAt(index)), index, 1e-12);
    }
    const Axis lon = makeUniformAxis("lon", "degrees_east", -10.0, 10.0, 21);
    EXPECT_DOUBLE_EQ(lon.indexOf(0.5), 10.5);
    // Outside the axis there is no index, not the nearest end.
    EXPECT_TRUE(std::isnan(levels.indexOf(1013.0)));
    EXPECT_TRUE(std::isnan(lon.indexOf(10.01)));
    EXPECT_TRUE(std::isnan(lon.indexOf(std::nan(""))));
}

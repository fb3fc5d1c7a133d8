#include "preprocessing/marching_squares.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "data/error.h"

using ensil::prep::ContourLine;
using ensil::prep::contourLines;

namespace {

// f(u, v) on a columns x rows lattice, column fastest.
template <typename F>
std::vector<float> lattice(std::size_t columns, std::size_t rows, F f) {
    std::vector<float> values;
    for (std::size_t v = 0; v < rows; ++v) {
        for (std::size_t u = 0; u < columns; ++u) {
            values.push_back(static_cast<float>(f(static_cast<double>(u), static_cast<double>(v))));
        }
    }
    return values;
}

}  // namespace

TEST(MarchingSquares, CircleIsOneClosedLineOnTheTrueCircle) {
    // The distance from a point off the lattice: its contour at R is the circle of radius R.
    const double cu = 20.3, cv = 18.7, radius = 11.6;
    const auto values =
        lattice(41, 37, [&](double u, double v) { return std::hypot(u - cu, v - cv); });
    const std::vector<ContourLine> lines = contourLines(values, 41, 37, static_cast<float>(radius));
    ASSERT_EQ(lines.size(), 1U);
    EXPECT_TRUE(lines[0].closed);
    // A point on each edge the circle crosses: about 4 per unit of its length over the diagonal.
    EXPECT_GT(lines[0].points.size(), 80U);
    for (const glm::dvec2& p : lines[0].points) {
        EXPECT_NEAR(std::hypot(p.x - cu, p.y - cv), radius, 0.05);
    }
    // The line goes round: consecutive points are neighbours, never a jump across the circle.
    for (std::size_t i = 0; i < lines[0].points.size(); ++i) {
        const glm::dvec2 a = lines[0].points[i];
        const glm::dvec2 b = lines[0].points[(i + 1) % lines[0].points.size()];
        EXPECT_LT(std::hypot(a.x - b.x, a.y - b.y), 1.5);
    }
}

TEST(MarchingSquares, PlaneGivesOneOpenStraightLineAcross) {
    const auto f = [](double u, double v) { return 0.7 * u - 0.4 * v + 2.0; };
    const auto values = lattice(30, 20, f);
    const std::vector<ContourLine> lines = contourLines(values, 30, 20, 8.5F);
    ASSERT_EQ(lines.size(), 1U);
    EXPECT_FALSE(lines[0].closed);
    for (const glm::dvec2& p : lines[0].points) EXPECT_NEAR(f(p.x, p.y), 8.5, 1e-5);
    // From one side of the lattice to another.
    const auto onBorder = [](glm::dvec2 p) {
        return p.x <= 1e-9 || p.y <= 1e-9 || p.x >= 29.0 - 1e-9 || p.y >= 19.0 - 1e-9;
    };
    EXPECT_TRUE(onBorder(lines[0].points.front()));
    EXPECT_TRUE(onBorder(lines[0].points.back()));
}

TEST(MarchingSquares, TwoBumpsAreTwoLines) {
    const auto values = lattice(40, 20, [](double u, double v) {
        return std::min(std::hypot(u - 10.0, v - 10.0), std::hypot(u - 30.0, v - 10.0));
    });
    const auto lines = contourLines(values, 40, 20, 4.5F);
    ASSERT_EQ(lines.size(), 2U);
    EXPECT_TRUE(lines[0].closed);
    EXPECT_TRUE(lines[1].closed);
}

TEST(MarchingSquares, MissingValueBreaksTheLineWithoutALeap) {
    auto values = lattice(20, 10, [](double u, double) { return u; });
    values[7 + 20 * 5] = std::numeric_limits<float>::quiet_NaN();  // on the line u = 7.5
    const auto lines = contourLines(values, 20, 10, 7.5F);
    // The four cells around the missing point have no line: two pieces, above and below it.
    ASSERT_EQ(lines.size(), 2U);
    for (const ContourLine& line : lines) {
        EXPECT_FALSE(line.closed);
        for (const glm::dvec2& p : line.points) {
            EXPECT_NEAR(p.x, 7.5, 1e-6);
            EXPECT_TRUE(p.y <= 4.0 + 1e-9 || p.y >= 6.0 - 1e-9) << p.y;
        }
    }
}

TEST(MarchingSquares, SaddleFollowsTheCellCentre) {
    // Inside corners bottom-left and top-right; the centre (the mean) is 0.5.
    const std::vector<float> values{1.0F, 0.0F, 0.0F, 1.0F};  // (0,0) (1,0) (0,1) (1,1)
    // Centre inside (0.5 > 0.4): the inside corners are joined, the outside ones cut off.
    for (const ContourLine& line : contourLines(values, 2, 2, 0.4F)) {
        ASSERT_EQ(line.points.size(), 2U);
        const glm::dvec2 mid = 0.5 * (line.points[0] + line.points[1]);
        const bool nearOutsideCorner = (mid.x > 0.5 && mid.y < 0.5) || (mid.x < 0.5 && mid.y > 0.5);
        EXPECT_TRUE(nearOutsideCorner) << mid.x << ", " << mid.y;
    }
    // Centre outside (0.5 < 0.6): the inside corners are cut off.
    const auto apart = contourLines(values, 2, 2, 0.6F);
    ASSERT_EQ(apart.size(), 2U);
    for (const ContourLine& line : apart) {
        const glm::dvec2 mid = 0.5 * (line.points[0] + line.points[1]);
        const bool nearInsideCorner = (mid.x < 0.5 && mid.y < 0.5) || (mid.x > 0.5 && mid.y > 0.5);
        EXPECT_TRUE(nearInsideCorner) << mid.x << ", " << mid.y;
    }
}

TEST(MarchingSquares, RefusesValuesThatDoNotFitTheLattice) {
    const std::vector<float> values(11, 0.0F);
    EXPECT_THROW(contourLines(values, 4, 3, 0.5F), ensil::data::Error);
}

#include "preprocessing/band_envelope.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "data/error.h"
#include "fixtures.h"
#include "tests/support/special_values.h"

using namespace ensil;

namespace {
using test::kNaN;
}

TEST(BandEnvelope, LowestAndHighestOfTheListedMembersOnly) {
    // Member m is m + 10 i at point i; members 1 and 3 listed: 1 + 10 i and 3 + 10 i.
    const auto e = test::analyticEnsemble(4, 5, 2, 2, [](std::size_t m, std::size_t i, auto, auto) {
        return static_cast<float>(m) + 10.0F * static_cast<float>(i);
    });
    const std::vector<std::size_t> members{3, 1};
    const prep::BandEnvelope band = prep::computeBandEnvelope(e, members);
    ASSERT_EQ(band.lowest.size(), e.grid.pointCount());
    for (std::size_t p = 0; p < e.grid.pointCount(); ++p) {
        const float i = static_cast<float>(p % 5);
        EXPECT_EQ(band.lowest[p], 1.0F + 10.0F * i) << p;
        EXPECT_EQ(band.highest[p], 3.0F + 10.0F * i) << p;
    }
}

TEST(BandEnvelope, AMissingValueIsInsideNoIntersectionAndLeftOutOfTheUnion) {
    // Point 0: member 0 missing; point 1: both missing; point 2: member 1 infinite.
    auto e = test::analyticEnsemble(2, 4, 2, 2, [](std::size_t m, std::size_t i, auto, auto) {
        if (i == 0 && m == 0) return kNaN;
        if (i == 1) return kNaN;
        if (i == 2 && m == 1) return std::numeric_limits<float>::infinity();
        return static_cast<float>(m + 1);
    });
    const std::vector<std::size_t> members{0, 1};
    const prep::BandEnvelope band = prep::computeBandEnvelope(e, members);
    EXPECT_TRUE(std::isnan(band.lowest[0]));
    EXPECT_EQ(band.highest[0], 2.0F);
    EXPECT_TRUE(std::isnan(band.lowest[1]));
    EXPECT_TRUE(std::isnan(band.highest[1]));
    EXPECT_TRUE(std::isnan(band.lowest[2]));
    EXPECT_EQ(band.highest[2], 1.0F);
    EXPECT_EQ(band.lowest[3], 1.0F);
    EXPECT_EQ(band.highest[3], 2.0F);
}

TEST(BandEnvelope, RefusesNoMembersAndAnIndexOutOfRange) {
    const auto e = test::analyticEnsemble(2, 3, 2, 2, [](auto, auto, auto, auto) { return 1.0F; });
    EXPECT_THROW((void)prep::computeBandEnvelope(e, {}), data::Error);
    const std::vector<std::size_t> outside{0, 2};
    try {
        (void)prep::computeBandEnvelope(e, outside);
        FAIL() << "an index out of range was accepted";
    } catch (const data::Error& error) {
        EXPECT_EQ(error.kind(), data::ErrorKind::InvalidArgument);
        EXPECT_NE(std::string(error.what()).find("member index 2"), std::string::npos);
    }
}

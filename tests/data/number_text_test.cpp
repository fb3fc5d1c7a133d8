// Numbers in figures: plain decimals between 0.001 and a million, exponents only outside.
#include "data/number_text.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace ensil::data {
namespace {

TEST(ReadableNumber, PlainDecimalsWithThousandsSeparatorsBetweenAThousandthAndAMillion) {
    EXPECT_EQ(readableNumber(23690.0), "23,690");  // GFS's gh default, once "2.369e+04"
    EXPECT_EQ(readableNumber(23694.4), "23,694");  // the integer part is never rounded away
    EXPECT_EQ(readableNumber(1000.0), "1000");     // four digits: no separator (1000 hPa)
    EXPECT_EQ(readableNumber(260.0), "260");
    EXPECT_EQ(readableNumber(291.94), "291.9");
    EXPECT_EQ(readableNumber(0.06712), "0.06712");
    EXPECT_EQ(readableNumber(0.5), "0.5");
    EXPECT_EQ(readableNumber(-12.5), "-12.5");
    EXPECT_EQ(readableNumber(0.0), "0");
    EXPECT_EQ(readableNumber(999999.0), "999,999");
    EXPECT_EQ(readableNumber(-54321.0), "-54,321");
    EXPECT_EQ(readableNumber(0.001), "0.001");
    EXPECT_EQ(readableNumber(9999.7), "10,000");
}

TEST(ReadableNumber, ExponentsOnlyOutsideThatRange) {
    EXPECT_EQ(readableNumber(-1.035e-05), "-1.035e-05");
    EXPECT_EQ(readableNumber(2.5e7), "2.5e+07");
    EXPECT_EQ(readableNumber(std::numeric_limits<double>::quiet_NaN()), "NaN");
}

TEST(ReadableNumber, SignificantDigitsAreAsked) {
    EXPECT_EQ(readableNumber(3.14159265, 6), "3.14159");
    EXPECT_EQ(readableNumber(3.14159265, 2), "3.1");
    EXPECT_EQ(readableNumber(0.000123456, 3), "0.000123");
}

}  // namespace
}  // namespace ensil::data

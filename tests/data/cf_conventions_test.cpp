#include "data/cf_conventions.h"

#include <gtest/gtest.h>

using ensil::data::formatCfTime;

TEST(CfTime, DecodesUnitsSinceAnEpoch) {
    EXPECT_EQ(formatCfTime(6, "hours since 2017-1-1 00:00:00"), "2017-01-01T06:00");
    EXPECT_EQ(formatCfTime(36, "hours since 2017-01-01"), "2017-01-02T12:00");
    EXPECT_EQ(formatCfTime(59, "days since 2011-08-01 00:00:00"), "2011-09-29T00:00");
    EXPECT_EQ(formatCfTime(90, "minutes since 2009-11-19T10:00:00Z"), "2009-11-19T11:30");
    EXPECT_EQ(formatCfTime(1, "days since 2000-02-28", "proleptic_gregorian"), "2000-02-29T00:00");
}

TEST(CfTime, RefusesWhatIsNotACfTime) {
    EXPECT_FALSE(formatCfTime(3, "hours"));
    EXPECT_FALSE(formatCfTime(3, "m s-1"));
    EXPECT_FALSE(formatCfTime(3, "days since 2000-01-01", "360_day"));
    EXPECT_FALSE(formatCfTime(3, "days since 2000-13-01"));
}

TEST(Units, LengthUnits) {
    EXPECT_TRUE(ensil::data::isLengthUnit("m"));
    EXPECT_TRUE(ensil::data::isLengthUnit("km"));
    EXPECT_FALSE(ensil::data::isLengthUnit("hPa"));
}

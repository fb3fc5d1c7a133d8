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

// Every CF calendar (python3-cftime is the oracle on 10,000 random cases: tests/python).
TEST(CfTime, CountsInEveryCalendar) {
    EXPECT_EQ(formatCfTime(1, "days since 1582-10-04", "standard"), "1582-10-15T00:00");
    EXPECT_EQ(formatCfTime(1, "days since 1582-10-04", "proleptic_gregorian"), "1582-10-05T00:00");
    EXPECT_EQ(formatCfTime(1, "days since 1900-02-28", "julian"), "1900-02-29T00:00");
    EXPECT_EQ(formatCfTime(1, "days since 1900-02-28", "standard"), "1900-03-01T00:00");
    EXPECT_EQ(formatCfTime(1, "days since 2000-02-28", "noleap"), "2000-03-01T00:00");
    EXPECT_EQ(formatCfTime(1, "days since 2001-02-28", "all_leap"), "2001-02-29T00:00");
    EXPECT_EQ(formatCfTime(2, "days since 2001-02-28", "360_day"), "2001-02-30T00:00");
    EXPECT_EQ(formatCfTime(360, "days since 2001-01-01", "360_day"), "2002-01-01T00:00");
    EXPECT_EQ(formatCfTime(-1, "hours since 2000-01-01", "365_day"), "1999-12-31T23:00");
}

TEST(CfTime, RefusesWhatIsNotACfTime) {
    EXPECT_FALSE(formatCfTime(3, "hours"));
    EXPECT_FALSE(formatCfTime(3, "m s-1"));
    EXPECT_FALSE(formatCfTime(3, "days since 2000-01-01", "none"));
    EXPECT_FALSE(formatCfTime(3, "days since 2001-02-29", "standard"));
    EXPECT_FALSE(formatCfTime(3, "days since 1582-10-10", "standard")) << "a day that never was";
    EXPECT_FALSE(formatCfTime(3, "days since 2000-13-01"));
}

TEST(Units, LengthUnits) {
    EXPECT_TRUE(ensil::data::isLengthUnit("m"));
    EXPECT_TRUE(ensil::data::isLengthUnit("km"));
    EXPECT_FALSE(ensil::data::isLengthUnit("hPa"));
}

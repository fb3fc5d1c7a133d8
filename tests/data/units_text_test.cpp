// Units typeset for people (data/units_text.h): exponents become superscripts, nothing else
// changes.
#include "data/units_text.h"

#include <gtest/gtest.h>

using ensil::data::readableUnits;

TEST(UnitsText, ExponentsInEveryNotationBecomeSuperscripts) {
    EXPECT_EQ(readableUnits("m**2 s**-2"), "m\u00b2 s\u207b\u00b2");  // ERA5's geopotential
    EXPECT_EQ(readableUnits("m s-1"), "m s\u207b\u00b9");
    EXPECT_EQ(readableUnits("m^2.s^-2"), "m\u00b2 s\u207b\u00b2");
    EXPECT_EQ(readableUnits("kg kg**-1"), "kg kg\u207b\u00b9") << "not simplified to 1";
    EXPECT_EQ(readableUnits("W m-2"), "W m\u207b\u00b2");
    EXPECT_EQ(readableUnits("m2*s-10"), "m\u00b2 s\u207b\u00b9\u2070");
    EXPECT_EQ(readableUnits("kg m**+3"), "kg m\u00b3");
    EXPECT_EQ(readableUnits("m1 s"), "m s");
}

TEST(UnitsText, UnitsWithoutExponentsOrNotMadeOfSymbolsStayAsTheyAre) {
    for (const char* same : {"K", "degK", "hPa", "%", "", "1", "degrees_north", "10 m", "1.5",
                             "days since 1900-01-01 00:00:00", "m**", "s-", "(0 - 1)"}) {
        EXPECT_EQ(readableUnits(same), same);
    }
    EXPECT_EQ(readableUnits("m  s-1"), "m s\u207b\u00b9") << "one space between factors";
}

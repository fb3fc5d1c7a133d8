// The variable data open with when none is named (data/variable_choice.h): the lists of
// variables WRF, GFS and ERA5 files hold, and what a meteorologist would look at first in each.
#include "data/variable_choice.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace ensil;

namespace {
data::VariableInfo field(std::string name, std::size_t levels,
                         std::vector<std::string> dimensions = {"time", "lev", "lat", "lon"},
                         std::string longName = {}, std::string standardName = {}) {
    data::VariableInfo v;
    v.name = std::move(name);
    v.levels = levels;
    v.usable = levels > 0;
    v.dimensions = std::move(dimensions);
    v.longName = std::move(longName);
    v.standardName = std::move(standardName);
    return v;
}

std::string chosen(const std::vector<data::VariableInfo>& variables) {
    const auto index = data::chooseVariable(variables);
    return index ? variables[*index].name : std::string("(none)");
}
}  // namespace

TEST(VariableChoice, WrfOpensOnPotentialTemperatureNotOnStaggeredVerticalVelocity) {
    const std::vector<std::string> mass{"Time", "bottom_top", "south_north", "west_east"};
    const std::vector<std::string> wStag{"Time", "bottom_top_stag", "south_north", "west_east"};
    const std::vector<std::string> uStag{"Time", "bottom_top", "south_north", "west_east_stag"};
    // In wrfout's order; W has the most levels (bottom_top_stag is one longer).
    std::vector<data::VariableInfo> wrf{
        field("U", 39, uStag, "x-wind component"),
        field("W", 40, wStag, "z-wind component"),
        field("PH", 40, wStag, "perturbation geopotential"),
        field("T", 39, mass, "perturbation potential temperature theta-t0"),
        field("P", 39, mass, "perturbation pressure"),
        field("QVAPOR", 39, mass, "Water vapor mixing ratio"),
    };
    // T, P and PH are perturbations from a base state; humidity is the physical field left.
    EXPECT_EQ(chosen(wrf), "QVAPOR");
    // The potential temperature ensil derives from T (the NetCDF reader lists it last).
    wrf.push_back(field("theta", 39, mass,
                        "potential temperature, WRF's T + 300 K, derived by ensil",
                        "air_potential_temperature"));
    EXPECT_EQ(chosen(wrf), "theta");
}

TEST(VariableChoice, GfsOpensOnWindSpeedThenTemperatureNeverOnGeopotentialFirst) {
    std::vector<data::VariableInfo> gfs{field("gh", 31, {}, "Geopotential height"),
                                        field("t", 31, {}, "Temperature"),
                                        field("u", 31),
                                        field("v", 31),
                                        field("w", 31),
                                        field("r", 31, {}, "Relative humidity")};
    EXPECT_EQ(chosen(gfs), "t");
    data::VariableInfo speed = field("wind_speed", 31);
    speed.derived = true;
    gfs.push_back(speed);
    EXPECT_EQ(chosen(gfs), "wind_speed");
}

TEST(VariableChoice, ByStandardNameOrLongNameWhenTheNameSaysNothing) {
    EXPECT_EQ(data::quantityOf("var130", "air_temperature", ""), data::Quantity::Temperature);
    EXPECT_EQ(data::quantityOf("x", "", "Potential temperature"),
              data::Quantity::PotentialTemperature);
    EXPECT_EQ(data::quantityOf("TMP", "", ""), data::Quantity::Temperature);
    EXPECT_EQ(data::quantityOf("omega", "", ""), data::Quantity::VerticalVelocity);
    EXPECT_EQ(data::quantityOf("field", "", ""), data::Quantity::Other);
    // ERA5's two: temperature before geopotential.
    EXPECT_EQ(chosen({field("z", 2), field("t", 2)}), "t");
}

TEST(VariableChoice, AVolumeBeforeASheetAndUnusableOnesNever) {
    // A two-level temperature is a sheet one cell thick; a field with depth shows more.
    EXPECT_EQ(chosen({field("t", 2), field("cloud", 20)}), "cloud");
    EXPECT_EQ(chosen({field("t", 0), field("u", 5)}), "u");
    EXPECT_EQ(chosen({field("t", 0)}), "(none)");
    // Among equals, the one with the most levels, then the first in the file.
    EXPECT_EQ(chosen({field("a", 5), field("b", 9), field("c", 9)}), "b");
}

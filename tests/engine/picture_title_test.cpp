// The title line and file name a picture gets: from the real files' own variable, units,
// fixed time and member dimension.
#include "engine/picture_title.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "data/demo_ensemble.h"
#include "data/ensemble_reader.h"

using namespace ensil;

namespace {
data::Ensemble open(const char* file, const char* variable, const char* memberDim = "") {
    return data::openEnsemble({.paths = {std::string(ENSIL_SHARED_DATA_DIR "/") + file},
                               .variable = variable,
                               .memberDimension = memberDim});
}
}  // namespace

TEST(PictureTitle, SaysVariableUnitsIsovalueTimeAndMembers) {
    const data::Ensemble era5 = open("era5_eda_members.nc", "t");
    EXPECT_EQ(engine::pictureTitle(era5, 260.0F),
              "t (Temperature) [K] \u00b7 isovalue 260 K \u00b7 time 2017-01-01T00:00 \u00b7 "
              "10 members along number");
    EXPECT_EQ(engine::pictureFileStem(era5, 260.0F), "t_260K_time-2017-01-01T00-00");

    const data::Ensemble uk = open("uk_hires.nc", "air_potential_temperature", "time");
    EXPECT_EQ(engine::pictureTitle(uk, 290.5F),
              "air_potential_temperature [K] \u00b7 isovalue 290.5 K \u00b7 3 members along time");
    EXPECT_EQ(engine::pictureFileStem(uk, 290.5F), "air_potential_temperature_290.5K");
}

TEST(PictureTitle, TypesetsTheUnitsExponentsAndKeepsTheFileNameAscii) {
    // ERA5's geopotential is in "m**2 s**-2".
    const data::Ensemble era5 = open("era5_eda_members.nc", "z");
    ASSERT_EQ(era5.units, "m**2 s**-2") << "as the file writes it";
    EXPECT_EQ(engine::pictureTitle(era5, 57575.0F),
              "z (Geopotential) [m\u00b2 s\u207b\u00b2] \u00b7 isovalue 57,575 m\u00b2 "
              "s\u207b\u00b2 \u00b7 time 2017-01-01T00:00 \u00b7 10 members along number");
    EXPECT_EQ(engine::exceedanceText(era5, 57575.0F), "P(z > 57,575 m\u00b2 s\u207b\u00b2)");
    const std::string stem = engine::pictureFileStem(era5, 57575.0F);
    EXPECT_EQ(stem.substr(0, 7), "z_57575") << "no separators or exponents in a file name";
    EXPECT_TRUE(std::all_of(stem.begin(), stem.end(), [](char c) {
        return static_cast<unsigned char>(c) < 128;
    })) << stem;
}

TEST(PictureTitle, ALongNameWithParenthesesOfItsOwnIsNotNestedInOurs) {
    data::DemoEnsembleParams small;
    small.members = 3;
    small.nx = 16;
    small.ny = 8;
    small.nz = 4;
    const data::Ensemble demo = data::makeDemoEnsemble(small).ensemble;
    ASSERT_NE(demo.longName.find('('), std::string::npos) << demo.longName;
    const std::string title = engine::pictureTitle(demo, 30.0F);
    EXPECT_EQ(title.substr(0, title.find(" [")), "wind_speed: " + demo.longName);
    EXPECT_EQ(title.find("))"), std::string::npos) << title;
}

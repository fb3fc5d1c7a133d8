// The levels a selection keeps (data/level_range.h) and the units they are given in, converted
// by UDUNITS-2 (data/unit_conversion.h): parsing, choosing the layers, and reading only them
// through every path a reader is called by (whole, in parts, and a format read whole then cut).
#include "data/level_range.h"

#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "data/demo_ensemble.h"
#include "data/ensemble_part.h"
#include "data/ensemble_reader.h"
#include "data/error.h"
#include "data/netcdf_writer.h"
#include "data/unit_conversion.h"
#include "tests/data/reader_test_helpers.h"
#include "tests/support/shared_data.h"
#include "tests/support/temp_dir.h"

using namespace ensil;

namespace {

std::string errorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const data::Error& e) {
        return e.what();
    }
    return "no error";
}

data::Axis pressure() {
    data::Axis z;
    z.name = "plev";
    z.units = "Pa";
    z.values = {100000, 92500, 85000, 70000, 50000, 25000, 10000, 5000};
    z.positiveUp = false;
    return z;
}

// The layers [first, first + count) of every member of `whole`.
std::vector<float> layersOf(const data::Ensemble& whole, std::size_t first, std::size_t count) {
    const std::size_t layer = whole.grid.nx() * whole.grid.ny();
    std::vector<float> kept;
    for (const data::Member& m : whole.members) {
        kept.insert(kept.end(), m.values.begin() + static_cast<std::ptrdiff_t>(first * layer),
                    m.values.begin() + static_cast<std::ptrdiff_t>((first + count) * layer));
    }
    return kept;
}

std::vector<float> valuesOf(const data::Ensemble& e) {
    std::vector<float> all;
    for (const data::Member& m : e.members) all.insert(all.end(), m.values.begin(), m.values.end());
    return all;
}

}  // namespace

TEST(UnitConversion, ConvertsAsUdunitsDatabaseSaysAndRefusesWhatDoesNotMatch) {
    EXPECT_DOUBLE_EQ(*data::convertUnits(850.0, "hPa", "Pa"), 85000.0);
    EXPECT_DOUBLE_EQ(*data::convertUnits(850.0, "millibars", "Pa"), 85000.0);
    EXPECT_DOUBLE_EQ(*data::convertUnits(12.0, "km", "m"), 12000.0);
    EXPECT_DOUBLE_EQ(*data::convertUnits(0.0, "degC", "K"), 273.15);
    EXPECT_DOUBLE_EQ(*data::convertUnits(1.0, " kPa ", "hPa"), 10.0);
    EXPECT_EQ(data::convertUnits(850.0, "hPa", "m"), std::nullopt);
    EXPECT_EQ(data::convertUnits(3.0, "level", "Pa"), std::nullopt);
    EXPECT_TRUE(data::isKnownUnit("degrees_north"));
    EXPECT_FALSE(data::isKnownUnit("furlongz"));
    EXPECT_FALSE(data::isKnownUnit(""));
}

TEST(LevelRange, ParsesEndsAndUnitsAndSaysWhatItWants) {
    EXPECT_EQ(data::parseLevelRange("1000:100hPa"), (data::LevelRange{1000, 100, "hPa"}));
    EXPECT_EQ(data::parseLevelRange(" 1000 : 100 hPa "), (data::LevelRange{1000, 100, "hPa"}));
    EXPECT_EQ(data::parseLevelRange("0:12km"), (data::LevelRange{0, 12, "km"}));
    EXPECT_EQ(data::parseLevelRange("1000hPa:100hPa"), (data::LevelRange{1000, 100, "hPa"}));
    EXPECT_EQ(data::parseLevelRange("3:20"), (data::LevelRange{3, 20, ""}));
    EXPECT_EQ(data::parseLevelRange("-0.5:1e3 m"), (data::LevelRange{-0.5, 1000, "m"}));
    // What levelRangeText writes (projects keep it) reads back the same.
    for (const char* text : {"1000:100hPa", "0.25:12.5 km", "3:20", "85000:5e-3 Pa"}) {
        const data::LevelRange range = data::parseLevelRange(text);
        EXPECT_EQ(data::parseLevelRange(data::levelRangeText(range)), range) << text;
    }
    EXPECT_EQ(data::levelRangeText({1000, 100, "hPa"}), "1000:100 hPa");
    for (const char* bad :
         {"1000-100", "a:100", "1000:", "1000hPa:100km", "1000:100 furlongz", "nan:100"}) {
        const std::string message = errorOf([&] { (void)data::parseLevelRange(bad); });
        EXPECT_NE(message.find(std::string("'") + bad + "'"), std::string::npos) << message;
        EXPECT_NE(message.find("1000:100hPa"), std::string::npos) << message;  // the form
    }
}

TEST(LevelRange, KeepsTheLevelsWithinEitherWayRoundInAnyUnitsOfTheAxis) {
    const data::Axis z = pressure();
    using Span = std::pair<std::size_t, std::size_t>;
    const auto span = [&](const data::LevelRange& r) {
        const data::LayerSpan s = data::layersWithin(z, r, "t.nc");
        return Span(s.first, s.count);
    };
    EXPECT_EQ(span({1000, 100, "hPa"}), Span(0, 7));
    EXPECT_EQ(span({300, 850, "hPa"}), Span(2, 3));
    EXPECT_EQ(span({85000, 25000, ""}), Span(2, 4));
    EXPECT_EQ(span({850, 250, "millibar"}), Span(2, 4));
    EXPECT_EQ(span({100, 5, "kPa"}), Span(0, 8));

    // Fewer than two levels, units of another quantity, and an axis UDUNITS-2 does not know are
    // refused naming the file, the axis and its range.
    std::string message = errorOf([&] { (void)data::layersWithin(z, {900, 800, "hPa"}, "t.nc"); });
    EXPECT_NE(message.find("hold 1 level of the vertical axis 'plev' of t.nc (from 100,000 to "
                           "5000 Pa, 8 levels)"),
              std::string::npos)
        << message;
    message = errorOf([&] { (void)data::layersWithin(z, {0, 12, "km"}, "t.nc"); });
    EXPECT_NE(message.find("'km' and 'Pa' measure different things"), std::string::npos) << message;
    data::Axis model = z;
    model.name = "bottom_top";
    model.units = "level";
    message = errorOf([&] { (void)data::layersWithin(model, {1000, 100, "hPa"}, "wrfout"); });
    EXPECT_NE(message.find("whose units UDUNITS-2 does not know"), std::string::npos) << message;
}

// The demo written as NetCDF (read in parts) keeps the levels asked for, whole or slab by slab,
// with the same values as the whole read's layers; the cache key tells them apart.
TEST(LevelRange, NetcdfReadsOnlyTheLevelsKeptWholeAndInParts) {
    const test::TempDir dir;
    const std::string path = (dir.path() / "demo.nc").string();
    data::writeNetcdf(
        data::makeDemoEnsemble({.members = 3, .nx = 12, .ny = 8, .nz = 10, .seed = 5}).ensemble,
        path);
    data::DataSelection all = test::selection({path});
    const data::Ensemble whole = data::openEnsemble(all);
    // The demo's levels run from 1000 to 100 hPa, roughly evenly in log-pressure.
    data::DataSelection troposphere = all;
    troposphere.levels = data::LevelRange{850, 300, "hPa"};
    const data::LayerSpan span = data::layersWithin(whole.grid.z(), *troposphere.levels, "demo.nc");
    ASSERT_GE(span.count, 2U);
    ASSERT_LT(span.count, whole.grid.nz());

    const data::EnsembleDescription described = data::describeEnsemble(troposphere);
    EXPECT_EQ(described.grid.nz(), span.count);
    EXPECT_DOUBLE_EQ(described.grid.z().front(), whole.grid.z().values[span.first]);
    const data::Ensemble kept = data::openEnsemble(troposphere);
    EXPECT_EQ(kept.grid.z().values, described.grid.z().values);
    EXPECT_EQ(valuesOf(kept), layersOf(whole, span.first, span.count));

    // A slab of the levels kept, as the streaming passes read it: the layers further up.
    const data::Ensemble slab = data::openEnsemblePart(
        troposphere, described,
        {.firstMember = 1, .memberCount = 2, .firstLayer = 1, .layerCount = 2});
    data::Ensemble twoMembers = whole;
    twoMembers.members.erase(twoMembers.members.begin());
    EXPECT_EQ(valuesOf(slab), layersOf(twoMembers, span.first + 1, 2));
    EXPECT_DOUBLE_EQ(slab.grid.z().front(), whole.grid.z().values[span.first + 1]);

    EXPECT_NE(data::sourceIdentity(troposphere), data::sourceIdentity(all));
    troposphere.levels = data::LevelRange{900, 880, "hPa"};
    EXPECT_EQ(test::errorOpening(troposphere).kind(), data::ErrorKind::InvalidArgument);
}

// VTK is read whole: the levels kept are cut out afterwards, with the same values.
TEST(LevelRange, AFormatReadWholeIsCutToTheLevelsKept) {
    data::DataSelection all = test::selection({test::sharedDataFile("ironProt.vtk")});
    const data::Ensemble whole = data::openEnsemble(all);
    data::DataSelection middle = all;
    middle.levels = data::LevelRange{20, 30, ""};  // the volume's z in its own coordinates
    const data::LayerSpan span = data::layersWithin(whole.grid.z(), *middle.levels, "iron");
    const data::Ensemble kept = data::openEnsemble(middle);
    EXPECT_EQ(kept.grid.nz(), span.count);
    EXPECT_EQ(kept.grid.nx(), whole.grid.nx());
    EXPECT_EQ(valuesOf(kept), layersOf(whole, span.first, span.count));
}

// The GRIB reader: the ERA5 sample against its NetCDF conversion, and small GRIB files written
// here with ecCodes for each case the reader must handle (pressure levels in hPa and Pa, a
// Gaussian grid, every scanning mode, bitmaps in GRIB 2 and GRIB 1, model levels and heights,
// damaged messages, grids it refuses, wind speed).
#include <eccodes.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "data/ensemble_reader.h"
#include "data/error.h"
#include "tests/data/grib_test_file.h"
#include "tests/data/reader_test_helpers.h"
#include "tests/support/shared_data.h"
#include "tests/support/temp_dir.h"

using namespace ensil;
using test::GribField;
using test::GribKey;

namespace {

using test::sharedDataFile;

data::DataSelection select(const std::string& path, const std::string& variable = {},
                           std::size_t timeIndex = 0) {
    data::DataSelection s;
    s.paths = {path};
    s.variable = variable;
    s.timeIndex = timeIndex;
    return s;
}

bool mentions(const std::exception& e, const std::string& text) {
    return std::string(e.what()).find(text) != std::string::npos;
}

// The largest packingError ecCodes states for the messages of `shortName`: how far a decoded
// value may lie from what was packed.
double packingError(const std::string& path, const std::string& shortName) {
    std::FILE* file = std::fopen(path.c_str(), "rb");
    EXPECT_NE(file, nullptr);
    double worst = 0;
    int error = 0;
    while (codes_handle* h = codes_handle_new_from_file(nullptr, file, PRODUCT_GRIB, &error)) {
        char name[64] = {};
        std::size_t length = sizeof name;
        double e = 0;
        codes_get_string(h, "shortName", name, &length);
        if (shortName == name && codes_get_double(h, "packingError", &e) == 0) {
            worst = std::max(worst, e);
        }
        codes_handle_delete(h);
    }
    std::fclose(file);
    return worst;
}

// One message on the small grid of test::smallGrid().
GribField field(const std::string& shortName, const std::string& typeOfLevel, long level,
                long member, std::function<double(double, double)> value, long step = 0,
                std::vector<GribKey> grid = test::smallGrid()) {
    GribField f;
    f.keys = std::move(grid);
    f.keys.insert(f.keys.end(), {{"shortName", shortName},
                                 {"typeOfLevel", typeOfLevel},
                                 {"level", level},
                                 {"perturbationNumber", member},
                                 {"dataDate", 20240115L},
                                 {"dataTime", 0L},
                                 {"step", step}});
    f.value = std::move(value);
    return f;
}

std::string writeGrib(const std::string& path, const std::vector<GribField>& fields,
                      std::vector<std::size_t>* offsets = nullptr) {
    std::string bytes;
    for (const GribField& f : fields) {
        if (offsets != nullptr) offsets->push_back(bytes.size());
        bytes += test::encodeGrib(f);
    }
    test::writeBytes(path, bytes);
    return path;
}

// Checks every value of the ensemble against expected(member, lat, lon, level) (NaN: missing).
void expectValues(const data::Ensemble& e,
                  const std::function<double(std::size_t, double, double, double)>& expected,
                  double tolerance) {
    const data::Grid& g = e.grid;
    std::size_t wrong = 0;
    for (std::size_t m = 0; m < e.members.size(); ++m)
        for (std::size_t k = 0; k < g.nz(); ++k)
            for (std::size_t j = 0; j < g.ny(); ++j)
                for (std::size_t i = 0; i < g.nx(); ++i) {
                    const double want =
                        expected(m, g.y().values[j], g.x().values[i], g.z().values[k]);
                    const float got = e.members[m].values[g.index(i, j, k)];
                    // NaN expected: missing, which only NaN matches.
                    const bool same =
                        std::isnan(want) ? std::isnan(got) : std::abs(got - want) <= tolerance;
                    if (!same) {
                        if (++wrong <= 3) {
                            ADD_FAILURE() << "member " << m << " at (" << i << ", " << j << ", "
                                          << k << "): " << got << ", expected " << want;
                        }
                    }
                }
    EXPECT_EQ(wrong, 0u);
}

}  // namespace

TEST(GribReader, Era5OpensAsTheSameEnsembleAsItsNetcdfConversion) {
    const std::string grib = sharedDataFile("era5-levels-members.grib");
    const std::string nc = sharedDataFile("era5_eda_members.nc");
    for (const char* variable : {"z", "t"}) {
        const double tolerance = packingError(grib, variable);
        ASSERT_GT(tolerance, 0.0);
        for (std::size_t time = 0; time < 4; ++time) {
            SCOPED_TRACE(std::string(variable) + " at time index " + std::to_string(time));
            data::EnsembleDescription gd, nd;
            const data::Ensemble g = data::openEnsemble(select(grib, variable, time), {}, {}, &gd);
            const data::Ensemble n = data::openEnsemble(select(nc, variable, time), {}, {}, &nd);
            EXPECT_EQ(gd.format, "GRIB 1");
            EXPECT_EQ(gd.variable, nd.variable);
            EXPECT_EQ(gd.longName, nd.longName);
            EXPECT_EQ(gd.units, nd.units);
            EXPECT_EQ(gd.memberDimension, nd.memberDimension);
            EXPECT_EQ(gd.members, nd.members);
            EXPECT_EQ(gd.memberNames, nd.memberNames);
            EXPECT_EQ(gd.fixedDimensions, nd.fixedDimensions);
            ASSERT_EQ(gd.variables.size(), nd.variables.size());
            for (std::size_t v = 0; v < gd.variables.size(); ++v) {
                EXPECT_EQ(gd.variables[v].name, nd.variables[v].name);
                EXPECT_EQ(gd.variables[v].dimensions, nd.variables[v].dimensions);
                EXPECT_EQ(gd.variables[v].shape, nd.variables[v].shape);
                EXPECT_EQ(gd.variables[v].units, nd.variables[v].units);
                EXPECT_EQ(gd.variables[v].levels, nd.variables[v].levels);
            }
            for (int a = 0; a < 3; ++a) {
                const data::Axis& ga = g.grid.axis(a);
                const data::Axis& na = n.grid.axis(a);
                EXPECT_EQ(ga.name, na.name);
                EXPECT_EQ(ga.units, na.units);
                EXPECT_EQ(ga.standardName, na.standardName);
                EXPECT_EQ(ga.positiveUp, na.positiveUp);
                ASSERT_EQ(ga.size(), na.size());
                for (std::size_t i = 0; i < ga.size(); ++i) {
                    EXPECT_NEAR(ga.values[i], na.values[i], 1e-9) << ga.name << "[" << i << "]";
                }
            }
            ASSERT_EQ(g.memberCount(), n.memberCount());
            std::size_t wrong = 0;
            for (std::size_t m = 0; m < g.memberCount(); ++m) {
                EXPECT_EQ(g.members[m].name, n.members[m].name);
                ASSERT_EQ(g.members[m].values.size(), n.members[m].values.size());
                for (std::size_t p = 0; p < g.members[m].values.size(); ++p) {
                    wrong += std::abs(g.members[m].values[p] - n.members[m].values[p]) <= tolerance
                                 ? 0
                                 : 1;
                }
            }
            EXPECT_EQ(wrong, 0u) << "values further apart than the packing error " << tolerance;
            EXPECT_TRUE(g.warnings.empty());
        }
    }
}

namespace {

// One GRIB 2 message holding several fields of one grid: the first field's sections 0 to 3,
// then sections 4 to 7 once per field (as ecCodes's multi-field support writes them).
std::string multiFieldMessage(const std::vector<GribField>& fields) {
    codes_multi_handle* multi = codes_grib_multi_handle_new(nullptr);
    for (const GribField& f : fields) {
        const std::string bytes = test::encodeGrib(f);
        codes_handle* h = codes_handle_new_from_message_copy(nullptr, bytes.data(), bytes.size());
        EXPECT_NE(h, nullptr);
        EXPECT_EQ(codes_grib_multi_handle_append(h, 4, multi), 0);
        codes_handle_delete(h);
    }
    std::FILE* out = std::tmpfile();
    EXPECT_EQ(codes_grib_multi_handle_write(multi, out), 0);
    codes_grib_multi_handle_delete(multi);
    std::string message(static_cast<std::size_t>(std::ftell(out)), '\0');
    std::rewind(out);
    EXPECT_EQ(std::fread(message.data(), 1, message.size(), out), message.size());
    std::fclose(out);
    return message;
}

// Fields (not messages) as ecCodes's tools count them: grib_count with multi-field support.
long fieldsEccodesCounts(const std::string& path) {
    codes_grib_multi_support_on(nullptr);
    std::FILE* file = std::fopen(path.c_str(), "rb");
    long count = 0;
    int error = 0;
    while (codes_handle* h = codes_handle_new_from_file(nullptr, file, PRODUCT_GRIB, &error)) {
        ++count;
        codes_handle_delete(h);
    }
    codes_grib_multi_support_reset_file(nullptr, file);
    codes_grib_multi_support_off(nullptr);
    std::fclose(file);
    return count;
}

}  // namespace

// A GRIB 2 message may hold several fields (sections 4 to 7 repeated): each is read, whatever
// level or member it is, beside single-field messages in the same file.
TEST(GribReader, EveryFieldOfAMultiFieldMessageIsRead) {
    const test::TempDir dir;
    const auto value = [](std::size_t member, double hpa) {
        return [member, hpa](double lat, double lon) {
            return 100.0 * static_cast<double>(member) + hpa / 10.0 + lat * 0.1 + lon * 0.01;
        };
    };
    // Member 0 at 850 and 500 hPa and member 1 at 850 hPa in one message; member 1 at 500 hPa
    // alone after it.
    const std::string multi =
        multiFieldMessage({field("t", "isobaricInhPa", 850, 0, value(0, 850)),
                           field("t", "isobaricInhPa", 500, 0, value(0, 500)),
                           field("t", "isobaricInhPa", 850, 1, value(1, 850))});
    const std::string single = test::encodeGrib(field("t", "isobaricInhPa", 500, 1, value(1, 500)));
    const std::string path = dir.file("multi.grib2");
    test::writeBytes(path, multi + single);
    ASSERT_EQ(fieldsEccodesCounts(path), 4) << "the file must hold a message of three fields";

    data::EnsembleDescription d;
    const data::Ensemble e = data::openEnsemble(select(path), {}, {}, &d);
    EXPECT_EQ(d.memberNames, (std::vector<std::string>{"member 0", "member 1"}));
    EXPECT_EQ(e.grid.z().values, (std::vector<double>{50000, 85000}));
    expectValues(
        e,
        [&](std::size_t m, double lat, double lon, double pa) {
            return value(m, pa / 100.0)(lat, lon);
        },
        1e-3);
}

TEST(GribReader, PressureLevelsInHpaAndPaMakeOnePressureAxis) {
    const test::TempDir dir;
    const auto value = [](std::size_t member, double pa) {
        return [member, pa](double lat, double lon) {
            return 1000.0 * static_cast<double>(member) + pa / 100.0 + lat * 0.1 + lon * 0.01;
        };
    };
    std::vector<GribField> fields;
    for (long member : {1L, 0L}) {
        // Out of order on purpose: the axis is sorted by pressure, whatever the file's order.
        fields.push_back(field("t", "isobaricInPa", 50, member, value(member, 50)));
        fields.push_back(field("t", "isobaricInhPa", 850, member, value(member, 85000)));
        fields.push_back(field("t", "isobaricInPa", 100, member, value(member, 100)));
        fields.push_back(field("t", "isobaricInhPa", 500, member, value(member, 50000)));
    }
    const std::string path = writeGrib(dir.file("mixed.grib2"), fields);
    data::EnsembleDescription d;
    const data::Ensemble e = data::openEnsemble(select(path), {}, {}, &d);
    EXPECT_EQ(d.format, "GRIB 2");
    EXPECT_EQ(e.grid.z().name, "plev");
    EXPECT_EQ(e.grid.z().units, "Pa");
    EXPECT_FALSE(e.grid.z().positiveUp);
    EXPECT_EQ(e.grid.z().values, (std::vector<double>{50, 100, 50000, 85000}));
    EXPECT_EQ(d.memberNames, (std::vector<std::string>{"member 0", "member 1"}));
    expectValues(
        e, [&](std::size_t m, double lat, double lon, double pa) { return value(m, pa)(lat, lon); },
        1e-3);
}

TEST(GribReader, ModelLevelsAndHeightsAreAxesOfTheirOwnBesidePressure) {
    const test::TempDir dir;
    // t on model levels, on heights above ground and on pressure levels: three variables, each
    // with its own vertical axis, sorted whatever the file's order.
    const auto value = [](long member, double level) {
        return [member, level](double lat, double lon) {
            return 100.0 * static_cast<double>(member) + level + lat * 0.1 + lon * 0.01;
        };
    };
    std::vector<GribField> fields;
    for (long member : {0L, 1L}) {
        for (long level : {3L, 1L, 2L}) {
            fields.push_back(field("t", "hybrid", level, member, value(member, level)));
        }
        // Not 2 m: ecCodes names t there '2t', another parameter.
        for (long metres : {100L, 50L}) {
            fields.push_back(
                field("t", "heightAboveGround", metres, member, value(member, metres)));
        }
        for (long hpa : {850L, 500L}) {
            fields.push_back(field("t", "isobaricInhPa", hpa, member, value(member, hpa)));
        }
    }
    const std::string path = writeGrib(dir.file("levels.grib2"), fields);
    // Opens one variable and checks every value; perLevelUnit turns its axis's values into the
    // levels the fields were written at (Pa into hPa for pressure).
    const auto open = [&](const std::string& variable, double perLevelUnit = 1.0) {
        data::Ensemble e = data::openEnsemble(select(path, variable));
        expectValues(
            e,
            [&](std::size_t m, double lat, double lon, double z) {
                return value(static_cast<long>(m), z / perLevelUnit)(lat, lon);
            },
            1e-3);
        return e;
    };
    const data::Ensemble model = open("t_hybrid");
    EXPECT_EQ(model.grid.z().name, "hybrid");
    EXPECT_FALSE(model.grid.z().positiveUp) << "model levels count down from the top";
    EXPECT_EQ(model.grid.z().values, (std::vector<double>{1, 2, 3}));
    const data::Ensemble height = open("t_heightAboveGround");
    EXPECT_EQ(height.grid.z().name, "height");
    EXPECT_EQ(height.grid.z().units, "m");
    EXPECT_TRUE(height.grid.z().positiveUp);
    EXPECT_EQ(height.grid.z().values, (std::vector<double>{50, 100}));
    const data::Ensemble pressure = open("t_isobaric", 100.0);
    EXPECT_EQ(pressure.grid.z().name, "plev");
    EXPECT_EQ(pressure.grid.z().values, (std::vector<double>{50000, 85000}));
}

TEST(GribReader, RegularGaussianGridHasItsUnevenLatitudes) {
    const test::TempDir dir;
    const auto value = [](long member, long level) {
        return [member, level](double lat, double lon) {
            return 2.0 * lat + 0.01 * lon + static_cast<double>(member * 100 + level);
        };
    };
    const std::vector<GribKey> gaussian{{"packingType", std::string("grid_ieee")},
                                        {"productDefinitionTemplateNumber", 1L}};
    std::vector<GribField> fields;
    for (long member : {0L, 1L}) {
        for (long level : {500L, 850L}) {
            GribField f =
                field("t", "isobaricInhPa", level, member, value(member, level), 0, gaussian);
            f.sample = "regular_gg_pl_grib2";
            fields.push_back(f);
        }
    }
    const std::string path = writeGrib(dir.file("gaussian.grib2"), fields);
    const data::Ensemble e = data::openEnsemble(select(path));

    // The latitudes ecCodes gives the grid, north to south.
    codes_handle* h = codes_grib_handle_new_from_samples(nullptr, "regular_gg_pl_grib2");
    ASSERT_NE(h, nullptr);
    std::size_t n = 0;
    ASSERT_EQ(codes_get_size(h, "distinctLatitudes", &n), 0);
    std::vector<double> latitudes(n);
    ASSERT_EQ(codes_get_double_array(h, "distinctLatitudes", latitudes.data(), &n), 0);
    codes_handle_delete(h);
    std::sort(latitudes.rbegin(), latitudes.rend());

    const data::Axis& y = e.grid.y();
    ASSERT_EQ(y.size(), latitudes.size());
    EXPECT_EQ(e.grid.nx(), 128u);
    // Gaussian latitudes are unevenly spaced: not the even steps between the first and last.
    double furthest = 0;
    for (std::size_t j = 0; j < y.size(); ++j) {
        EXPECT_NEAR(y.values[j], latitudes[j], 1e-6);
        const double even = latitudes.front() + (latitudes.back() - latitudes.front()) *
                                                    static_cast<double>(j) /
                                                    static_cast<double>(y.size() - 1);
        furthest = std::max(furthest, std::abs(y.values[j] - even));
    }
    EXPECT_GT(furthest, 0.01);
    expectValues(
        e,
        [&](std::size_t m, double lat, double lon, double pa) {
            return value(static_cast<long>(m), std::lround(pa / 100))(lat, lon);
        },
        1e-3);
}

TEST(GribReader, EveryScanningModeGivesTheSameField) {
    const test::TempDir dir;
    const auto value = [](long member, long level) {
        return [member, level](double lat, double lon) {
            return lat * 10 + lon + static_cast<double>(member * 1000 + level);
        };
    };
    const auto expected = [&](std::size_t m, double lat, double lon, double pa) {
        return value(static_cast<long>(m), std::lround(pa / 100))(lat, lon);
    };
    for (int mode = 0; mode < 8; ++mode) {
        const bool iNegative = (mode & 1) != 0, jPositive = (mode & 2) != 0,
                   jConsecutive = (mode & 4) != 0;
        SCOPED_TRACE("iScansNegatively " + std::to_string(iNegative) + ", jScansPositively " +
                     std::to_string(jPositive) + ", jPointsAreConsecutive " +
                     std::to_string(jConsecutive));
        std::vector<GribField> fields;
        for (long member : {0L, 1L}) {
            for (long level : {500L, 850L}) {
                fields.push_back(field("t", "isobaricInhPa", level, member, value(member, level), 0,
                                       test::smallGrid(iNegative, jPositive, jConsecutive)));
            }
        }
        const std::string path =
            writeGrib(dir.file("mode" + std::to_string(mode) + ".grib2"), fields);
        const data::Ensemble e = data::openEnsemble(select(path));
        EXPECT_EQ(e.grid.x().values, (std::vector<double>{0, 10, 20, 30, 40, 50, 60, 70}));
        EXPECT_EQ(e.grid.y().values, (std::vector<double>{40, 30, 20, 10, 0}));
        expectValues(e, expected, 1e-3);
    }
}

TEST(GribReader, BitmapMakesNaNExactlyWhereValuesAreMissing) {
    const test::TempDir dir;
    const auto missingAt = [](double lat, double lon) {
        return (std::lround(lat / 10) + std::lround(lon / 10)) % 3 == 0;
    };
    const auto value = [&](long member) {
        return [member, missingAt](double lat, double lon) {
            return missingAt(lat, lon) ? std::nan("") : lat + lon + static_cast<double>(member);
        };
    };
    std::vector<GribField> fields;
    for (long member : {0L, 1L}) {
        for (long level : {500L, 850L}) {
            fields.push_back(field("t", "isobaricInhPa", level, member, value(member)));
        }
    }
    const std::string path = writeGrib(dir.file("bitmap.grib2"), fields);
    // The file really has a bitmap (ecCodes would otherwise have packed 9999s).
    std::FILE* file = std::fopen(path.c_str(), "rb");
    int error = 0;
    codes_handle* h = codes_handle_new_from_file(nullptr, file, PRODUCT_GRIB, &error);
    ASSERT_NE(h, nullptr);
    long bitmapPresent = 0;
    codes_get_long(h, "bitmapPresent", &bitmapPresent);
    EXPECT_EQ(bitmapPresent, 1);
    codes_handle_delete(h);
    std::fclose(file);

    const data::Ensemble e = data::openEnsemble(select(path));
    const data::Grid& g = e.grid;
    std::size_t missing = 0;
    for (std::size_t m = 0; m < 2; ++m)
        for (std::size_t k = 0; k < 2; ++k)
            for (std::size_t j = 0; j < g.ny(); ++j)
                for (std::size_t i = 0; i < g.nx(); ++i) {
                    const double lat = g.y().values[j], lon = g.x().values[i];
                    const float got = e.members[m].values[g.index(i, j, k)];
                    if (missingAt(lat, lon)) {
                        EXPECT_TRUE(std::isnan(got)) << i << ", " << j;
                        ++missing;
                    } else {
                        EXPECT_NEAR(got, lat + lon + static_cast<double>(m), 1e-4);
                    }
                }
    EXPECT_GT(missing, 0u);
    EXPECT_LT(missing, 2 * 2 * g.nx() * g.ny());
}

TEST(GribReader, AGrib1BitmapMakesNaNWhereValuesAreMissing) {
    const test::TempDir dir;
    // GRIB 1: ECMWF's local definition 1 numbers the ensemble's members.
    const auto missingAt = [](double lat, double lon) { return lat == 20.0 && lon >= 30.0; };
    std::vector<GribField> fields;
    for (long member : {0L, 1L}) {
        for (long level : {850L, 500L}) {
            GribField f;
            f.sample = "regular_ll_pl_grib1";
            f.keys = {{"setLocalDefinition", 1L},
                      {"localDefinitionNumber", 1L},
                      {"marsType", std::string("pf")},
                      {"stream", std::string("enfo")},
                      {"number", member},
                      {"numberOfForecastsInEnsemble", 10L},
                      {"shortName", std::string("t")},
                      {"typeOfLevel", std::string("isobaricInhPa")},
                      {"level", level},
                      {"dataDate", 20240115L},
                      {"Ni", 8L},
                      {"Nj", 5L},
                      {"longitudeOfFirstGridPointInDegrees", 0.0},
                      {"longitudeOfLastGridPointInDegrees", 70.0},
                      {"latitudeOfFirstGridPointInDegrees", 40.0},
                      {"latitudeOfLastGridPointInDegrees", 0.0},
                      {"iDirectionIncrementInDegrees", 10.0},
                      {"jDirectionIncrementInDegrees", 10.0},
                      {"bitsPerValue", 24L}};
            f.value = [=](double lat, double lon) {
                return missingAt(lat, lon) ? std::nan("")
                                           : lat + lon + static_cast<double>(member + level);
            };
            fields.push_back(f);
        }
    }
    const std::string path = writeGrib(dir.file("bitmap.grib1"), fields);
    data::EnsembleDescription d;
    const data::Ensemble e = data::openEnsemble(select(path), {}, {}, &d);
    EXPECT_EQ(d.format, "GRIB 1");
    EXPECT_EQ(d.memberNames, (std::vector<std::string>{"member 0", "member 1"}));
    EXPECT_EQ(e.grid.z().values, (std::vector<double>{50000, 85000}));
    std::size_t missing = 0;
    expectValues(
        e,
        [&](std::size_t m, double lat, double lon, double pa) {
            if (missingAt(lat, lon)) {
                ++missing;
                return std::nan("");
            }
            return lat + lon + static_cast<double>(m) + pa / 100.0;
        },
        1e-3);
    EXPECT_EQ(missing, 2u * 2u * 5u) << "five points of each level of each member";
}

TEST(GribReader, DamagedMessagesAreSkippedWithTheirOffsetOrRefused) {
    const test::TempDir dir;
    std::vector<GribField> fields;
    for (long step : {0L, 6L}) {
        for (long member : {0L, 1L}) {
            for (long level : {500L, 850L}) {
                fields.push_back(field(
                    "t", "isobaricInhPa", level, member,
                    [=](double lat, double lon) { return lat + lon + step; }, step));
            }
        }
    }
    std::vector<std::size_t> offsets;
    const std::string good = test::readBytes(writeGrib(dir.file("good.grib2"), fields, &offsets));
    ASSERT_EQ(offsets.size(), 8u);

    // Cut in the middle of the last message (time 1): time 0 reads, with a warning naming
    // where the cut message starts; time 1 lacks a field and is refused naming it too.
    const std::string cut = dir.file("cut.grib2");
    test::writeBytes(cut, good.substr(0, offsets[7] + (good.size() - offsets[7]) / 2));
    const std::string offset7 = "byte offset " + std::to_string(offsets[7]);
    const data::Ensemble early = data::openEnsemble(select(cut, "t", 0));
    ASSERT_EQ(early.warnings.size(), 1u);
    EXPECT_TRUE(early.warnings.front().find(offset7) != std::string::npos)
        << early.warnings.front();
    EXPECT_TRUE(early.warnings.front().find(cut) != std::string::npos) << early.warnings.front();
    const data::Error late = test::errorOpening(select(cut, "t", 1));
    EXPECT_EQ(late.kind(), data::ErrorKind::CorruptFile);
    EXPECT_TRUE(mentions(late, offset7)) << late.what();
    EXPECT_TRUE(mentions(late, "member 1 at 850 hPa")) << late.what();
    const std::string lateWords = late.what();
    EXPECT_EQ(lateWords.find(offset7), lateWords.rfind(offset7)) << "named once: " << lateWords;

    // A message whose length field is wrong (the third, time 0) is skipped, before ecCodes
    // allocates the 2 GB it claims: time 1 reads.
    std::string bytes = good;
    bytes[offsets[2] + 12] = static_cast<char>(0x7f);  // GRIB 2's 8-byte length, most significant
    const std::string damaged = dir.file("length.grib2");
    test::writeBytes(damaged, bytes);
    const data::Ensemble later = data::openEnsemble(select(damaged, "t", 1));
    ASSERT_FALSE(later.warnings.empty());
    EXPECT_TRUE(later.warnings.front().find("byte offset " + std::to_string(offsets[2])) !=
                std::string::npos)
        << later.warnings.front();
    EXPECT_TRUE(later.warnings.front().find("bytes long, but the file ends") != std::string::npos)
        << later.warnings.front();
    EXPECT_EQ(test::errorOpening(select(damaged, "t", 0)).kind(), data::ErrorKind::CorruptFile);

    // Where damaged messages leave a variable unusable (here the 500 hPa fields of a two-level
    // file, one time), the refusal names the messages skipped, not only the level that is left.
    const std::vector<GribField> twoLevels(fields.begin(), fields.begin() + 4);
    std::vector<std::size_t> twoOffsets;
    std::string levelBytes =
        test::readBytes(writeGrib(dir.file("levels.grib2"), twoLevels, &twoOffsets));
    ASSERT_EQ(twoOffsets.size(), 4u);
    levelBytes[twoOffsets[0] + 12] = static_cast<char>(0x7f);  // member 0 at 500 hPa
    levelBytes[twoOffsets[2] + 12] = static_cast<char>(0x7f);  // member 1 at 500 hPa
    const std::string oneLevelLeft = dir.file("one_level_left.grib2");
    test::writeBytes(oneLevelLeft, levelBytes);
    try {
        (void)data::describeEnsemble(select(oneLevelLeft, "t", 0));
        ADD_FAILURE() << "a file with one readable level was accepted";
    } catch (const data::Error& e) {
        EXPECT_TRUE(mentions(e, "has one level only")) << e.what();
        EXPECT_TRUE(mentions(e, "2 messages were skipped as damaged, which may be why: '" +
                                    oneLevelLeft + "', GRIB message 1 at byte offset 0 is damaged"))
            << e.what();
        EXPECT_TRUE(mentions(e, "byte offset " + std::to_string(twoOffsets[2]))) << e.what();
    }

    // A length shorter than GRIB's own first sections (ecCodes would copy them past the end of
    // the buffer it allocates) is skipped too: the fifth message, time 1.
    bytes = good;
    for (std::size_t i = 8; i < 16; ++i) bytes[offsets[4] + i] = static_cast<char>(i == 15 ? 2 : 0);
    const std::string tiny = dir.file("tiny.grib2");
    test::writeBytes(tiny, bytes);
    const data::Ensemble first = data::openEnsemble(select(tiny, "t", 0));
    ASSERT_EQ(first.warnings.size(), 1u);
    EXPECT_TRUE(first.warnings.front().find("byte offset " + std::to_string(offsets[4]) +
                                            " is damaged (it says it is 2 bytes long") !=
                std::string::npos)
        << first.warnings.front();

    // Bytes flipped anywhere: an ensemble or a data::Error, never anything else.
    std::mt19937 random(17);
    for (int trial = 0; trial < 60; ++trial) {
        std::string flipped = good;
        const int flips = 1 + trial % 6;
        for (int f = 0; f < flips; ++f) {
            const std::size_t at = random() % flipped.size();
            flipped[at] = static_cast<char>(flipped[at] ^ static_cast<char>(1 + random() % 255));
        }
        const std::string path = dir.file("flipped.grib2");
        test::writeBytes(path, flipped);
        for (std::size_t time : {0u, 1u}) {
            try {
                const data::Ensemble e = data::openEnsemble(select(path, {}, time));
                for (const data::Member& m : e.members) {
                    ASSERT_EQ(m.values.size(), e.grid.pointCount());
                }
            } catch (const data::Error&) {
                // a clear refusal is fine
            }
        }
    }
}

// Complex packing (templates 5.2 and 5.3, NCEP's GFS and GEFS files) reads, and a message whose
// group count is damaged is skipped before ecCodes decodes it: ecCodes 2.28 would walk the
// groups past the end of the message and crash the program.
TEST(GribReader, ComplexPackingReadsAndADamagedGroupCountIsSkippedNotDecoded) {
    for (const std::string packing : {"grid_complex", "grid_complex_spatial_differencing"}) {
        SCOPED_TRACE(packing);
        const test::TempDir dir;
        std::vector<GribField> fields;
        for (long step : {0L, 6L}) {
            for (long member : {0L, 1L}) {
                for (long level : {500L, 850L}) {
                    // Simple packing at 16 bits and 0.01 K first: complex packing keeps them.
                    std::vector<GribKey> grid = test::smallGrid();
                    grid.front() = {"packingType", std::string("grid_simple")};
                    grid.emplace_back("bitsPerValue", 16L);
                    grid.emplace_back("decimalScaleFactor", 2L);
                    fields.push_back(field(
                        "t", "isobaricInhPa", level, member,
                        [=](double lat, double lon) {
                            return 250.0 + lat + lon / 8 + member + step;
                        },
                        step, grid));
                    fields.back().packingOfValues = packing;
                }
            }
        }
        std::vector<std::size_t> offsets;
        const std::string path = writeGrib(dir.file("complex.grib2"), fields, &offsets);
        const data::Ensemble e = data::openEnsemble(select(path, "t", 0));
        EXPECT_TRUE(e.warnings.empty());
        expectValues(
            e,
            [](std::size_t m, double lat, double lon, double) { return 250.0 + lat + lon / 8 + m; },
            packingError(path, "t") + 1e-4);

        // The fifth message (time 1, member 0, 500 hPa) says its values form 2^32 - 16 groups.
        std::string bytes = test::readBytes(path);
        codes_handle* h = codes_handle_new_from_message(nullptr, bytes.data() + offsets[4],
                                                        offsets[5] - offsets[4]);
        ASSERT_NE(h, nullptr);
        long section5 = 0;
        ASSERT_EQ(codes_get_long(h, "offsetSection5", &section5), 0);
        codes_handle_delete(h);
        for (std::size_t i = 0; i < 4; ++i) {
            bytes[offsets[4] + static_cast<std::size_t>(section5) + 31 + i] =
                static_cast<char>(i == 3 ? 0xf0 : 0xff);
        }
        const std::string damaged = dir.file("damaged.grib2");
        test::writeBytes(damaged, bytes);
        const data::Ensemble early = data::openEnsemble(select(damaged, "t", 0));
        ASSERT_EQ(early.warnings.size(), 1u);
        const std::string& warning = early.warnings.front();
        EXPECT_NE(warning.find("byte offset " + std::to_string(offsets[4]) + " is damaged"),
                  std::string::npos)
            << warning;
        EXPECT_NE(warning.find("form 4294967280 groups"), std::string::npos) << warning;
        const data::Error late = test::errorOpening(select(damaged, "t", 1));
        EXPECT_TRUE(mentions(late, "member 0 at 500 hPa")) << late.what();
    }
}

TEST(GribReader, ReducedGaussianAndSphericalHarmonicsAreRefusedWithARegridCommand) {
    const test::TempDir dir;
    for (const auto& [sample, command] :
         {std::pair<std::string, std::string>{"reduced_gg_pl_32_grib2", "cdo setgridtype,regular"},
          {"sh_pl_grib2", "cdo sp2gp"}}) {
        std::vector<GribField> fields;
        for (long member : {0L, 1L}) {
            for (long level : {500L, 850L}) {
                GribField f;
                f.sample = sample;
                f.keys = {{"productDefinitionTemplateNumber", 1L},
                          {"perturbationNumber", member},
                          {"typeOfLevel", std::string("isobaricInhPa")},
                          {"level", level}};
                fields.push_back(f);
            }
        }
        const std::string path = writeGrib(dir.file(sample + ".grib2"), fields);
        const data::Error e = test::errorOpening(select(path));
        EXPECT_EQ(e.kind(), data::ErrorKind::UnsupportedFormat) << e.what();
        EXPECT_TRUE(mentions(e, command + " " + path)) << e.what();
    }
}

TEST(GribReader, WindSpeedFromUAndVOnTheirCommonLevels) {
    const test::TempDir dir;
    const auto u = [](long member, long level) {
        return
            [=](double lat, double lon) { return lat - lon + static_cast<double>(member + level); };
    };
    const auto v = [](long member, long level) {
        return [=](double lat, double lon) {
            return 0.5 * lon - 0.2 * lat + static_cast<double>(level - member);
        };
    };
    const auto write = [&](const std::string& name, std::vector<long> uLevels,
                           std::vector<long> vLevels) {
        std::vector<GribField> fields;
        for (long member : {0L, 1L}) {
            for (long level : uLevels)
                fields.push_back(field("u", "isobaricInhPa", level, member, u(member, level)));
            for (long level : vLevels)
                fields.push_back(field("v", "isobaricInhPa", level, member, v(member, level)));
        }
        return writeGrib(dir.file(name), fields);
    };
    const std::string path = write("uv.grib2", {850, 700, 500}, {850, 500, 300});
    data::EnsembleDescription d;
    const data::Ensemble e = data::openEnsemble(select(path, "wind_speed"), {}, {}, &d);
    EXPECT_EQ(e.grid.z().values, (std::vector<double>{50000, 85000}));
    EXPECT_EQ(e.units, "m s**-1");
    const auto speed = d.variables.back();
    EXPECT_EQ(speed.name, "wind_speed");
    EXPECT_TRUE(speed.derived);
    EXPECT_EQ(speed.levels, 2u);
    expectValues(
        e,
        [&](std::size_t m, double lat, double lon, double pa) {
            const long member = static_cast<long>(m), level = std::lround(pa / 100);
            return std::hypot(u(member, level)(lat, lon), v(member, level)(lat, lon));
        },
        1e-3);

    const std::string apart = write("apart.grib2", {850, 700}, {500, 300});
    const data::Error error = test::errorOpening(select(apart, "wind_speed"));
    EXPECT_EQ(error.kind(), data::ErrorKind::NotThreeDimensional);
    EXPECT_TRUE(mentions(error, "at least two common levels")) << error.what();
    EXPECT_TRUE(mentions(error, "700 hPa")) << error.what();
}

TEST(GribReader, ForecastStepsAreTimesThatCanStandInForMembers) {
    const test::TempDir dir;
    // One forecast (no ensemble template, so no 'number'), 3 steps from 2024-01-15 00:00
    // (the last crossing a day), 2 levels.
    std::vector<GribField> fields;
    for (long step : {30L, 6L, 12L}) {
        for (long level : {500L, 850L}) {
            GribField f = field(
                "t", "isobaricInhPa", level, 0,
                [=](double lat, double lon) { return lat + lon + static_cast<double>(step); },
                step);
            std::erase_if(f.keys, [](const GribKey& k) {
                return k.first == "productDefinitionTemplateNumber" ||
                       k.first == "numberOfForecastsInEnsemble" || k.first == "perturbationNumber";
            });
            fields.push_back(f);
        }
    }
    const std::string path = writeGrib(dir.file("forecast.grib2"), fields);
    const data::Error alone = test::errorOpening(select(path));
    EXPECT_EQ(alone.kind(), data::ErrorKind::MemberDimensionNotFound) << alone.what();
    EXPECT_EQ(alone.choices(), std::vector<std::string>{"time"});

    data::DataSelection byTime = select(path);
    byTime.memberDimension = "time";
    data::EnsembleDescription d;
    const data::Ensemble e = data::openEnsemble(byTime, {}, {}, &d);
    EXPECT_EQ(d.memberNames, (std::vector<std::string>{"2024-01-15T06:00", "2024-01-15T12:00",
                                                       "2024-01-16T06:00"}));
    EXPECT_EQ(d.fixedDimensions, std::vector<std::string>{"number = 0 of 1 (member 0)"});
    // cfgrib's names for the same axis (xarray users type them) take the same members.
    for (const char* cfgrib : {"step", "valid_time"}) {
        data::DataSelection asCfgrib = select(path);
        asCfgrib.memberDimension = cfgrib;
        data::EnsembleDescription named;
        data::openEnsemble(asCfgrib, {}, {}, &named);
        EXPECT_EQ(named.memberNames, d.memberNames) << cfgrib;
        EXPECT_EQ(named.memberDimension, "time") << cfgrib;
    }
    const std::vector<double> steps{6, 12, 30};
    expectValues(
        e, [&](std::size_t m, double lat, double lon, double) { return lat + lon + steps[m]; },
        1e-3);

    // Three times: index 3 is past their end.
    const data::Error past = test::errorOpening(select(path, "t", 3));
    EXPECT_EQ(past.kind(), data::ErrorKind::InvalidArgument);
    EXPECT_TRUE(mentions(past, "dimension 'time'")) << past.what();
}

TEST(GribReader, OneFilePerMemberIsNamedByItsFiles) {
    const test::TempDir dir;
    std::vector<std::string> paths;
    for (long run : {1L, 2L, 3L}) {
        std::vector<GribField> fields;
        for (long level : {500L, 850L}) {
            GribField f = field("t", "isobaricInhPa", level, 0, [=](double lat, double lon) {
                return lat + lon + static_cast<double>(run);
            });
            std::erase_if(f.keys, [](const GribKey& k) {
                return k.first == "productDefinitionTemplateNumber" ||
                       k.first == "numberOfForecastsInEnsemble" || k.first == "perturbationNumber";
            });
            fields.push_back(f);
        }
        paths.push_back(writeGrib(dir.file("run_0" + std::to_string(run) + ".grib2"), fields));
    }
    data::DataSelection s;
    s.paths = paths;
    data::EnsembleDescription d;
    const data::Ensemble e = data::openEnsemble(s, {}, {}, &d);
    EXPECT_EQ(d.memberNames, (std::vector<std::string>{"run_01", "run_02", "run_03"}));
    EXPECT_EQ(d.memberDimensionReason, "one file per member");
    expectValues(
        e,
        [](std::size_t m, double lat, double lon, double) {
            return lat + lon + static_cast<double>(m + 1);
        },
        1e-3);
}

// `ensil stats`: the statistics file it writes, checked field by field against values worked
// out here from the input as ensil reads it, and every refusal of a bad argument.
#include "cli/stats_command.h"

#include <gtest/gtest.h>
#include <netcdf.h>

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "data/demo_ensemble.h"
#include "data/ensemble_reader.h"
#include "data/netcdf_writer.h"
#include "tests/app/ensil_run.h"
#include "tests/support/temp_dir.h"

using namespace ensil;
using ensil::test::kEra5;

namespace {

// The statistics at one point, worked out here from the members' values the plain way
// (two passes, sample standard deviation), over the members listed.
struct PointStatistics {
    double count = 0, mean = NAN, stddev = NAN, minimum = NAN, maximum = NAN, range = NAN,
           exceedance = NAN;
};
PointStatistics statisticsAt(const data::Ensemble& e, const std::vector<std::size_t>& members,
                             std::size_t p, float c) {
    std::vector<double> values;
    for (const std::size_t m : members) {
        const float v = e.members[m].values[p];
        if (std::isfinite(v)) values.push_back(v);
    }
    PointStatistics s;
    s.count = static_cast<double>(values.size());
    if (values.empty()) return s;
    double sum = 0;
    int above = 0;
    for (const double v : values) {
        sum += v;
        above += v > c ? 1 : 0;
    }
    s.mean = sum / s.count;
    if (values.size() >= 2) {
        double squares = 0;
        for (const double v : values) squares += (v - s.mean) * (v - s.mean);
        s.stddev = std::sqrt(squares / (s.count - 1));
    }
    s.minimum = *std::min_element(values.begin(), values.end());
    s.maximum = *std::max_element(values.begin(), values.end());
    s.range = s.maximum - s.minimum;
    s.exceedance = above / s.count;
    return s;
}

// The share of the members with 8 finite corners at cell (i, j, k) whose corners lie on both
// sides of c; NaN when none has 8.
double levelCrossingAt(const data::Ensemble& e, const std::vector<std::size_t>& members,
                       std::size_t i, std::size_t j, std::size_t k, float c) {
    int valid = 0, crossing = 0;
    for (const std::size_t m : members) {
        bool finite = true, above = false, below = false;
        for (int corner = 0; corner < 8; ++corner) {
            const float v = e.members[m].values[e.grid.index(
                i + (corner & 1), j + ((corner >> 1) & 1), k + ((corner >> 2) & 1))];
            finite = finite && std::isfinite(v);
            above = above || v > c;
            below = below || v <= c;
        }
        if (!finite) continue;
        ++valid;
        crossing += above && below ? 1 : 0;
    }
    return valid == 0 ? NAN : static_cast<double>(crossing) / valid;
}

// The output file, through the netCDF C API.
class StatsFile {
public:
    explicit StatsFile(const std::string& path) {
        EXPECT_EQ(nc_open(path.c_str(), NC_NOWRITE, &m_id), NC_NOERR) << path;
    }
    StatsFile(const StatsFile&) = delete;
    StatsFile& operator=(const StatsFile&) = delete;
    ~StatsFile() {
        if (m_id >= 0) nc_close(m_id);
    }
    [[nodiscard]] int var(const char* name) const {
        int id = -1;
        EXPECT_EQ(nc_inq_varid(m_id, name, &id), NC_NOERR) << name;
        return id;
    }
    [[nodiscard]] std::vector<float> floats(const char* name, std::size_t n) const {
        std::vector<float> values(n, -12345.0F);
        EXPECT_EQ(nc_get_var_float(m_id, var(name), values.data()), NC_NOERR) << name;
        return values;
    }
    [[nodiscard]] std::vector<double> doubles(const char* name) const {
        const int id = var(name);
        int dim = -1;
        nc_inq_vardimid(m_id, id, &dim);
        std::size_t n = 0;
        nc_inq_dimlen(m_id, dim, &n);
        std::vector<double> values(n);
        EXPECT_EQ(nc_get_var_double(m_id, id, values.data()), NC_NOERR) << name;
        return values;
    }
    [[nodiscard]] std::string text(const char* var, const char* name) const {
        const int id = std::string(var).empty() ? NC_GLOBAL : this->var(var);
        std::size_t length = 0;
        if (nc_inq_attlen(m_id, id, name, &length) != NC_NOERR) return "<missing>";
        std::string value(length, '\0');
        nc_get_att_text(m_id, id, name, value.data());
        return value;
    }
    // The names and sizes of a variable's dimensions, in storage order.
    [[nodiscard]] std::vector<std::pair<std::string, std::size_t>> dims(const char* name) const {
        int ndims = 0;
        std::array<int, NC_MAX_VAR_DIMS> ids{};
        nc_inq_var(m_id, var(name), nullptr, nullptr, &ndims, ids.data(), nullptr);
        std::vector<std::pair<std::string, std::size_t>> result;
        for (int d = 0; d < ndims; ++d) {
            std::array<char, NC_MAX_NAME + 1> dimName{};
            std::size_t size = 0;
            nc_inq_dim(m_id, ids[static_cast<std::size_t>(d)], dimName.data(), &size);
            result.emplace_back(dimName.data(), size);
        }
        return result;
    }

private:
    int m_id = -1;
};

// Checks a float from the file against a value worked out in double: NaN for NaN, else
// within float rounding.
void expectClose(float actual, double expected, const std::string& what) {
    if (std::isnan(expected)) {
        EXPECT_TRUE(std::isnan(actual)) << what << ": " << actual;
    } else {
        EXPECT_NEAR(actual, expected, 2e-6 * std::max(1.0, std::abs(expected))) << what;
    }
}

struct Fields {
    std::vector<float> count, mean, stddev, minimum, maximum, range, exceedance, crossing;
};
Fields readFields(const StatsFile& file, const data::Grid& g) {
    const std::size_t n = g.pointCount();
    return {file.floats("member_count", n),
            file.floats("mean", n),
            file.floats("stddev", n),
            file.floats("min", n),
            file.floats("max", n),
            file.floats("range", n),
            file.floats("exceedance_probability", n),
            file.floats("level_crossing_probability", (g.nx() - 1) * (g.ny() - 1) * (g.nz() - 1))};
}

// Every point's fields and every cell's level crossing against the values worked out here.
// Returns how many points have 0 < P(f > c) < 1 and how many cells 0 < crossing < 1, so a
// caller can make sure the isovalue tested something.
std::pair<int, int> expectFieldsMatch(const Fields& f, const data::Ensemble& e,
                                      const std::vector<std::size_t>& members, float c) {
    const data::Grid& g = e.grid;
    int mixedPoints = 0, mixedCells = 0;
    for (std::size_t p = 0; p < g.pointCount(); ++p) {
        const PointStatistics s = statisticsAt(e, members, p, c);
        const std::string at = " at point " + std::to_string(p);
        expectClose(f.count[p], s.count, "member_count" + at);
        expectClose(f.mean[p], s.mean, "mean" + at);
        expectClose(f.stddev[p], s.stddev, "stddev" + at);
        expectClose(f.minimum[p], s.minimum, "min" + at);
        expectClose(f.maximum[p], s.maximum, "max" + at);
        expectClose(f.range[p], s.range, "range" + at);
        expectClose(f.exceedance[p], s.exceedance, "exceedance_probability" + at);
        mixedPoints += s.exceedance > 0 && s.exceedance < 1 ? 1 : 0;
        if (::testing::Test::HasFailure()) return {0, 0};  // one point's report is enough
    }
    for (std::size_t k = 0; k + 1 < g.nz(); ++k) {
        for (std::size_t j = 0; j + 1 < g.ny(); ++j) {
            for (std::size_t i = 0; i + 1 < g.nx(); ++i) {
                const double expected = levelCrossingAt(e, members, i, j, k, c);
                const std::size_t cell = i + (g.nx() - 1) * (j + (g.ny() - 1) * k);
                expectClose(f.crossing[cell], expected,
                            "level_crossing_probability at cell " + std::to_string(cell));
                mixedCells += expected > 0 && expected < 1 ? 1 : 0;
                if (::testing::Test::HasFailure()) return {0, 0};
            }
        }
    }
    return {mixedPoints, mixedCells};
}

// The shortest text that reads back as the same float, as the file's long_name writes it.
QString shortest(float value) {
    std::array<char, 32> text{};
    const auto result = std::to_chars(text.data(), text.data() + text.size(), value);
    return QString::fromLatin1(text.data(), result.ptr - text.data());
}

// A generated ensemble of 4 members on 24 x 12 x 4, and an isovalue inside its values (the
// value of member 1 at a point in the middle), as text that reads back as the same float.
struct Generated {
    test::TempDir dir;
    QString input;
    data::Ensemble ensemble;
    float isovalue = 0.0F;
    QString isoText;
    Generated() {
        input = QString::fromStdString(dir.file("four.nc"));
        const test::EnsilRun g =
            test::runEnsil({"generate", "--members", "4", "--grid", "24x12x4", "--out", input});
        EXPECT_EQ(g.code, 0) << g.err.toStdString();
        ensemble = data::openEnsemble({.paths = {input.toStdString()}});
        isovalue = ensemble.members[1].values[ensemble.grid.index(12, 6, 2)];
        isoText = shortest(isovalue);
    }
    [[nodiscard]] QString out(const char* name) const {
        return QString::fromStdString(dir.file(name));
    }
};
}  // namespace

TEST(StatsCommand, EveryFieldOfTheFileIsTheStatisticsOfTheMembers) {
    const Generated gen;
    ASSERT_EQ(gen.ensemble.memberCount(), 4U);
    const QString out = gen.out("stats.nc");
    const test::EnsilRun o =
        test::runEnsil({"stats", gen.input, "--iso", gen.isoText, "--out", out, "--json"});
    ASSERT_EQ(o.code, 0) << o.err.toStdString();
    EXPECT_TRUE(o.err.isEmpty()) << o.err.toStdString();

    const data::Grid& g = gen.ensemble.grid;
    const StatsFile file(out.toStdString());
    const Fields f = readFields(file, g);
    const auto [mixedPoints, mixedCells] =
        expectFieldsMatch(f, gen.ensemble, {0, 1, 2, 3}, gen.isovalue);
    EXPECT_GT(mixedPoints, 10) << "the isovalue should split the members somewhere";
    EXPECT_GT(mixedCells, 10) << "some cells should be crossed by some members only";

    // Dimensions and coordinates: the data's own axes, and the cell centres.
    using Dims = std::vector<std::pair<std::string, std::size_t>>;
    for (const char* name :
         {"mean", "stddev", "min", "max", "range", "exceedance_probability", "member_count"}) {
        EXPECT_EQ(file.dims(name), (Dims{{"plev", 4}, {"lat", 12}, {"lon", 24}})) << name;
    }
    EXPECT_EQ(file.dims("level_crossing_probability"),
              (Dims{{"plev_cell", 3}, {"lat_cell", 11}, {"lon_cell", 23}}));
    EXPECT_EQ(file.doubles("lon"), g.x().values);
    EXPECT_EQ(file.doubles("lat"), g.y().values);
    EXPECT_EQ(file.doubles("plev"), g.z().values);
    const std::vector<double> latCells = file.doubles("lat_cell");
    ASSERT_EQ(latCells.size(), 11U);
    EXPECT_DOUBLE_EQ(latCells[3], 0.5 * (g.y().values[3] + g.y().values[4]));
    const std::vector<double> plevCells = file.doubles("plev_cell");
    ASSERT_EQ(plevCells.size(), 3U);
    EXPECT_DOUBLE_EQ(plevCells[0], 0.5 * (g.z().values[0] + g.z().values[1]));
    EXPECT_EQ(file.text("lon", "units"), g.x().units);
    EXPECT_EQ(file.text("lon_cell", "units"), g.x().units);
    EXPECT_EQ(file.text("plev", "axis"), "Z");
    EXPECT_EQ(file.text("plev_cell", "positive"), "down");

    // Units, names and the file's own description.
    EXPECT_EQ(file.text("mean", "units"), "m s-1");
    EXPECT_EQ(file.text("stddev", "units"), "m s-1");
    EXPECT_EQ(file.text("range", "units"), "m s-1");
    EXPECT_EQ(file.text("exceedance_probability", "units"), "1");
    EXPECT_EQ(file.text("member_count", "units"), "1");
    EXPECT_EQ(file.text("level_crossing_probability", "units"), "1");
    EXPECT_EQ(file.text("mean", "long_name"), "ensemble mean of wind_speed");
    EXPECT_EQ(file.text("exceedance_probability", "long_name"),
              "probability that wind_speed exceeds " + gen.isoText.toStdString() + " m s-1");
    EXPECT_EQ(file.text("", "Conventions"), "CF-1.8");
    EXPECT_EQ(file.text("", "members"), "member 1, member 2, member 3, member 4");
    EXPECT_EQ(file.text("", "source"), std::filesystem::absolute(gen.input.toStdString()).string());
    EXPECT_NE(
        file.text("", "history")
            .find("ensil stats " + gen.input.toStdString() + " --iso " + gen.isoText.toStdString()),
        std::string::npos)
        << file.text("", "history");

    // The JSON for scripts says the same.
    const QJsonObject json = jsonOf(o);
    EXPECT_EQ(json["output"].toString(), out);
    EXPECT_EQ(json["variable"].toString(), "wind_speed");
    EXPECT_EQ(json["isovalue"].toDouble(), gen.isoText.toDouble());  // as the user wrote it
    EXPECT_EQ(json["member_count"].toInt(), 4);
    EXPECT_EQ(json["members"].toArray().size(), 4);
    EXPECT_GE(json["seconds"].toObject()["total"].toDouble(), 0.0);
    const QJsonObject stddev = json["fields"].toObject()["stddev"].toObject();
    EXPECT_EQ(stddev["min"].toDouble(),
              static_cast<double>(*std::min_element(f.stddev.begin(), f.stddev.end())));
    EXPECT_EQ(stddev["max"].toDouble(),
              static_cast<double>(*std::max_element(f.stddev.begin(), f.stddev.end())));
    EXPECT_EQ(json["fields"].toObject()["member_count"].toObject()["max"].toDouble(), 4.0);
}

TEST(StatsCommand, MembersListedAreTheOnlyOnesSummarised) {
    const Generated gen;
    const QString out = gen.out("two.nc");
    const test::EnsilRun o = test::runEnsil(
        {"stats", gen.input, "--iso", gen.isoText, "--members", "1,3", "--out", out, "--json"});
    ASSERT_EQ(o.code, 0) << o.err.toStdString();
    const data::Grid& g = gen.ensemble.grid;
    const StatsFile file(out.toStdString());
    const std::vector<float> mean = file.floats("mean", g.pointCount());
    const std::vector<float> count = file.floats("member_count", g.pointCount());
    const std::size_t p = g.index(5, 7, 1);
    const double expected =
        0.5 * (gen.ensemble.members[0].values[p] + double{gen.ensemble.members[2].values[p]});
    EXPECT_NEAR(mean[p], expected, 1e-5 * std::abs(expected));
    EXPECT_EQ(count[p], 2.0F);
    expectFieldsMatch(readFields(file, g), gen.ensemble, {0, 2}, gen.isovalue);
    EXPECT_EQ(file.text("", "members"), "member 1, member 3");
    EXPECT_EQ(jsonOf(o)["member_count"].toInt(), 2);
    EXPECT_EQ(jsonOf(o)["members"].toArray(), (QJsonArray{"member 1", "member 3"}));

    // A range, and spaces as a user may type them.
    const QString threeOut = gen.out("three.nc");
    const test::EnsilRun range = test::runEnsil(
        {"stats", gen.input, "--iso", gen.isoText, "--members", "2 - 4", "--out", threeOut});
    ASSERT_EQ(range.code, 0) << range.err.toStdString();
    const StatsFile three(threeOut.toStdString());
    expectFieldsMatch(readFields(three, g), gen.ensemble, {1, 2, 3}, gen.isovalue);
}

TEST(StatsCommand, MissingValuesAndAMemberWithoutDataAreLeftOut) {
    // The third member (number 3) is all _FillValue (left out, with a warning); one point misses
    // member 0's value and another every member's.
    test::TempDir dir;
    data::Ensemble e =
        data::makeDemoEnsemble({.members = 4, .nx = 6, .ny = 5, .nz = 3, .seed = 3}).ensemble;
    const std::size_t holed = e.grid.index(2, 2, 1);
    const std::size_t empty = e.grid.index(4, 1, 2);
    e.members[0].values[holed] = NAN;
    for (data::Member& m : e.members) m.values[empty] = NAN;
    std::fill(e.members[2].values.begin(), e.members[2].values.end(), NAN);
    const std::string input = dir.file("holes.nc");
    data::writeNetcdf(e, input);
    const data::Ensemble read = data::openEnsemble({.paths = {input}});
    const float c = read.members[1].values[e.grid.index(3, 2, 1)];
    const QString out = QString::fromStdString(dir.file("stats.nc"));
    const test::EnsilRun o = test::runEnsil(
        {"stats", QString::fromStdString(input), "--iso", shortest(c), "--out", out, "--json"});
    ASSERT_EQ(o.code, 0) << o.err.toStdString();
    EXPECT_TRUE(o.err.contains("warning: 'member 3' of 'wind_speed' has no valid value"))
        << o.err.toStdString();
    EXPECT_TRUE(o.err.contains("left out of the statistics")) << o.err.toStdString();
    EXPECT_EQ(jsonOf(o)["member_count"].toInt(), 3);
    EXPECT_EQ(jsonOf(o)["members_without_data"].toArray(), QJsonArray{"member 3"});
    const StatsFile file(out.toStdString());
    const Fields f = readFields(file, read.grid);
    expectFieldsMatch(f, read, {0, 1, 3}, c);
    EXPECT_EQ(f.count[holed], 2.0F);
    EXPECT_EQ(f.count[empty], 0.0F);
    EXPECT_TRUE(std::isnan(f.mean[empty]));
    EXPECT_EQ(file.text("", "members"), "member 1, member 2, member 4");

    // Listing the member without data is refused.
    const test::EnsilRun listed = test::runEnsil({"stats", QString::fromStdString(input), "--iso",
                                                  shortest(c), "--members", "2-3", "--out", out});
    EXPECT_EQ(listed.code, 2);
    EXPECT_TRUE(listed.err.contains("member 3 ('member 3') has no valid value"))
        << listed.err.toStdString();
}

TEST(StatsCommand, Era5TemperatureAt260KReadsBackThroughEnsil) {
    test::TempDir dir;
    const QString out = QString::fromStdString(dir.file("era5_t_stats.nc"));
    const test::EnsilRun o =
        test::runEnsil({"stats", kEra5, "--var", "t", "--iso", "260", "--out", out, "--json"});
    ASSERT_EQ(o.code, 0) << o.err.toStdString();
    EXPECT_EQ(jsonOf(o)["member_count"].toInt(), 10);
    const data::Ensemble t = data::openEnsemble({.paths = {kEra5.toStdString()}, .variable = "t"});
    ASSERT_EQ(t.memberCount(), 10U);

    // ensil's reader asks for a member dimension, which a statistics file has none of, so the
    // file is read through the netCDF API: t's grid, and the mean of the 10 members.
    const StatsFile file(out.toStdString());
    using Dims = std::vector<std::pair<std::string, std::size_t>>;
    EXPECT_EQ(file.dims("mean"), (Dims{{"plev", 2}, {"lat", 61}, {"lon", 120}}));
    EXPECT_EQ(file.doubles("lon"), t.grid.x().values);
    EXPECT_EQ(file.doubles("lat"), t.grid.y().values);
    EXPECT_EQ(file.doubles("plev"), t.grid.z().values);
    EXPECT_EQ(file.text("mean", "units"), "K");
    EXPECT_EQ(file.text("exceedance_probability", "long_name"), "probability that t exceeds 260 K");
    EXPECT_EQ(file.text("", "members"),
              "member 0, member 1, member 2, member 3, member 4, member 5, member 6, member 7, "
              "member 8, member 9");
    EXPECT_NE(file.text("", "title").find("time = 0 of 4 (2017-01-01T00:00)"), std::string::npos)
        << file.text("", "title");
    const std::vector<float> mean = file.floats("mean", t.grid.pointCount());
    for (const std::size_t p : {t.grid.index(0, 0, 0), t.grid.index(37, 20, 1),
                                t.grid.index(100, 45, 0), t.grid.index(119, 60, 1)}) {
        double sum = 0;
        for (const data::Member& m : t.members) sum += m.values[p];
        EXPECT_NEAR(mean[p], sum / 10.0, 1e-4) << "point " << p;
    }
}

TEST(StatsCommand, BadArgumentsAreRefusedNamingWhatIsWrong) {
    const Generated gen;
    const QString out = gen.out("bad.nc");
    struct Case {
        QStringList args;
        int code;
        const char* phrase;
    };
    const std::vector<Case> cases{
        {{"stats", gen.input, "--out", out}, 2, "say which isovalue with --iso"},
        {{"stats", gen.input, "--iso", "nan", "--out", out}, 2, "--iso"},
        {{"stats", gen.input, "--iso", "1000", "--out", out},
         2,
         "isovalue 1000 is outside the values of 'wind_speed'"},
        {{"stats", gen.input, "--iso", gen.isoText, "--members", "3-1", "--out", out},
         2,
         "the range 3-1 runs backwards; write 1-3"},
        {{"stats", gen.input, "--iso", gen.isoText, "--members", "1,1", "--out", out},
         2,
         "lists member 1 twice"},
        {{"stats", gen.input, "--iso", gen.isoText, "--members", "0,2", "--out", out},
         2,
         "there is no member 0; members are numbered from 1"},
        {{"stats", gen.input, "--iso", gen.isoText, "--members", "1-3,2", "--out", out},
         2,
         "lists member 2 twice"},
        {{"stats", gen.input, "--iso", gen.isoText, "--members", "99", "--out", out},
         2,
         "there is no member 99: "},
        {{"stats", gen.input, "--iso", gen.isoText, "--members", "1,,2", "--out", out},
         2,
         "has an empty entry"},
        {{"stats", gen.input, "--iso", gen.isoText, "--members", "-1", "--out", out},
         2,
         "'-1' is neither a member number nor a range"},
        {{"stats", gen.input, "--iso", gen.isoText}, 2, "say where to write the statistics"},
        {{"stats", "--iso", gen.isoText, "--out", out}, 2, "name the files to summarise"},
        {{"stats", gen.input, "--iso", gen.isoText, "--out", gen.input},
         2,
         "is one of the input files"},
        {{"stats", gen.input, "--iso", gen.isoText, "--out", "/nonexistent-ensil-folder/s.nc"},
         1,
         "the folder '/nonexistent-ensil-folder' does not exist"},
        {{"stats", gen.input, "--iso", gen.isoText, "--out",
          QString::fromStdString(gen.dir.path().string())},
         1,
         "it is a folder"},
        {{"stats", gen.input, "--iso", gen.isoText, "--bogus", "--out", out},
         2,
         "Unknown option 'bogus'"},
    };
    for (const Case& c : cases) {
        const test::EnsilRun o = test::runEnsil(c.args);
        const std::string command = c.args.join(' ').toStdString();
        EXPECT_EQ(o.code, c.code) << command << "\n" << o.err.toStdString();
        EXPECT_TRUE(o.err.contains(QLatin1String(c.phrase))) << command << "\n"
                                                             << o.err.toStdString();
        EXPECT_TRUE(o.err.startsWith("ensil stats: ")) << command << "\n" << o.err.toStdString();
    }
    // The range of the values is named, and 99's message says what the file holds.
    const test::EnsilRun outside = test::runEnsil(cases[2].args);
    EXPECT_TRUE(outside.err.contains("m s-1): every member is on one side of it"))
        << outside.err.toStdString();
    const test::EnsilRun tooHigh = test::runEnsil(cases[7].args);
    EXPECT_TRUE(tooHigh.err.contains("holds 4 members of 'wind_speed' (1 to 4)"))
        << tooHigh.err.toStdString();
    EXPECT_FALSE(std::filesystem::exists(out.toStdString())) << "no file for a refused command";
    // The input is untouched by an --out naming it.
    EXPECT_EQ(data::openEnsemble({.paths = {gen.input.toStdString()}}).memberCount(), 4U);
}

TEST(StatsCommand, HelpNamesEveryOption) {
    const test::EnsilRun help = test::runEnsil({"stats", "--help"});
    EXPECT_EQ(help.code, 0);
    for (const char* option : {"--iso", "--members", "--out", "--json", "--var", "--member-dim",
                               "--time-index", "stats [options] PATH..."}) {
        EXPECT_TRUE(help.out.contains(QLatin1String(option))) << option;
    }
    EXPECT_TRUE(test::runEnsil({"--help"}).out.contains("stats"));
}

TEST(StatsCommand, MemberListsParseAsUsersWriteThem) {
    using cli::MemberRange;
    QString problem;
    EXPECT_EQ(cli::parseMemberList("1,3,5-9", problem),
              (std::vector<MemberRange>{{1, 1}, {3, 3}, {5, 9}}));
    EXPECT_EQ(cli::parseMemberList(" 4 , 1-2 ", problem),
              (std::vector<MemberRange>{{4, 4}, {1, 2}}));
    for (const char* bad : {"", "a", "1,", "1-", "-2", "1-2-3", "1.5", "5-9,9", "1,1", "3-1", "0",
                            "0-2", "99999999999999999999"}) {
        problem.clear();
        EXPECT_FALSE(cli::parseMemberList(QLatin1String(bad), problem).has_value()) << bad;
        EXPECT_TRUE(problem.startsWith("--members '")) << bad << ": " << problem.toStdString();
    }
}

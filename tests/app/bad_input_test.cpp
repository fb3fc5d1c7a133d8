// The bad-input corpus (tests/data/bad, written by its make_corpus.py): each file once crashed,
// hung or misled ensil. Each case runs through the commands a user types and must end with a
// clear message naming the file and what is wrong, and a non-zero exit status: never an
// abort, a hang or an exit 0 with a wrong result.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTextStream>
#include <algorithm>
#include <cmath>
#include <fstream>

#include "tests/app/ensil_run.h"
#include "tests/support/temp_dir.h"

using namespace ensil;

namespace {
const QString kBad = QStringLiteral(ENSIL_SHARED_DATA_DIR "/../bad/");

using Outcome = test::EnsilRun;

struct Case {
    const char* file;
    const char* phrase;  // part of the message that says what is wrong
};

// Files refused with exit status 1 and a message naming the file and what is wrong.
const Case kCorruptCases[] = {
    // VTK legacy files whose counts once wrapped around (abort: std::length_error) or asked for
    // gigabytes before the error.
    {"vtk_negative_dimensions.vtk", "gives '-5' as a DIMENSIONS size"},
    {"vtk_negative_last_dimension.vtk", "gives '-1' as a DIMENSIONS size"},
    {"vtk_all_negative_dimensions.vtk", "gives '-1' as a DIMENSIONS size"},
    {"vtk_zero_dimension.vtk", "every axis needs at least one point"},
    {"vtk_huge_dimensions.vtk", "more values than its 191 bytes can hold"},
    {"vtk_negative_coordinate_count.vtk", "gives '-4' as x_coordinates count"},
    {"vtk_billion_coordinates.vtk", "more values than its 235 bytes can hold"},
    // A classic NetCDF file cut inside its data, once read with zeros for the missing end.
    {"netcdf_truncated_data.nc",
     "is truncated: it holds 1444 bytes, but its header implies 1544 (the values of variable "
     "'t' end there)"},
};

// Every number the JSON promises, checked for null (NaN and infinity print as null).
bool holdsNull(const QJsonValue& value) {
    if (value.isNull()) return true;
    if (value.isArray()) {
        for (const QJsonValue& v : value.toArray()) {
            if (holdsNull(v)) return true;
        }
    }
    if (value.isObject()) {
        for (const QJsonValue& v : value.toObject()) {
            if (holdsNull(v)) return true;
        }
    }
    return false;
}

}  // namespace

TEST(BadInput, EveryCorruptFileIsRefusedClearlyByInfoAndPreprocess) {
    for (const Case& c : kCorruptCases) {
        const QString path = kBad + QLatin1String(c.file);
        for (const QStringList& command :
             {QStringList{"info", path}, QStringList{"preprocess", path, "--iso", "1"}}) {
            const Outcome o = test::runEnsil(command);
            EXPECT_EQ(o.code, 1) << c.file << " " << command.front().toStdString();
            EXPECT_TRUE(o.err.contains(QLatin1String(c.file))) << o.err.toStdString();
            EXPECT_TRUE(o.err.contains(QLatin1String(c.phrase))) << o.err.toStdString();
        }
    }
}

TEST(BadInput, MemberFilesHoldingDifferentVariablesAreNotMixed) {
    // Values of `t` were once reported as `u`, with exit 0.
    const Outcome o = test::runEnsil({"info", kBad + "member_u.nc", kBad + "member_t.nc"});
    EXPECT_EQ(o.code, 1);
    EXPECT_TRUE(o.err.contains("holds 't' where")) << o.err.toStdString();
    EXPECT_TRUE(o.err.contains("--var")) << o.err.toStdString();
    // Naming the variable is the way out: then the file without it is named.
    const Outcome named =
        test::runEnsil({"info", kBad + "member_u.nc", kBad + "member_t.nc", "--var", "u"});
    EXPECT_NE(named.code, 0);
    EXPECT_TRUE(named.err.contains("member_t.nc")) << named.err.toStdString();
}

TEST(BadInput, ANamedPipeIsRefusedInsteadOfWaitedOn) {
    const test::TempDir dir;
    const std::string pipe = dir.file("members.nc");
    ASSERT_EQ(::mkfifo(pipe.c_str(), 0600), 0);
    // Before, opening it to read its first bytes blocked forever.
    const Outcome o = test::runEnsil({"info", QString::fromStdString(pipe)});
    EXPECT_EQ(o.code, 1);
    EXPECT_TRUE(o.err.contains("is not a regular file")) << o.err.toStdString();
}

TEST(BadInput, AnEmptyOrUnusableCacheFolderIsSaid) {
    const QString era5 = QStringLiteral(ENSIL_SHARED_DATA_DIR "/era5_eda_members.nc");
    // '' once wrote the cache into the current folder.
    const Outcome empty =
        test::runEnsil({"preprocess", era5, "--var", "t", "--iso", "260", "--cache-dir", ""});
    EXPECT_EQ(empty.code, 2);
    EXPECT_TRUE(empty.err.contains("--cache-dir '' is refused")) << empty.err.toStdString();
    // A file where the folder should be: the run goes on, and says it stored nothing.
    const test::TempDir dir;
    const std::string file = dir.file("not-a-folder");
    { std::ofstream(file) << "x"; }
    const Outcome unusable = test::runEnsil({"preprocess", era5, "--var", "t", "--iso", "260",
                                             "--cache-dir", QString::fromStdString(file)});
    EXPECT_EQ(unusable.code, 0) << unusable.err.toStdString();
    EXPECT_TRUE(unusable.err.contains("warning: cannot write the preprocessing cache"))
        << unusable.err.toStdString();
}

TEST(BadInput, TheDefaultClusterCountFitsASmallEnsembleAndAnAskedOneIsExplained) {
    const test::TempDir dir;
    const QString file = QString::fromStdString(dir.file("four.nc"));
    ASSERT_EQ(
        test::runEnsil({"generate", "--members", "4", "--grid", "24x12x4", "--out", file}).code, 0);
    // The default of 5 clusters on 4 members once failed, blaming the user; then it put each
    // member in a cluster of its own. It is about half the members.
    const Outcome fits =
        test::runEnsil({"preprocess", file, "--iso", "20", "--no-cache", "--json"});
    ASSERT_EQ(fits.code, 0) << fits.err.toStdString();
    EXPECT_TRUE(fits.out.contains("\"k\":2")) << fits.out.left(400).toStdString();
    const Outcome asked =
        test::runEnsil({"preprocess", file, "--iso", "20", "--no-cache", "--clusters", "6"});
    EXPECT_EQ(asked.code, 2);
    EXPECT_TRUE(asked.err.contains("--clusters 6 is more than the 4 members"))
        << asked.err.toStdString();
}

TEST(BadInput, AMemberWithoutDataIsNamedAndLeftOutOfTheClustering) {
    // Member 2 is all _FillValue: its distances and the linkage heights were once null.
    const QString file = kBad + "member_without_data.nc";
    const Outcome o = test::runEnsil({"preprocess", file, "--iso", "4", "--no-cache", "--json"});
    ASSERT_EQ(o.code, 0) << o.err.toStdString();
    EXPECT_TRUE(o.err.contains("warning: 'member 2' of 't' has no valid value"))
        << o.err.toStdString();
    EXPECT_TRUE(o.err.contains("left out of the clustering")) << o.err.toStdString();
    const QJsonObject json = jsonOf(o);
    EXPECT_FALSE(holdsNull(json)) << o.out.toStdString();
    EXPECT_EQ(json["members_without_data"].toArray(), QJsonArray{"member 2"});
    EXPECT_EQ(json["member_count"].toInt(), 3);
    ASSERT_EQ(json["distance_matrix"].toArray().size(), 3);
    ASSERT_EQ(json["linkage"].toArray().size(), 2);
    QStringList names;
    for (const QJsonValue& m : json["members"].toArray()) names << m["name"].toString();
    EXPECT_EQ(names, (QStringList{"member 0", "member 1", "member 3"}));
    EXPECT_EQ(json["clusters"].toArray().size(), 3);
    EXPECT_EQ(json["colors"].toArray().size(), 3);
    // `ensil info` says so too.
    const Outcome info = test::runEnsil({"info", file, "--json"});
    ASSERT_EQ(info.code, 0) << info.err.toStdString();
    EXPECT_EQ(jsonOf(info)["members_without_data"].toArray(), QJsonArray{"member 2"});
    EXPECT_TRUE(info.err.contains("warning: 'member 2' of 't' has no valid value"))
        << info.err.toStdString();
}

TEST(BadInput, MembersWithoutACommonValidPointArePlacedByTheStatedRuleAndSaid) {
    // The first two members are valid in different halves of the grid: their distance was
    // infinite, so the distance matrix and the last linkage height were null. (The file names
    // them 'member 0' and 'member 1'; their numbers are 1 and 2.)
    const QString file = kBad + "members_without_overlap.nc";
    const Outcome o = test::runEnsil({"preprocess", file, "--iso", "4", "--no-cache", "--json"});
    ASSERT_EQ(o.code, 0) << o.err.toStdString();
    EXPECT_TRUE(
        o.err.contains("warning: one pair of members shares no grid point where both have "
                       "a valid value ('member 0' and 'member 1')"))
        << o.err.toStdString();
    const QJsonObject json = jsonOf(o);
    EXPECT_FALSE(holdsNull(json)) << o.out.toStdString();
    EXPECT_EQ(json["pairs_without_overlap"].toArray(), (QJsonArray{QJsonArray{1, 2}}));
    // Placed as far apart as the farthest pair that was measured.
    const QJsonArray d = json["distance_matrix"].toArray();
    double farthestMeasured = 0.0;
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < i; ++j) {
            if (i == 1 && j == 0) continue;
            farthestMeasured = std::max(farthestMeasured, d[i].toArray()[j].toDouble());
        }
    }
    EXPECT_GT(farthestMeasured, 0.0);
    EXPECT_EQ(d[1].toArray()[0].toDouble(), farthestMeasured);
    EXPECT_EQ(d[0].toArray()[1].toDouble(), farthestMeasured);
    EXPECT_EQ(json["linkage"].toArray().size(), 3);
}

TEST(BadInput, InfinitiesInTheDataAreMissingValuesAndSaid) {
    // One +inf and one -inf: the range was once [0, null] and the histogram cast infinity.
    const QString file = kBad + "infinite_values.nc";
    const Outcome info = test::runEnsil({"info", file, "--json"});
    ASSERT_EQ(info.code, 0) << info.err.toStdString();
    const QJsonObject json = jsonOf(info);
    EXPECT_FALSE(holdsNull(json["range"])) << info.out.toStdString();
    EXPECT_FALSE(holdsNull(json["mean"])) << info.out.toStdString();
    const QJsonArray range = json["range"].toArray();
    ASSERT_EQ(range.size(), 2);
    EXPECT_EQ(range[0].toDouble(), 0.0);
    EXPECT_EQ(range[1].toDouble(), 10.0) << "the largest finite value";
    EXPECT_EQ(json["infinite"].toInt(), 2);
    EXPECT_EQ(json["missing"].toInt(), 2) << "counted with the missing values";
    EXPECT_TRUE(info.err.contains("2 values of 't' are infinite")) << info.err.toStdString();
    const Outcome text = test::runEnsil({"info", file});
    ASSERT_EQ(text.code, 0);
    EXPECT_TRUE(text.out.contains("Values:     0 .. 10 K")) << text.out.toStdString();

    const Outcome prep = test::runEnsil({"preprocess", file, "--iso", "4", "--no-cache", "--json"});
    ASSERT_EQ(prep.code, 0) << prep.err.toStdString();
    EXPECT_FALSE(holdsNull(jsonOf(prep))) << prep.out.toStdString();
    EXPECT_TRUE(prep.err.contains("2 values of 't' are infinite")) << prep.err.toStdString();
}

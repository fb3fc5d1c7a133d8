// The bad-input corpus (tests/data/bad, written by its make_corpus.py): each file once crashed,
// hung or misled ensil. Each case runs through the commands a user types and must end with a
// clear message naming the file and what is wrong, and a non-zero exit status: never an
// abort, a hang or an exit 0 with a wrong result.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <QTextStream>
#include <fstream>

#include "tests/app/ensil_run.h"
#include "tests/support/temp_dir.h"

using namespace ensil;

namespace {
const QString kBad = QStringLiteral(ENSIL_SHARED_DATA_DIR "/../bad/");

using Outcome = test::EnsilRun;
const auto run = test::runEnsil;

struct Case {
    const char* file;
    const char* phrase;  // part of the message that says what is wrong
};

// VTK legacy files whose counts once wrapped around (abort: std::length_error) or asked for
// gigabytes before the error.
const Case kVtkCases[] = {
    {"vtk_negative_dimensions.vtk", "gives '-5' as a DIMENSIONS size"},
    {"vtk_negative_last_dimension.vtk", "gives '-1' as a DIMENSIONS size"},
    {"vtk_all_negative_dimensions.vtk", "gives '-1' as a DIMENSIONS size"},
    {"vtk_zero_dimension.vtk", "every axis needs at least one point"},
    {"vtk_huge_dimensions.vtk", "more values than its 191 bytes can hold"},
    {"vtk_negative_coordinate_count.vtk", "gives '-4' as x_coordinates count"},
    {"vtk_billion_coordinates.vtk", "more values than its 235 bytes can hold"},
};
}  // namespace

TEST(BadInput, EveryCorruptVtkFileIsRefusedClearlyByInfoAndPreprocess) {
    for (const Case& c : kVtkCases) {
        const QString path = kBad + QLatin1String(c.file);
        for (const QStringList& command :
             {QStringList{"info", path}, QStringList{"preprocess", path, "--iso", "1"}}) {
            const Outcome o = run(command);
            EXPECT_EQ(o.code, 1) << c.file << " " << command.front().toStdString();
            EXPECT_TRUE(o.err.contains(QLatin1String(c.file))) << o.err.toStdString();
            EXPECT_TRUE(o.err.contains(QLatin1String(c.phrase))) << o.err.toStdString();
        }
    }
}

TEST(BadInput, MemberFilesHoldingDifferentVariablesAreNotMixed) {
    // Values of `t` were once reported as `u`, with exit 0.
    const Outcome o = run({"info", kBad + "member_u.nc", kBad + "member_t.nc"});
    EXPECT_EQ(o.code, 1);
    EXPECT_TRUE(o.err.contains("holds 't' where")) << o.err.toStdString();
    EXPECT_TRUE(o.err.contains("--var")) << o.err.toStdString();
    // Naming the variable is the way out: then the file without it is named.
    const Outcome named = run({"info", kBad + "member_u.nc", kBad + "member_t.nc", "--var", "u"});
    EXPECT_NE(named.code, 0);
    EXPECT_TRUE(named.err.contains("member_t.nc")) << named.err.toStdString();
}

TEST(BadInput, ANamedPipeIsRefusedInsteadOfWaitedOn) {
    const test::TempDir dir;
    const std::string pipe = dir.file("members.nc");
    ASSERT_EQ(::mkfifo(pipe.c_str(), 0600), 0);
    // Before, opening it to read its first bytes blocked forever.
    const Outcome o = run({"info", QString::fromStdString(pipe)});
    EXPECT_EQ(o.code, 1);
    EXPECT_TRUE(o.err.contains("is not a regular file")) << o.err.toStdString();
}

TEST(BadInput, AnEmptyOrUnusableCacheFolderIsSaid) {
    const QString era5 = QStringLiteral(ENSIL_SHARED_DATA_DIR "/era5_eda_members.nc");
    // '' once wrote the cache into the current folder.
    const Outcome empty =
        run({"preprocess", era5, "--var", "t", "--iso", "260", "--cache-dir", ""});
    EXPECT_EQ(empty.code, 2);
    EXPECT_TRUE(empty.err.contains("--cache-dir '' is refused")) << empty.err.toStdString();
    // A file where the folder should be: the run goes on, and says it stored nothing.
    const test::TempDir dir;
    const std::string file = dir.file("not-a-folder");
    { std::ofstream(file) << "x"; }
    const Outcome unusable = run({"preprocess", era5, "--var", "t", "--iso", "260", "--cache-dir",
                                  QString::fromStdString(file)});
    EXPECT_EQ(unusable.code, 0) << unusable.err.toStdString();
    EXPECT_TRUE(unusable.err.contains("warning: cannot write the preprocessing cache"))
        << unusable.err.toStdString();
}

TEST(BadInput, TheDefaultClusterCountFitsASmallEnsembleAndAnAskedOneIsExplained) {
    const test::TempDir dir;
    const QString file = QString::fromStdString(dir.file("four.nc"));
    ASSERT_EQ(run({"generate", "--members", "4", "--grid", "24x12x4", "--out", file}).code, 0);
    // The default of 5 clusters on 4 members once failed, blaming the user.
    const Outcome fits = run({"preprocess", file, "--iso", "20", "--no-cache", "--json"});
    ASSERT_EQ(fits.code, 0) << fits.err.toStdString();
    EXPECT_TRUE(fits.out.contains("\"k\":4")) << fits.out.left(400).toStdString();
    const Outcome asked = run({"preprocess", file, "--iso", "20", "--no-cache", "--clusters", "6"});
    EXPECT_EQ(asked.code, 2);
    EXPECT_TRUE(asked.err.contains("--clusters 6 is more than the 4 members"))
        << asked.err.toStdString();
}

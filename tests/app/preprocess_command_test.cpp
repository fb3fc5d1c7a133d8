#include <gtest/gtest.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkXMLMultiBlockDataReader.h>

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTextStream>

#include "cli/command_line.h"
#include "data/ensemble_reader.h"
#include "preprocessing/cluster_identity.h"
#include "preprocessing/inclusion_depth.h"
#include "tests/app/default_isovalue.h"
#include "tests/app/ensil_run.h"
#include "tests/support/temp_dir.h"

using namespace ensil;

namespace {
struct CommandRun {
    int code = 0;
    QString out, err;
};
CommandRun preprocess(QStringList args) {
    args.prepend("preprocess");
    args.prepend("ensil");
    CommandRun r;
    QTextStream out(&r.out), err(&r.err);
    r.code = cli::runCommandLine(args, out, err).exitCode;
    out.flush();
    err.flush();
    return r;
}
}  // namespace

TEST(PreprocessCommand, JsonHasTheContractAndTheSecondRunHitsTheCache) {
    test::TempDir cache;
    const QStringList args{ENSIL_SHARED_DATA_DIR "/era5_eda_members.nc",
                           "--var",
                           "t",
                           "--iso",
                           "260",
                           "--clusters",
                           "3",
                           "--linkage",
                           "complete",
                           "--json",
                           "--cache-dir",
                           QString::fromStdString(cache.path().string())};
    const CommandRun first = preprocess(args);
    ASSERT_EQ(first.code, 0) << first.err.toStdString();
    const QJsonObject o = QJsonDocument::fromJson(first.out.toUtf8()).object();
    EXPECT_EQ(o["member_count"].toInt(), 10);
    // The member table's figures, per member, from the same job as the workbench's.
    const QJsonArray members = o["members"].toArray();
    ASSERT_EQ(members.size(), 10);
    const QJsonArray memberClusters = o["clusters"].toArray();
    // One colour per member, the same for members of one cluster and apart across clusters.
    const QJsonArray colors = o["colors"].toArray();
    ASSERT_EQ(colors.size(), 10);
    for (int a = 0; a < 10; ++a) {
        EXPECT_TRUE(colors[a].toString().startsWith('#'));
        for (int b = 0; b < 10; ++b) {
            EXPECT_EQ(colors[a] == colors[b], memberClusters[a] == memberClusters[b]) << a << b;
        }
    }
    for (int m = 0; m < members.size(); ++m) {
        const QJsonObject member = members[m].toObject();
        EXPECT_FALSE(member["name"].toString().isEmpty());
        EXPECT_EQ(member["number"].toInt(), m + 1) << "the member table's #";
        EXPECT_EQ(member["cluster"].toInt(), memberClusters[m].toInt());
        EXPECT_GT(member["distance_to_mean"].toDouble(), 0.0) << m;
        EXPECT_GE(member["mean_outlyingness"].toDouble(-1.0), 0.0) << m;
    }
    EXPECT_EQ(o["grid"].toArray(), (QJsonArray{120, 61, 2}));
    EXPECT_EQ(o["isovalue"].toDouble(), 260.0);
    EXPECT_EQ(o["cache"].toString(), "miss");
    for (const char* key :
         {"load", "meshes", "decimation", "attributes", "similarity", "clustering", "total"}) {
        EXPECT_TRUE(o["seconds"].toObject().contains(key)) << key;
    }
    EXPECT_GT(o["triangles"].toInt(), 0);
    EXPECT_GT(o["vertices"].toInt(), 0);
    EXPECT_GT(o["context_gpu_bytes"].toInteger(), 0);
    EXPECT_EQ(o["gpu_bytes"].toInteger(), o["vertices"].toInteger() * 20 +
                                              o["triangles"].toInteger() * 12 +
                                              o["context_gpu_bytes"].toInteger());
    const QJsonArray d = o["distance_matrix"].toArray();
    ASSERT_EQ(d.size(), 10);
    for (int i = 0; i < 10; ++i) {
        ASSERT_EQ(d[i].toArray().size(), 10);
        EXPECT_EQ(d[i].toArray()[i].toDouble(), 0.0);
        for (int j = 0; j < 10; ++j)
            EXPECT_EQ(d[i].toArray()[j].toDouble(), d[j].toArray()[i].toDouble());
    }
    const QJsonArray linkage = o["linkage"].toArray();
    ASSERT_EQ(linkage.size(), 9) << "N - 1 merges, SciPy's linkage-matrix rows";
    EXPECT_EQ(linkage.last().toArray()[3].toInt(), 10) << "the last merge holds every member";
    // The legend's numbers (issue 37: these were the tree's labels, from 0, while the legend
    // said "Cluster 1"): the tree's stable identities + 1, which from one tree are 1..k.
    const QJsonArray numbers = o["clusters"].toArray();
    ASSERT_EQ(numbers.size(), 10);
    const prep::MergeTree tree = test::treeOfLinkageJson(linkage, 10);
    const std::vector<int> identities =
        prep::memberIdentities(prep::clusterLabels(tree, 3), prep::identitiesFromTree(tree, 3));
    for (int m = 0; m < 10; ++m) {
        EXPECT_EQ(numbers[m].toInt(), identities[static_cast<std::size_t>(m)] + 1) << m;
    }

    const CommandRun second = preprocess(args);
    ASSERT_EQ(second.code, 0);
    const QJsonObject again = QJsonDocument::fromJson(second.out.toUtf8()).object();
    EXPECT_EQ(again["cache"].toString(), "hit");
    EXPECT_EQ(again["triangles"], o["triangles"]);
    EXPECT_EQ(again["clusters"], o["clusters"]);
}

TEST(PreprocessCommand, RefusesAnIsovalueOutsideTheDataAndBadOptions) {
    const CommandRun outside = preprocess(
        {ENSIL_SHARED_DATA_DIR "/era5_eda_members.nc", "--var", "t", "--iso", "400", "--no-cache"});
    EXPECT_EQ(outside.code, 1);
    EXPECT_TRUE(outside.err.contains("225.8")) << outside.err.toStdString();
    // No --iso: the workbench's default, reported.
    const CommandRun byDefault = preprocess(
        {ENSIL_SHARED_DATA_DIR "/era5_eda_members.nc", "--var", "t", "--no-cache", "--json"});
    ASSERT_EQ(byDefault.code, 0) << byDefault.err.toStdString();
    EXPECT_TRUE(byDefault.err.contains("note: only 2 levels along plev"))
        << byDefault.err.toStdString();
    const QJsonObject chosen = QJsonDocument::fromJson(byDefault.out.toUtf8()).object();
    EXPECT_EQ(chosen["variable"].toString(), "t");
    EXPECT_FLOAT_EQ(
        static_cast<float>(chosen["isovalue"].toDouble()),
        test::workbenchDefaultIsovalue(ENSIL_SHARED_DATA_DIR "/era5_eda_members.nc", "t"));
    const CommandRun linkage =
        preprocess({ENSIL_SHARED_DATA_DIR "/era5_eda_members.nc", "--var", "t", "--iso", "260",
                    "--linkage", "median", "--no-cache"});
    EXPECT_EQ(linkage.code, 2) << "a bad option is a usage error";
    EXPECT_TRUE(linkage.err.contains("ward"))
        << "lists the linkages: " << linkage.err.toStdString();
    // These used to turn decimation off silently, or take a fraction as a count.
    for (const QStringList& bad : {QStringList{"--error", "-1"}, QStringList{"--error", "abc"},
                                   QStringList{"--clusters", "2.5"}, QStringList{"--iso", "nan"}}) {
        QStringList args{ENSIL_SHARED_DATA_DIR "/era5_eda_members.nc",
                         "--var",
                         "t",
                         "--iso",
                         "260",
                         "--no-cache"};
        args += bad;
        const CommandRun run = preprocess(args);
        EXPECT_EQ(run.code, 2) << bad.join(' ').toStdString();
        EXPECT_TRUE(run.err.contains(QStringLiteral("%1 '%2' is refused").arg(bad[0], bad[1])))
            << run.err.toStdString();
    }
    EXPECT_EQ(preprocess({"--iso", "3"}).code, 2) << "neither files nor --demo";
}

TEST(PreprocessCommand, JsonGivesTheContourBoxplotOfTheMembers) {
    // ERA5's temperature at 260 K: the depths, median and outliers are the engine's
    // (preprocessing/inclusion_depth.h) for the same members, and a median is the deepest.
    const std::string file = ENSIL_SHARED_DATA_DIR "/era5_eda_members.nc";
    const CommandRun r = preprocess(
        {QString::fromStdString(file), "--var", "t", "--iso", "260", "--no-cache", "--json"});
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    const QJsonObject json = QJsonDocument::fromJson(r.out.toUtf8()).object();
    const data::Ensemble e = data::openEnsemble({{file}, "t", {}, 0});
    const prep::ContourBoxplot expected = prep::computeContourBoxplot(e, 260.0F);
    const QJsonArray depth = json["depth"].toArray();
    ASSERT_EQ(depth.size(), static_cast<qsizetype>(e.memberCount()));
    for (qsizetype m = 0; m < depth.size(); ++m) {
        EXPECT_DOUBLE_EQ(depth[m].toDouble(), expected.depth[static_cast<std::size_t>(m)]) << m;
    }
    // Members by their numbers, from 1 (the member table's #).
    const auto median = json["median_member"].toInteger();
    EXPECT_EQ(median, static_cast<qint64>(expected.median) + 1);
    for (const QJsonValue d : depth) EXPECT_LE(d.toDouble(), depth[median - 1].toDouble());
    QJsonArray outliers;
    for (const std::size_t m : expected.outliers) outliers.append(static_cast<qint64>(m) + 1);
    EXPECT_EQ(json["outliers"].toArray(), outliers);
}

// --export writes what ParaView opens: VTK's own reader finds a block per member and summary
// surface, in the data's coordinates (degrees east and north, hPa), with the triangles --json
// reports.
TEST(PreprocessCommand, ExportedSurfacesOpenInVtksReaderWithTheTrianglesReported) {
    test::TempDir dir;
    const QString folder = QString::fromStdString((dir.path() / "surfaces").string());
    const CommandRun run = preprocess({ENSIL_SHARED_DATA_DIR "/era5_eda_members.nc", "--var", "t",
                                       "--iso", "260", "--no-cache", "--json", "--export", folder});
    ASSERT_EQ(run.code, 0) << run.err.toStdString();
    const QJsonObject o = QJsonDocument::fromJson(run.out.toUtf8()).object();
    const QJsonObject exported = o["export"].toObject();
    const QJsonArray files = exported["files"].toArray();
    ASSERT_FALSE(files.isEmpty()) << run.out.toStdString();
    EXPECT_TRUE(files[0].toString().endsWith("t_iso260.vtm")) << files[0].toString().toStdString();

    vtkNew<vtkXMLMultiBlockDataReader> reader;
    reader->SetFileName(files[0].toString().toStdString().c_str());
    reader->Update();
    auto* blocks = vtkMultiBlockDataSet::SafeDownCast(reader->GetOutput());
    ASSERT_NE(blocks, nullptr);
    const int members = o["member_count"].toInt();
    ASSERT_GE(blocks->GetNumberOfBlocks(), static_cast<unsigned>(members + 1));
    const data::EnsembleDescription d = data::describeEnsemble(
        {.paths = {ENSIL_SHARED_DATA_DIR "/era5_eda_members.nc"}, .variable = "t"});
    qint64 membersAndMean = 0, all = 0;
    for (unsigned b = 0; b < blocks->GetNumberOfBlocks(); ++b) {
        auto* poly = vtkPolyData::SafeDownCast(blocks->GetBlock(b));
        ASSERT_NE(poly, nullptr);
        all += poly->GetNumberOfPolys();
        if (b <= static_cast<unsigned>(members)) membersAndMean += poly->GetNumberOfPolys();
        double bounds[6];
        poly->GetBounds(bounds);
        for (int a = 0; a < 3; ++a) {
            EXPECT_GE(bounds[2 * a], d.grid.axis(a).minValue() - 1e-6) << "block " << b;
            EXPECT_LE(bounds[2 * a + 1], d.grid.axis(a).maxValue() + 1e-6) << "block " << b;
        }
    }
    EXPECT_EQ(membersAndMean, o["triangles"].toInteger()) << "the members' and the mean's";
    EXPECT_EQ(all, exported["triangles"].toInteger());

    const CommandRun badFormat =
        preprocess({"--demo", "--iso", "30", "--export", folder, "--format", "vtk"});
    EXPECT_EQ(badFormat.code, 2);
    EXPECT_TRUE(badFormat.err.contains("vtp, ply, obj, stl")) << badFormat.err.toStdString();
    const CommandRun noFolder = preprocess({"--demo", "--iso", "30", "--format", "ply"});
    EXPECT_EQ(noFolder.code, 2);
    EXPECT_TRUE(noFolder.err.contains("--export")) << noFolder.err.toStdString();
    const CommandRun badFrame =
        preprocess({"--demo", "--iso", "30", "--export", folder, "--coordinates", "screen"});
    EXPECT_EQ(badFrame.code, 2);
    EXPECT_TRUE(badFrame.err.contains("data or display")) << badFrame.err.toStdString();
}

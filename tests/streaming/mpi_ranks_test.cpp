// `mpirun -np K ensil preprocess` (mpi/): 1, 2, 3 and 4 ranks give the same results, bit for
// bit, and the in-memory run's within rounding; rank 0's cache holds the in-memory run's meshes;
// a rank that fails ends the job with its message. Runs the real program under mpirun
// (oversubscribed past the machine's cores; allowed as root, as CI runs).
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>

#include "data/demo_ensemble.h"
#include "data/ensemble_reader.h"
#include "data/error.h"
#include "data/netcdf_writer.h"
#include "mpi/mesh_transfer.h"
#include "preprocessing/mesh_cache.h"
#include "tests/support/temp_dir.h"

using namespace ensil;

namespace {

struct Outcome {
    int code = -1;
    QJsonObject json;
    std::string err;
};

std::string readText(const std::string& path) {
    QFile file(QString::fromStdString(path));
    if (!file.open(QIODevice::ReadOnly)) return {};
    return file.readAll().toStdString();
}

// Runs `command` through the shell with a time limit (a hang fails, never blocks the suite).
Outcome run(const test::TempDir& dir, const std::string& command) {
    setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
    setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
    const std::string out = dir.file("out.json"), err = dir.file("err.txt");
    const int status = std::system(("timeout 120 " + command + " > " + out + " 2> " + err).c_str());
    Outcome r;
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.json = QJsonDocument::fromJson(QByteArray::fromStdString(readText(out))).object();
    r.err = readText(err);
    return r;
}

std::string mpirun(int ranks) {
    return "mpirun --oversubscribe -np " + std::to_string(ranks) + " " + ENSIL_EXECUTABLE;
}

// The demo, 12 members of 48 x 32 x 20, member 3 without data.
std::string writeEnsemble(const test::TempDir& dir) {
    const std::string path = dir.file("ensemble.nc");
    data::Ensemble e =
        data::makeDemoEnsemble({.members = 12, .nx = 48, .ny = 32, .nz = 20}).ensemble;
    for (float& v : e.members[3].values) v = std::numeric_limits<float>::quiet_NaN();
    data::writeNetcdf(e, path);
    return path;
}

prep::IsovalueMeshes cached(const std::string& directory, const std::string& path) {
    const std::string key = data::sourceIdentity({.paths = {path}}) +
                            data::membersWithoutDataKey({"member 4"}) + "; " +
                            prep::pipelineKey({.isovalue = 30.0F}, 1.0F);
    const auto meshes = prep::MeshCache(directory).load(key);
    EXPECT_TRUE(meshes.has_value()) << "no cache entry in " << directory;
    return meshes.value_or(prep::IsovalueMeshes{});
}

bool sameMesh(const data::PackedMesh& a, const data::PackedMesh& b) {
    return a.vertices.size() == b.vertices.size() && a.indices == b.indices &&
           std::memcmp(a.vertices.data(), b.vertices.data(),
                       a.vertices.size() * sizeof(data::PackedVertex)) == 0;
}

}  // namespace

TEST(MpiRanks, OneToFourRanksGiveTheSameResultsAsEachOtherAndAsTheInMemoryRun) {
    test::TempDir dir;
    const std::string path = writeEnsemble(dir);
    const std::string args = " preprocess " + path + " --iso 30 --json --cache-dir ";
    const Outcome whole = run(dir, std::string(ENSIL_EXECUTABLE) + args + dir.file("cache-memory"));
    ASSERT_EQ(whole.code, 0) << whole.err;
    ASSERT_TRUE(whole.json["streaming"].isUndefined()) << "the reference must be the in-memory run";
    const prep::IsovalueMeshes reference = cached(dir.file("cache-memory"), path);
    Outcome first;
    for (int ranks = 1; ranks <= 4; ++ranks) {
        SCOPED_TRACE(testing::Message() << ranks << " ranks");
        const std::string cache = dir.file("cache-" + std::to_string(ranks));
        const Outcome r = run(dir, mpirun(ranks) + args + cache);
        ASSERT_EQ(r.code, 0) << r.err;
        ASSERT_TRUE(r.json["streaming"].isObject()) << "not run in slabs: " << r.err;
        EXPECT_NE(r.err.find("over " + std::to_string(ranks) + " MPI ranks"), std::string::npos)
            << r.err;
        EXPECT_EQ(r.json["members_without_data"].toArray(), QJsonArray{"member 4"});
        // Against the in-memory run: distances within rounding, the same tree and clusters.
        const QJsonArray d = r.json["distance_matrix"].toArray();
        const QJsonArray w = whole.json["distance_matrix"].toArray();
        ASSERT_EQ(d.size(), 11);
        for (qsizetype i = 0; i < d.size(); ++i) {
            for (qsizetype j = 0; j < d.size(); ++j) {
                const double want = w[i].toArray()[j].toDouble();
                EXPECT_NEAR(d[i].toArray()[j].toDouble(), want, 1e-9 * want);
            }
        }
        const QJsonArray merges = r.json["linkage"].toArray();
        ASSERT_EQ(merges.size(), whole.json["linkage"].toArray().size());
        for (qsizetype m = 0; m < merges.size(); ++m) {
            const QJsonArray a = merges[m].toArray(),
                             b = whole.json["linkage"].toArray()[m].toArray();
            EXPECT_EQ(a[0], b[0]);
            EXPECT_EQ(a[1], b[1]);
            EXPECT_EQ(a[3], b[3]);
        }
        EXPECT_EQ(r.json["clusters"], whole.json["clusters"]);
        EXPECT_EQ(r.json["colors"], whole.json["colors"]);
        // Rank 0's cache: the in-memory run's meshes exactly.
        const prep::IsovalueMeshes meshes = cached(cache, path);
        ASSERT_EQ(meshes.members.size(), reference.members.size());
        for (std::size_t m = 0; m < meshes.members.size(); ++m) {
            EXPECT_TRUE(sameMesh(meshes.members[m], reference.members[m])) << "member " << m;
        }
        EXPECT_TRUE(sameMesh(meshes.mean, reference.mean));
        // Against one rank: the same numbers bit for bit.
        if (ranks == 1) {
            first = r;
            continue;
        }
        for (const char* key : {"distance_matrix", "linkage", "clusters", "members", "vertices",
                                "triangles", "pairs_without_overlap"}) {
            EXPECT_EQ(r.json[key], first.json[key]) << key;
        }
    }
}

TEST(MpiRanks, AFailingRankEndsEveryRankWithItsMessage) {
    test::TempDir dir;
    const std::string path = writeEnsemble(dir);
    setenv("ENSIL_MPI_TEST_FAIL_RANK", "1", 1);
    const Outcome r = run(dir, mpirun(3) + " preprocess " + path + " --iso 30 --no-cache --json");
    unsetenv("ENSIL_MPI_TEST_FAIL_RANK");
    EXPECT_NE(r.code, 0);
    EXPECT_NE(r.code, 124) << "the job hung until the time limit";
    EXPECT_NE(r.err.find("rank 1 of 3: failing on purpose"), std::string::npos) << r.err;
    EXPECT_TRUE(r.json.isEmpty()) << "a result was printed";
}

TEST(MpiRanks, RefusalsEveryRankMeetsAreSaidOnceAndEndTheJobNormally) {
    test::TempDir dir;
    const std::string path = writeEnsemble(dir);
    const Outcome r = run(dir, mpirun(2) + " preprocess " + path + " --iso 1e6 --no-cache");
    EXPECT_EQ(r.code, 1) << r.err;
    const std::string said = "outside the values of 'wind_speed'";
    const auto at = r.err.find(said);
    ASSERT_NE(at, std::string::npos) << r.err;
    EXPECT_EQ(r.err.find(said, at + 1), std::string::npos) << "said more than once: " << r.err;
}

TEST(MpiRanks, AMembersMeshCrossesBetweenRanksIntact) {
    prep::MemberResult r;
    r.meshed.mesh.vertices.resize(3);
    for (std::size_t v = 0; v < 3; ++v) {
        r.meshed.mesh.vertices[v] = {{std::uint16_t(v), 2, 3}, 4, 5, 6, {7, -8},
                                     {9, std::int16_t(v)}};
    }
    r.meshed.mesh.indices = {0, 1, 2, 2, 1, 0};
    r.meshed.mesh.boundsMin = {1.0F, 2.0F, 3.0F};
    r.meshed.mesh.boundsMax = {4.0F, 5.0F, 6.5F};
    r.meshed.mesh.outlyingnessScale = 0.25F;
    r.meshed.stats.triangles = 2;
    r.meshed.stats.extracted = 7;
    r.meshed.stats.vertices = 3;
    r.meshed.stats.error = 0.125F;
    r.distanceToMean = 1.5;
    const std::vector<char> bytes = mpi::serialiseMember(r);
    const prep::MemberResult back = mpi::deserialiseMember(bytes);
    EXPECT_TRUE(sameMesh(back.meshed.mesh, r.meshed.mesh));
    EXPECT_EQ(back.meshed.mesh.boundsMin, r.meshed.mesh.boundsMin);
    EXPECT_EQ(back.meshed.mesh.boundsMax, r.meshed.mesh.boundsMax);
    EXPECT_EQ(back.meshed.mesh.outlyingnessScale, 0.25F);
    EXPECT_EQ(back.meshed.stats.triangles, 2u);
    EXPECT_EQ(back.meshed.stats.extracted, 7u);
    EXPECT_EQ(back.meshed.stats.error, 0.125F);
    EXPECT_EQ(back.distanceToMean, 1.5);
    EXPECT_THROW(mpi::deserialiseMember(std::span<const char>(bytes.data(), bytes.size() - 1)),
                 data::Error);
}

#include "preprocessing/mesh_cache.h"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>

#include "data/error.h"
#include "fixtures.h"
#include "tests/support/temp_dir.h"

using namespace ensil;

namespace {
prep::IsovalueMeshes sample() {
    const auto e = test::analyticEnsemble(3, 24, 24, 24, [](auto m, auto i, auto j, auto k) {
        return glm::length(glm::vec3(i, j, k) - glm::vec3(11.5F)) - static_cast<float>(m);
    });
    prep::PipelineOptions options;
    options.isovalue = 7.0F;
    return prep::buildIsovalueMeshes(e, prep::computeEnsembleMoments(e),
                                     data::DisplayFrame(e.grid, 1.0F), options);
}

bool sameBytes(const data::PackedMesh& a, const data::PackedMesh& b) {
    return a.vertices.size() == b.vertices.size() && a.indices == b.indices &&
           a.boundsMin == b.boundsMin && a.boundsMax == b.boundsMax &&
           a.outlyingnessScale == b.outlyingnessScale &&
           std::memcmp(a.vertices.data(), b.vertices.data(),
                       a.vertices.size() * sizeof(data::PackedVertex)) == 0;
}

std::size_t filesIn(const std::filesystem::path& dir) {
    std::size_t n = 0;
    for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir)) ++n;
    return n;
}
}  // namespace

TEST(MeshCache, StoresAndLoadsExactlyWhatWasBuilt) {
    test::TempDir dir;
    const prep::MeshCache cache(dir.path());
    const prep::IsovalueMeshes built = sample();
    EXPECT_FALSE(cache.load("k").has_value());
    cache.store("k", built);
    EXPECT_EQ(filesIn(dir.path()), 1u) << "no temporary file left behind";
    const auto loaded = cache.load("k");
    ASSERT_TRUE(loaded.has_value());
    EXPECT_EQ(loaded->isovalue, built.isovalue);
    EXPECT_EQ(loaded->triangles, built.triangles);
    ASSERT_EQ(loaded->members.size(), built.members.size());
    EXPECT_TRUE(sameBytes(loaded->mean, built.mean));
    for (std::size_t m = 0; m < built.members.size(); ++m)
        EXPECT_TRUE(sameBytes(loaded->members[m], built.members[m]));
    EXPECT_FALSE(cache.load("another key").has_value());
}

TEST(MeshCache, DamagedEntriesAreDetectedRemovedAndMissed) {
    test::TempDir dir;
    const prep::MeshCache cache(dir.path());
    const prep::IsovalueMeshes built = sample();
    cache.store("flip", built);
    const auto path = cache.pathFor("flip");
    {
        std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
        f.seekp(static_cast<std::streamoff>(std::filesystem::file_size(path) - 100));
        const char x = 0x5a;
        f.write(&x, 1);
    }
    EXPECT_FALSE(cache.load("flip").has_value()) << "checksum must catch a changed byte";
    EXPECT_FALSE(std::filesystem::exists(path));

    cache.store("cut", built);
    std::filesystem::resize_file(cache.pathFor("cut"),
                                 std::filesystem::file_size(cache.pathFor("cut")) / 2);
    EXPECT_FALSE(cache.load("cut").has_value());
    EXPECT_FALSE(std::filesystem::exists(cache.pathFor("cut")));

    std::ofstream(cache.pathFor("junk"), std::ios::binary) << "not a cache entry";
    EXPECT_FALSE(cache.load("junk").has_value());
}

TEST(MeshCache, UnwritableFolderIsATypedError) {
    const prep::MeshCache cache("/proc/ensil-cannot-write-here");
    EXPECT_THROW(cache.store("k", sample()), data::Error);
}

TEST(MeshCache, TrimsTheOldestEntriesBeyondItsSize) {
    test::TempDir dir;
    const prep::IsovalueMeshes built = sample();
    const prep::MeshCache unlimited(dir.path());
    unlimited.store("first", built);
    const auto entryBytes = std::filesystem::file_size(unlimited.pathFor("first"));
    std::filesystem::last_write_time(
        unlimited.pathFor("first"),
        std::filesystem::file_time_type::clock::now() - std::chrono::hours(1));
    const prep::MeshCache small(dir.path(), entryBytes + entryBytes / 2);
    small.store("second", built);
    EXPECT_FALSE(std::filesystem::exists(small.pathFor("first")));
    EXPECT_TRUE(small.load("second").has_value());
}

TEST(MeshCache, KeysSayWhatChanges) {
    prep::PipelineOptions a;
    a.isovalue = 30.0F;
    prep::PipelineOptions b = a;
    b.isovalue = 30.000002F;
    EXPECT_NE(prep::pipelineKey(a, 1.0F), prep::pipelineKey(b, 1.0F)) << "floats must round-trip";
    EXPECT_NE(prep::pipelineKey(a, 1.0F), prep::pipelineKey(a, 2.0F));
    b = a;
    b.decimate = false;
    EXPECT_NE(prep::pipelineKey(a, 1.0F), prep::pipelineKey(b, 1.0F));
}

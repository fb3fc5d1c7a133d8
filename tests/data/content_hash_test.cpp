// The identity of input data (the mesh cache key) follows the file's contents: a file
// rewritten with the same size and its modification time put back is other data.
#include "data/content_hash.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "data/ensemble_reader.h"
#include "data/error.h"
#include "tests/support/temp_dir.h"

using namespace ensil;

TEST(ContentHash, ARewriteWithTheSameSizeAndTimeIsOtherData) {
    const test::TempDir dir;
    const std::string path = dir.file("members.nc");
    { std::ofstream(path, std::ios::binary) << "the first contents"; }
    const auto time = std::filesystem::last_write_time(path);
    data::DataSelection selection;
    selection.paths = {path};
    const std::string before = data::sourceIdentity(selection);
    const std::uint64_t hashBefore = data::contentHash(path);
    { std::ofstream(path, std::ios::binary) << "other contents!!!!"; }
    ASSERT_EQ(std::filesystem::file_size(path), 18U) << "the same size";
    std::filesystem::last_write_time(path, time);
    EXPECT_NE(data::contentHash(path), hashBefore);
    EXPECT_NE(data::sourceIdentity(selection), before)
        << "the stale cache entry would be taken for this data";
    // The same contents again: the same identity (the cache still hits when nothing changed).
    { std::ofstream(path, std::ios::binary) << "the first contents"; }
    std::filesystem::last_write_time(path, time);
    EXPECT_EQ(data::sourceIdentity(selection), before);
}

TEST(ContentHash, AFileThatCannotBeReadIsSaid) {
    EXPECT_THROW((void)data::contentHash("/nonexistent/members.nc"), data::Error);
}

TEST(ContentHash, AFileUnchangedSinceItWasHashedIsNotReadAgain) {
    // A file of the repository's test data, written long before this test runs (a file written
    // within the last second is always read again: content_hash.h says why).
    const std::string path = ENSIL_SHARED_DATA_DIR "/era5_eda_members.nc";
    const std::size_t readsBefore = data::contentHashFileReads();
    const std::uint64_t first = data::contentHash(path);
    const std::size_t readsAfterFirst = data::contentHashFileReads();
    EXPECT_LE(readsAfterFirst - readsBefore, 1U);
    EXPECT_EQ(data::contentHash(path), first);
    EXPECT_EQ(data::contentHashFileReads(), readsAfterFirst)
        << "the hash of an unchanged file is given again without reading it";
}

TEST(ContentHash, AFileJustWrittenIsReadEachTime) {
    // Its change time may be shared by a write in the same clock tick, so it is not remembered.
    const test::TempDir dir;
    const std::string path = dir.file("members.nc");
    { std::ofstream(path, std::ios::binary) << "contents"; }
    const std::size_t readsBefore = data::contentHashFileReads();
    const std::uint64_t first = data::contentHash(path);
    EXPECT_EQ(data::contentHash(path), first);
    EXPECT_EQ(data::contentHashFileReads(), readsBefore + 2);
}

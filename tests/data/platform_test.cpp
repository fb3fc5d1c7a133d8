// The Linux branches of data/platform.h against what Linux and the standard library say by
// other roads: std::filesystem for a file, /proc/meminfo's total for the memory, the pages'
// own addresses and contents for the huge-page mapping.
#include "data/platform.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "tests/support/temp_dir.h"

using namespace ensil;

namespace {
std::size_t memTotalBytes() {
    std::ifstream in("/proc/meminfo");
    std::string key, unit;
    std::size_t kib = 0;
    while (in >> key >> kib >> unit) {
        if (key == "MemTotal:") return kib * 1024;
    }
    return 0;
}
}  // namespace

TEST(Platform, AFileStampFollowsTheFileAndOnlyIt) {
    test::TempDir dir;
    const std::string path = dir.file("a.txt");
    std::ofstream(path) << "twelve bytes";
    const auto first = data::fileStamp(path);
    ASSERT_TRUE(first.has_value());
    EXPECT_EQ(first->size, std::filesystem::file_size(path));
    EXPECT_EQ(data::fileStamp(path), first) << "nothing changed";
    // Rewritten with other contents and a later time: another stamp.
    std::ofstream(path) << "thirteen byte";
    std::filesystem::last_write_time(
        path, std::filesystem::last_write_time(path) + std::chrono::seconds(5));
    const auto second = data::fileStamp(path);
    ASSERT_TRUE(second.has_value());
    EXPECT_EQ(second->size, 13U);
    EXPECT_GT(second->modifiedNs, first->modifiedNs);
    EXPECT_EQ(second->file, first->file) << "the same file";
    EXPECT_FALSE(data::fileStamp(dir.file("missing")).has_value());
}

TEST(Platform, MemoryFiguresAreThisMachinesAndThisProcesss) {
    const std::size_t available = data::availableMemoryBytes();
    EXPECT_GT(available, 0U);
    EXPECT_LE(available, memTotalBytes());
    const auto resident = data::residentMemoryBytes();
    const auto peak = data::peakResidentMemoryBytes();
    ASSERT_TRUE(resident && peak);
    EXPECT_GT(*resident, 1U << 20);
    EXPECT_GE(*peak, *resident);
    EXPECT_FALSE(data::standardErrorIsTerminal()) << "ctest captures standard error";
}

TEST(Platform, HugePagesAreAlignedZeroedAndWritable) {
    ASSERT_TRUE(data::mapsHugePages());
    const std::size_t bytes = std::size_t{5} << 20;
    auto* block = static_cast<unsigned char*>(data::mapHugePages(bytes));
    ASSERT_NE(block, nullptr);
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(block) % (std::size_t{2} << 20), 0U);
    std::size_t nonZero = 0;
    for (std::size_t i = 0; i < bytes; i += 4096) nonZero += block[i] != 0 ? 1 : 0;
    EXPECT_EQ(nonZero, 0U);
    block[bytes - 1] = 7;  // the last byte is the block's
    EXPECT_EQ(block[bytes - 1], 7);
    data::unmapHugePages(block, bytes);
}

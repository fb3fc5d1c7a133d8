#include "data/bulk_allocator.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <numeric>
#include <vector>

using namespace ensil;

TEST(BulkAllocator, LargeBlocksStartOnAHugePageBoundaryAndHoldEveryValue) {
    // Sizes round and odd, each at least the 1 MiB from which blocks are mapped: a member of
    // the demo (exactly 2 MiB), one a few values past 5 MiB, one just over the threshold.
    const std::vector<std::size_t> counts{std::size_t{1} << 19, (std::size_t{5} << 18) + 3,
                                          (std::size_t{1} << 18) + 1};
    std::vector<data::FieldValues> blocks;
    for (const std::size_t n : counts) {
        data::FieldValues v(n);
        // So that the kernel can back whole 2 MiB stretches with one page each (Linux).
        EXPECT_EQ(reinterpret_cast<std::uintptr_t>(v.data()) % (std::size_t{2} << 20), 0u) << n;
        std::iota(v.begin(), v.end(), 0.0F);
        blocks.push_back(std::move(v));
    }
    for (std::size_t b = 0; b < blocks.size(); ++b) {
        ASSERT_EQ(blocks[b].size(), counts[b]);
        EXPECT_EQ(blocks[b].front(), 0.0F);
        EXPECT_EQ(blocks[b].back(), static_cast<float>(counts[b] - 1)) << counts[b];
    }
    blocks.erase(blocks.begin() + 1);  // released out of order, the others intact
    EXPECT_EQ(blocks[1].back(), static_cast<float>(counts[2] - 1));
}

TEST(BulkAllocator, SmallAndEmptyBlocksAndGrowingOnesWork) {
    data::FieldValues small(100, 1.5F), none;
    EXPECT_EQ(small.back(), 1.5F);
    EXPECT_TRUE(none.empty());
    for (std::size_t i = 0; i < (std::size_t{3} << 18); ++i) none.push_back(static_cast<float>(i));
    EXPECT_EQ(none[123456], 123456.0F);
    EXPECT_EQ(none.back(), static_cast<float>((std::size_t{3} << 18) - 1));
}

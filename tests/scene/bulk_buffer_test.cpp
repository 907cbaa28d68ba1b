// The load's large-array storage (scenes/bulk_buffer.h): blocks of 4 MiB and more start on a
// 2 MiB boundary (what transparent huge pages need), contents survive growth across that size,
// and reserveUnwritten keeps what a vector holds.
#include "scenes/bulk_buffer.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <numeric>

namespace shadowlab {
namespace {

constexpr std::uintptr_t kHugePage = std::uintptr_t(2) << 20;

TEST(BulkBuffer, LargeBlocksAreHugePageAlignedAndHoldTheirValues) {
    BulkVector<float> large(3'000'000);  // 12 MB
    if (bulkMapsLargeBlocks()) {
        EXPECT_EQ(reinterpret_cast<std::uintptr_t>(large.data()) % kHugePage, 0u);
    }
    for (std::size_t i = 0; i < large.size(); ++i) large[i] = float(i);
    for (std::size_t i = 0; i < large.size(); i += 99'991) EXPECT_EQ(large[i], float(i));
    EXPECT_EQ(large.back(), float(large.size() - 1));

    BulkVector<std::uint32_t> small(1000, 7u);  // below the mapping size: the ordinary heap
    EXPECT_EQ(std::accumulate(small.begin(), small.end(), 0u), 7000u);
}

TEST(BulkBuffer, GrowthAcrossTheMappingSizeKeepsTheContents) {
    BulkVector<std::uint32_t> v;
    for (std::uint32_t i = 0; i < 2'500'000; ++i) v.push_back(i * 3u);  // 10 MB, from heap blocks to mappings
    ASSERT_EQ(v.size(), 2'500'000u);
    for (std::uint32_t i = 0; i < v.size(); i += 12'345) ASSERT_EQ(v[i], i * 3u);
    v = BulkVector<std::uint32_t>();  // unmapped
    EXPECT_EQ(v.capacity(), 0u);
}

TEST(BulkBuffer, ReserveUnwrittenKeepsWhatTheVectorHolds) {
    std::vector<std::uint32_t> v{1, 2, 3};
    reserveUnwritten(v, 3'000'000);
    EXPECT_GE(v.capacity(), 3'000'000u);
    EXPECT_EQ(v, (std::vector<std::uint32_t>{1, 2, 3}));
    for (std::uint32_t i = 0; i < 1'000'000; ++i) v.push_back(i);
    EXPECT_EQ(v[3 + 999'999], 999'999u);
    reserveUnwritten(v, 10);  // already large enough: unchanged
    EXPECT_EQ(v.size(), 1'000'003u);
    adviseHugePages(nullptr, 1u << 30);  // nothing to advise
}

}  // namespace
}  // namespace shadowlab

// The allocator of the mesher's largest arrays: large blocks on 2 MiB boundaries, small ones as
// operator new gives them, both holding what is written.
#include "mesher/huge_page_allocator.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <numeric>
#include <vector>

namespace mesher {
namespace {

TEST(HugePageAllocator, LargeBlocksStartOnAHugePageAndHoldTheirData) {
  std::vector<uint64_t, HugePageAllocator<uint64_t>> large(3'000'000);  // 24 MB
  EXPECT_EQ(reinterpret_cast<uintptr_t>(large.data()) % HugePageAllocator<uint64_t>::kHugePage, 0u);
  std::iota(large.begin(), large.end(), uint64_t{7});
  large.resize(5'000'000);  // moved into a new block, the old one given back
  EXPECT_EQ(reinterpret_cast<uintptr_t>(large.data()) % HugePageAllocator<uint64_t>::kHugePage, 0u);
  EXPECT_EQ(large[0], 7u);
  EXPECT_EQ(large[2'999'999], 3'000'006u);
  EXPECT_EQ(large[4'999'999], 0u);
}

TEST(HugePageAllocator, SmallBlocksGrowIntoLargeOnes) {
  std::vector<uint32_t, HugePageAllocator<uint32_t>> grown;
  for (uint32_t i = 0; i < 3'000'000; ++i) grown.push_back(i);  // through small blocks to 12 MB
  EXPECT_EQ(reinterpret_cast<uintptr_t>(grown.data()) % HugePageAllocator<uint32_t>::kHugePage, 0u);
  for (uint32_t i = 0; i < grown.size(); i += 99'991) EXPECT_EQ(grown[i], i);
  const std::vector<uint32_t, HugePageAllocator<uint32_t>> copy = grown;
  EXPECT_EQ(copy, grown);
  grown.clear();
  grown.shrink_to_fit();
  EXPECT_EQ(grown.capacity(), 0u);
}

}  // namespace
}  // namespace mesher

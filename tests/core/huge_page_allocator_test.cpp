#include "core/huge_page_allocator.h"

#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

namespace rastrace {
namespace {

using Vector = std::vector<std::uint64_t, HugePageAllocator<std::uint64_t>>;

TEST(HugePageAllocator, BlocksOfTwoMebibytesOrMoreAreAlignedToAHugePage) {
  Vector large;
  large.reserve((HugePageAllocator<std::uint64_t>::kHugePage / sizeof(std::uint64_t)) + 1);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(large.data()) % HugePageAllocator<std::uint64_t>::kHugePage, 0u);
}

TEST(HugePageAllocator, AVectorKeepsEveryValueWhileGrowingThroughSmallAndHugeBlocks) {
  // 1.5 million values: 12 MB, grown by doubling from small (heap) blocks into mapped ones.
  Vector values;
  for (std::uint64_t i = 0; i < 1'500'000; ++i) values.push_back(i * 2654435761u);
  std::uint64_t wrong = 0;
  for (std::uint64_t i = 0; i < values.size(); ++i) wrong += values[i] != i * 2654435761u;
  EXPECT_EQ(wrong, 0u);
  const std::size_t capacity = values.capacity();
  values.clear();
  values.resize(1000, 7);
  EXPECT_EQ(values.capacity(), capacity);  // cleared, not given back
  EXPECT_EQ(values[999], 7u);
}

}  // namespace
}  // namespace rastrace

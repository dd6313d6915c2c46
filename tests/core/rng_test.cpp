#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <vector>

#include "core/rng.h"

namespace rastrace {
namespace {

// splitmix64's published first outputs for seed 0 (the reference implementation by Vigna).
TEST(Rng, SplitMix64SequenceForSeedZero) {
  Rng rng(0);
  EXPECT_EQ(rng.next(), 0xE220A8397B1DCDAFull);
  EXPECT_EQ(rng.next(), 0x6E789E6AA1B965F4ull);
  EXPECT_EQ(rng.next(), 0x06C45D188009454Full);
}

TEST(Rng, BelowStaysInRange) {
  Rng rng(42);
  for (int i = 0; i < 1000; ++i) EXPECT_LT(rng.below(7), 7u);
}

TEST(Rng, ShuffleIsAPermutationFixedByTheSeed) {
  std::vector<int> a(100), b(100);
  std::iota(a.begin(), a.end(), 0);
  std::iota(b.begin(), b.end(), 0);
  Rng ra(9), rb(9);
  shuffle(std::span(a), ra);
  shuffle(std::span(b), rb);
  EXPECT_EQ(a, b);
  std::vector<int> sorted = a;
  std::sort(sorted.begin(), sorted.end());
  std::vector<int> identity(100);
  std::iota(identity.begin(), identity.end(), 0);
  EXPECT_EQ(sorted, identity);
  EXPECT_NE(a, identity);
  // Fisher-Yates from the back: the last slot takes the element at below(100) of a fresh Rng(9).
  Rng first(9);
  EXPECT_EQ(a.back(), static_cast<int>(first.below(100)));
}

}  // namespace
}  // namespace rastrace

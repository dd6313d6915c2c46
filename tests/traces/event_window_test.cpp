// Recording into storage a sink lends gives the sink the events that batches would, and leaves no
// slot behind: the same random run of single stores, four-event stores, appends and flushes goes
// through an EventWindow into a lending MemorySink and, through a TeeSink (which does not lend),
// into the batch calls of another; the batch path must still hand over exactly kCapacity events
// per batch between flushes, as the recorders always did.
#include <cstdint>
#include <random>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "traces/event_window.h"
#include "traces/memory_sink.h"
#include "traces/tee_sink.h"

namespace rastrace {
namespace {

constexpr std::size_t kCapacity = 16;

// Records the size of every texel batch it is handed.
class BatchSizes final : public EventSink {
 public:
  void texel_accesses(std::span<const TexelAccess> accesses) override { sizes.push_back(accesses.size()); }
  std::vector<std::size_t> sizes;
};

TexelAccess event(std::uint32_t n) {
  TexelAccess e;
  e.texture = n % 3;
  e.level = static_cast<std::uint8_t>(n % 5);
  e.x = n;
  e.y = n * 7;
  e.pixel_x = static_cast<std::uint16_t>(n);
  e.pixel_y = static_cast<std::uint16_t>(n >> 3);
  e.triangle = n / 9;
  return e;
}

bool same(const TexelAccess& a, const TexelAccess& b) {
  return a.texture == b.texture && a.level == b.level && a.x == b.x && a.y == b.y && a.pixel_x == b.pixel_x &&
         a.pixel_y == b.pixel_y && a.triangle == b.triangle;
}

// Feeds both windows the same seeded run; returns the events stored.
std::vector<TexelAccess> feed(EventWindow<TexelAccess, kCapacity, 4>& lent, EventWindow<TexelAccess, kCapacity, 4>& batched,
                              const MemorySink& lender, unsigned seed) {
  std::mt19937 random(seed);
  std::vector<TexelAccess> expected;
  std::uint32_t n = 0;
  for (int step = 0; step < 2000; ++step) {
    const unsigned what = random() % 20;
    if (what < 12) {
      const TexelAccess e = event(n++);
      *lent.reserve(1) = e;
      *batched.reserve(1) = e;
      lent.stored();
      batched.stored();
      expected.push_back(e);
    } else if (what < 17) {
      TexelAccess* a = lent.reserve(4);
      TexelAccess* b = batched.reserve(4);
      for (int i = 0; i < 4; ++i) {
        a[i] = b[i] = event(n++);
        expected.push_back(a[i]);
      }
      lent.stored();
      batched.stored();
    } else if (what < 19) {
      std::vector<TexelAccess> run(random() % (3 * kCapacity));
      for (TexelAccess& e : run) e = event(n++);
      lent.append(run);
      batched.append(run);
      expected.insert(expected.end(), run.begin(), run.end());
    } else {
      lent.flush();
      batched.flush();
      // Flushed: the lender holds every event and no open slot.
      EXPECT_EQ(lender.texels.size(), expected.size());
    }
  }
  lent.flush();
  batched.flush();
  return expected;
}

TEST(EventWindow, LentStorageHoldsWhatBatchesDeliverAndBatchesKeepTheirSizes) {
  for (unsigned seed = 1; seed <= 5; ++seed) {
    MemorySink lender, copier;
    BatchSizes sizes;
    TeeSink tee({&copier, &sizes});
    ASSERT_TRUE(lender.lends_storage());
    ASSERT_FALSE(tee.lends_storage());
    std::vector<TexelAccess> expected;
    {
      EventWindow<TexelAccess, kCapacity, 4> lent(&lender), batched(&tee);
      expected = feed(lent, batched, lender, seed);
    }
    ASSERT_EQ(lender.texels.size(), expected.size()) << seed;
    ASSERT_EQ(copier.texels.size(), expected.size()) << seed;
    for (std::size_t i = 0; i < expected.size(); ++i) {
      ASSERT_TRUE(same(lender.texels[i], expected[i])) << seed << " " << i;
      ASSERT_TRUE(same(copier.texels[i], expected[i])) << seed << " " << i;
    }
    // Batches are full but at flushes: kCapacity each, a flushed remainder smaller.
    std::size_t full = 0;
    for (const std::size_t size : sizes.sizes) {
      EXPECT_LE(size, kCapacity);
      EXPECT_GT(size, 0u);
      full += size == kCapacity;
    }
    EXPECT_GT(full, sizes.sizes.size() / 2) << seed;
  }
}

TEST(EventWindow, AnErrorUnwindingDropsTheEventsAndGivesTheLentSlotsBack) {
  MemorySink lender;
  try {
    EventWindow<TexelAccess, kCapacity, 4> window(&lender);
    for (std::uint32_t n = 0; n < 3 * kCapacity + 5; ++n) {
      *window.reserve(1) = event(n);
      window.stored();
    }
    throw std::runtime_error("sink failed");
  } catch (const std::runtime_error&) {
  }
  // The full spans were committed; the open one was given back empty.
  EXPECT_EQ(lender.texels.size(), 3 * kCapacity);
}

// Fetches stored but not yet committed reach the sink after begin_draw, as an unflushed batch
// would: the draw starts before them, not after the span's unset slots.
TEST(EventWindow, AFetchSpanOutAcrossBeginDrawIsNotCountedAsFetches) {
  MemorySink sink;
  EventWindow<VertexFetch, kCapacity> window(&sink);
  for (std::uint32_t n = 0; n < 5; ++n) {
    *window.reserve(1) = VertexFetch{n, n == 0};
    window.stored();
  }
  sink.begin_draw(DrawInfo{});
  window.flush();
  ASSERT_EQ(sink.draw_first_fetch.size(), 1u);
  EXPECT_EQ(sink.draw_first_fetch[0], 0u);
  EXPECT_EQ(sink.fetches.size(), 5u);
}

}  // namespace
}  // namespace rastrace

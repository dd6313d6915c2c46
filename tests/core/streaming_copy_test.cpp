#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/rng.h"
#include "core/streaming_copy.h"

namespace rastrace {
namespace {

// Every length around the streaming threshold and the line size, from every source and
// destination offset within a line: the bytes equal memcpy's, and the bytes either side of the
// destination are untouched (a whole-line store there would overwrite them).
TEST(StreamingCopy, EqualsMemcpyAtEveryLengthAndAlignmentAndWritesNothingOutside) {
  Rng rng(7);
  std::vector<std::uint8_t> source(4096 + 128);
  for (auto& b : source) b = static_cast<std::uint8_t>(rng.next());
  const std::size_t lengths[] = {0,
                                 1,
                                 63,
                                 64,
                                 65,
                                 kStreamedCopyMinBytes - 1,
                                 kStreamedCopyMinBytes,
                                 kStreamedCopyMinBytes + 1,
                                 kStreamedCopyMinBytes + 63,
                                 2048,
                                 4000,
                                 4096};
  constexpr std::uint8_t kGuard = 0xA5;
  for (const std::size_t length : lengths)
    for (std::size_t from = 0; from < 64; from += 7)
      for (std::size_t to = 0; to < 64; ++to) {
        std::vector<std::uint8_t> out(4096 + 256, kGuard);
        copy_bytes_streaming(out.data() + 64 + to, source.data() + from, length);
        streaming_fence();
        for (std::size_t i = 0; i < out.size(); ++i) {
          const bool inside = i >= 64 + to && i < 64 + to + length;
          const std::uint8_t expected = inside ? source[from + i - 64 - to] : kGuard;
          ASSERT_EQ(out[i], expected) << "length " << length << ", source offset " << from << ", destination offset "
                                      << to << ", byte " << i;
        }
      }
}

TEST(StreamingCopy, CopiesTwelveByteEventsWhole) {
  struct Event {
    std::uint16_t x, y;
    std::uint8_t op, mask;
    std::uint32_t triangle;
  };
  std::vector<Event> events(300), copied(301);
  for (std::size_t i = 0; i < events.size(); ++i)
    events[i] = {static_cast<std::uint16_t>(i), static_cast<std::uint16_t>(2 * i), 1, 15,
                 static_cast<std::uint32_t>(i * 7)};
  copy_streaming(events.data(), events.data() + events.size(), copied.data() + 1);
  streaming_fence();
  for (std::size_t i = 0; i < events.size(); ++i) {
    EXPECT_EQ(copied[i + 1].x, events[i].x);
    EXPECT_EQ(copied[i + 1].triangle, events[i].triangle);
  }
}

}  // namespace
}  // namespace rastrace

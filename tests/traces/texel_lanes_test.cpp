// The SIMD kernels between texel records and lanes (traces/texel_lanes.h): interleaved records
// are byte for byte the portable ones, and so are split lanes; byte-delta prefix sums equal a
// 64-bit running value's low 32 bits and find every step out of [0, 2^32); through the decoder, a
// column leaving its range by 1-byte steps is an error, and a column crossing 2^31 is not; the
// portable paths (machines without AVX2) decode a frame-like chunk, whole or damaged, to the same
// records and errors.
#include <algorithm>
#include <cstddef>
#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "traces/chunk_codec.h"
#include "traces/texel_lanes.h"

namespace rastrace {
namespace {

struct Random {
  std::uint64_t state;
  std::uint64_t next() {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return state >> 17;
  }
};

TEST(TexelLanes, InterleavedRecordsAreTheFieldsTruncatedToTheirWidthsWithZeroPadding) {
  Random random{11};
  for (const bool details : {true, false}) {
    for (std::size_t count = 0; count <= 41; ++count) {
      std::vector<std::uint32_t> lane[7];
      for (auto& l : lane)
        for (std::size_t i = 0; i < count; ++i) l.push_back(static_cast<std::uint32_t>(random.next()));
      const TexelLanes lanes{lane[0].data(),
                             lane[1].data(),
                             lane[2].data(),
                             lane[3].data(),
                             details ? lane[4].data() : nullptr,
                             details ? lane[5].data() : nullptr,
                             details ? lane[6].data() : nullptr};
      // Garbage first: every byte, padding included, must be written.
      std::vector<TexelAccess> fast(count), portable(count);
      if (count > 0) {  // (data() of an empty vector may be null, which memset must not get)
        std::memset(static_cast<void*>(fast.data()), 0xA5, count * sizeof(TexelAccess));
        std::memset(static_cast<void*>(portable.data()), 0x5A, count * sizeof(TexelAccess));
      }
      interleave_texels(lanes, count, fast.data());
      interleave_texels_portable(lanes, count, portable.data());
      if (count > 0) {
        ASSERT_EQ(std::memcmp(fast.data(), portable.data(), count * sizeof(TexelAccess)), 0) << count;
      }
      for (std::size_t i = 0; i < count; ++i) {
        const TexelAccess& t = fast[i];
        ASSERT_EQ(t.texture, lane[0][i] & 0xFFFF);
        ASSERT_EQ(t.level, lane[1][i] & 0xFF);
        ASSERT_EQ(t.x, lane[2][i] & 0xFFFF);
        ASSERT_EQ(t.y, lane[3][i] & 0xFFFF);
        ASSERT_EQ(t.pixel_x, details ? lane[4][i] & 0xFFFF : 0u);
        ASSERT_EQ(t.pixel_y, details ? lane[5][i] & 0xFFFF : 0u);
        ASSERT_EQ(t.triangle, details ? lane[6][i] : 0u);
        const unsigned char* bytes = reinterpret_cast<const unsigned char*>(&t);
        ASSERT_EQ(bytes[offsetof(TexelAccess, level) + 1], 0) << "padding of record " << i;
      }
    }
  }
}

// zig-zag, as the column coding stores a delta
std::uint8_t zigzag(int delta) { return static_cast<std::uint8_t>(delta >= 0 ? 2 * delta : -2 * delta - 1); }

TEST(TexelLanes, SplitLanesHoldEachFieldWidenedAndIgnoreThePaddingByte) {
  Random random{29};
  for (std::size_t count = 0; count <= 41; ++count) {
    std::vector<TexelAccess> records(count);
    for (TexelAccess& r : records) {
      const std::uint64_t a = random.next(), b = random.next();
      r = TexelAccess{static_cast<std::uint16_t>(a),       static_cast<std::uint8_t>(a >> 16),
                      static_cast<std::uint16_t>(a >> 24), static_cast<std::uint16_t>(a >> 40),
                      static_cast<std::uint16_t>(b),       static_cast<std::uint16_t>(b >> 16),
                      static_cast<std::uint32_t>(b >> 32)};
      // A padding byte that is not zero (records a caller built itself) must not reach a lane.
      reinterpret_cast<unsigned char*>(&r)[3] = static_cast<unsigned char>(a >> 56);
    }
    // Lanes further apart than the records, as an open chunk's are, with garbage between them.
    const std::size_t stride = count + 3;
    std::vector<std::uint32_t> fast(7 * stride, 0xA5A5A5A5u), portable(7 * stride, 0xA5A5A5A5u);
    split_texels(records.data(), count, fast.data(), stride);
    split_texels_portable(records.data(), count, portable.data(), stride);
    ASSERT_EQ(fast, portable) << count;
    for (std::size_t i = 0; i < count; ++i) {
      const TexelAccess& r = records[i];
      const std::uint32_t want[7] = {r.texture, r.level, r.x, r.y, r.pixel_x, r.pixel_y, r.triangle};
      for (std::size_t k = 0; k < 7; ++k) ASSERT_EQ(fast[k * stride + i], want[k]) << count << " " << i << " " << k;
    }
    for (std::size_t k = 0; k < 7; ++k)
      for (std::size_t i = count; i < stride; ++i) ASSERT_EQ(fast[k * stride + i], 0xA5A5A5A5u) << "past the records";
  }
}

TEST(TexelLanes, ByteDeltaSumsAreTheLow32BitsOfTheRunningValueAndFindEveryStepOutOf32Bits) {
  Random random{5};
  // Starts near 0 (steps below it), near 2^31 (crossing it is in range), near 2^32 (above it).
  for (const std::uint64_t start : {3ull, 0x7FFFFF80ull, 0xFFFFFF00ull, 0x12345678ull}) {
    for (int trial = 0; trial < 50; ++trial) {
      const std::size_t count = 8 + random.next() % 120;
      const int drift = static_cast<int>(random.next() % 5) - 2;  // -2..2: values wander up or down
      std::vector<std::uint8_t> deltas(count + 8);
      for (std::size_t i = 0; i < count; ++i)
        deltas[i] = zigzag(std::clamp(static_cast<int>(random.next() % 256) - 128 + drift * 40, -128, 127));
      std::vector<std::uint32_t> lane(count, 0);
      ByteDeltaSums sums{static_cast<std::uint32_t>(start)};
      const std::size_t done = add_byte_deltas(deltas.data(), count, false, sums, lane.data());
      ASSERT_EQ(done % 8, 0u);
      ASSERT_LE(done, count);
      if (done == 0) GTEST_SKIP() << "no AVX2 on this machine: the scalar decoder does the work";
      ASSERT_GT(done + 8, count);  // every whole group of eight
      std::uint64_t value = start, ored = 0;
      bool out = false;
      for (std::size_t i = 0; i < done; ++i) {
        const int d = (deltas[i] & 1) ? -(deltas[i] >> 1) - 1 : deltas[i] >> 1;
        value += static_cast<std::uint64_t>(static_cast<std::int64_t>(d));
        out |= value > 0xFFFFFFFFull;
        ored |= value & 0xFFFFFFFFull;
        ASSERT_EQ(lane[i], static_cast<std::uint32_t>(value)) << "record " << i << " from " << start;
      }
      EXPECT_EQ(sums.value, static_cast<std::uint32_t>(value));
      EXPECT_EQ(sums.left_32_bits, out) << "from " << start << ", trial " << trial;
      if (!out) {
        EXPECT_EQ(sums.ored, ored);
      }
    }
  }
}

TEST(TexelLanes, ByteDeltaSumsStopAtTheFirstGroupOfEightHoldingAnEscape) {
  std::vector<std::uint8_t> deltas(40, zigzag(1));
  deltas[21] = 0xFF;  // in the third group of eight
  std::vector<std::uint32_t> lane(40);
  ByteDeltaSums sums{100};
  const std::size_t done = add_byte_deltas(deltas.data(), 40, true, sums, lane.data());
  if (done == 0) GTEST_SKIP() << "no AVX2 on this machine";
  EXPECT_EQ(done, 16u);
  EXPECT_EQ(sums.value, 116u);
  EXPECT_EQ(lane[15], 116u);
  // Without escapes (mode 1) 0xFF is the delta -128.
  ByteDeltaSums plain{1000};
  EXPECT_EQ(add_byte_deltas(deltas.data(), 40, false, plain, lane.data()), 40u);
  EXPECT_EQ(plain.value, 1000u + 39 - 128);
}

// A texel chunk's raw bytes: every column constant (mode 0) except `column`, which starts at
// `first` and moves by `steps` (1-byte deltas, mode 1).
std::string chunk_with_steps(int column, std::uint64_t first, const std::vector<int>& steps) {
  std::string raw;
  const auto put64 = [&](std::uint64_t v) { raw.append(reinterpret_cast<const char*>(&v), 8); };
  for (int k = 0; k < 7; ++k) {
    if (k != column) {
      raw.push_back(0);
      put64(k == 1 ? 2 : 9);
      continue;
    }
    raw.push_back(1);
    put64(first);
    for (const int s : steps) raw.push_back(static_cast<char>(zigzag(s)));
  }
  return raw;
}

std::string decode(const std::string& raw, std::uint32_t n, std::vector<TexelAccess>& out, bool details = true) {
  return decode_texel_records({reinterpret_cast<const std::uint8_t*>(raw.data()), raw.size()}, n, out, details);
}

TEST(TexelLanes, AColumnLeavingItsRangeByByteStepsIsAnErrorWhereverItLeaves) {
  std::vector<TexelAccess> out;
  for (const std::size_t n : {5u, 20u, 700u}) {  // the scalar tail, SIMD groups, two blocks
    for (std::size_t at = 1; at + 1 < n; at += n / 5 + 1) {
      // x: down from `at` by 1, so the value crosses 0 at record at + 1, then back up above 0.
      std::vector<int> down(n - 1, 0);
      for (std::size_t i = 0; i + 1 < n; ++i) down[i] = i <= at ? -1 : (i < at + 4 ? 1 : 0);
      EXPECT_EQ(decode(chunk_with_steps(2, at, down), static_cast<std::uint32_t>(n), out),
                "a value in the x column is out of range (at most 65535)")
          << n << " records, crossing 0 after " << at;
      // y: up to 65535 (its limit) at record `at`, then one more.
      std::vector<int> up(n - 1, 0);
      for (std::size_t i = 0; i + 1 < n; ++i) up[i] = i <= at ? 1 : 0;
      EXPECT_EQ(decode(chunk_with_steps(3, 0xFFFFull - at, up), static_cast<std::uint32_t>(n), out),
                "a value in the y column is out of range (at most 65535)")
          << n << " records, crossing 65536 after " << at;
      // triangle: up to 2^32 - 1, then one more (the lanes hold 32 bits: the step out of them).
      EXPECT_EQ(decode(chunk_with_steps(6, 0xFFFFFFFFull - at, up), static_cast<std::uint32_t>(n), out),
                "a value in the triangle column is out of range (at most 4294967295)")
          << n << " records, crossing 2^32 after " << at;
      // level: above 255 (its limit) from record at + 1 on.
      EXPECT_EQ(decode(chunk_with_steps(1, 255 - at, up), static_cast<std::uint32_t>(n), out),
                "a value in the level column is out of range (at most 255)");
      // triangle: crossing 2^31 is in range, and every value is exact.
      ASSERT_EQ(decode(chunk_with_steps(6, 0x80000000ull - at, up), static_cast<std::uint32_t>(n), out), "");
      for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(out[i].triangle, 0x80000000ull - at + std::min(i, at + 1)) << i;
    }
  }
}

// A rendered frame's texels in miniature: fragments of 8 texels (a 2x2 footprint on two levels)
// walking a scanline of quads, the texel position jumping at times (escaped deltas), triangles
// changing every few fragments.
std::vector<TexelAccess> fragments(std::size_t count) {
  Random random{3};
  std::vector<TexelAccess> t;
  std::uint32_t px = 0, py = 100, triangle = 7, u = 500, v = 20;
  while (t.size() < count) {
    if (random.next() % 5 == 0) ++triangle;
    if (random.next() % 40 == 0) u = static_cast<std::uint32_t>(random.next() % 4096);  // escapes
    px = (px + 1) % 1024;
    u += static_cast<std::uint32_t>(random.next() % 3);
    for (std::uint8_t level = 0; level < 2; ++level)
      for (std::uint32_t k = 0; k < 4 && t.size() < count; ++k)
        t.push_back({1, level, static_cast<std::uint16_t>((u >> level) + (k & 1)),
                     static_cast<std::uint16_t>((v >> level) + (k >> 1)), static_cast<std::uint16_t>(px),
                     static_cast<std::uint16_t>(py), triangle});
  }
  return t;
}

TEST(TexelLanes, ThePortablePathsDecodeTheSameRecordsAndErrorsAsTheSimdOnes) {
  const std::vector<TexelAccess> texels = fragments(65536);
  std::string raw;
  encode_texel_records(texels, raw);
  ASSERT_EQ(static_cast<std::uint8_t>(raw[9]), 0x82);  // the level column (after the texture's 9 bytes): runs
  std::vector<TexelAccess> simd, portable;
  for (const bool details : {true, false}) {
    for (int damage = 0; damage < 40; ++damage) {
      std::string bytes = raw;
      if (damage > 0) bytes[(damage * 7919u) % bytes.size()] ^= static_cast<char>(1 << (damage % 8));
      const std::string simd_error = decode(bytes, 65536, simd, details);
      use_texel_lane_simd(false);
      const std::string portable_error = decode(bytes, 65536, portable, details);
      use_texel_lane_simd(true);
      ASSERT_EQ(portable_error, simd_error) << "damage " << damage;
      if (damage == 0) {
        ASSERT_EQ(simd_error, "");
      }
      if (!simd_error.empty()) continue;
      ASSERT_EQ(std::memcmp(simd.data(), portable.data(), simd.size() * sizeof(TexelAccess)), 0) << damage;
      if (damage > 0 || !details) continue;
      for (std::size_t i = 0; i < texels.size(); ++i) {
        const TexelAccess &g = simd[i], &w = texels[i];
        ASSERT_TRUE(g.texture == w.texture && g.level == w.level && g.x == w.x && g.y == w.y &&
                    g.pixel_x == w.pixel_x && g.pixel_y == w.pixel_y && g.triangle == w.triangle)
            << "record " << i;
      }
    }
  }
}

}  // namespace
}  // namespace rastrace

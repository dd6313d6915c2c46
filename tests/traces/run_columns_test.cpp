// Run columns (trace version 4, chunk_codec.h mode 0x82): chosen where a field holds still over
// runs of 4 records or more on average and the column shrinks; exact round trips across the
// decoder's blocks and long runs; damaged run columns are errors naming the column; files of
// earlier versions cannot hold them.
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/error.h"
#include "tests/support/temp_dir.h"
#include "traces/chunk_codec.h"
#include "traces/trace_format.h"
#include "traces/trace_reader.h"
#include "traces/trace_writer.h"

namespace rastrace {
namespace {

using ::testing::HasSubstr;

// 1024 texels: a constant texture, the level in runs of 4, x stepping every record, y in runs of
// 2 (too short to be stored as runs), pixel_x in runs of 8, a constant pixel_y, and a triangle
// constant for 1000 records (longer than one run can be) then jumping far (an escaped delta).
std::vector<TexelAccess> footprints() {
  std::vector<TexelAccess> t;
  for (std::uint32_t i = 0; i < 1024; ++i)
    t.push_back({3, static_cast<std::uint8_t>((i / 4) % 2), static_cast<std::uint16_t>(i),
                 static_cast<std::uint16_t>(i / 2), static_cast<std::uint16_t>(i / 8), 7, i < 1000 ? 5u : 100000u});
  return t;
}

std::span<const std::uint8_t> bytes_of(const std::string& raw) {
  return {reinterpret_cast<const std::uint8_t*>(raw.data()), raw.size()};
}

void expect_same(const std::vector<TexelAccess>& got, const std::vector<TexelAccess>& want) {
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < want.size(); ++i) {
    const TexelAccess &g = got[i], &w = want[i];
    ASSERT_TRUE(g.texture == w.texture && g.level == w.level && g.x == w.x && g.y == w.y && g.pixel_x == w.pixel_x &&
                g.pixel_y == w.pixel_y && g.triangle == w.triangle)
        << "record " << i;
  }
}

TEST(RunColumns, ChosenWhereRunsAverageFourRecordsOrMoreAndTheColumnShrinks) {
  const std::vector<TexelAccess> texels = footprints();
  std::string raw;
  encode_texel_records(texels, raw);
  // texture constant: 9 bytes; level, 256 runs: 1 + 8 + 4 + 4 + 256 lengths + 255 deltas = 528;
  // x and y, 1-byte deltas: 1 + 8 + 1023 = 1032 each; pixel_x, 128 runs: 272; pixel_y: 9;
  // triangle, 5 runs (255, 255, 255, 235, 24), one escaped delta: 1 + 8 + 4 + 4 + 5 + 4 + 8 = 34.
  EXPECT_EQ(raw.size(), 9u + 528 + 1032 + 1032 + 272 + 9 + 34);
  EXPECT_EQ(static_cast<std::uint8_t>(raw[9]), 0x82);                // level
  EXPECT_EQ(static_cast<std::uint8_t>(raw[9 + 528]), 1);             // x
  EXPECT_EQ(static_cast<std::uint8_t>(raw[9 + 528 + 1032]), 1);      // y: runs of 2 stay deltas
  EXPECT_EQ(static_cast<std::uint8_t>(raw[raw.size() - 34]), 0x82);  // triangle
  std::vector<TexelAccess> back;
  ASSERT_EQ(decode_texel_records(bytes_of(raw), 1024, back), "");
  expect_same(back, texels);
  std::vector<TexelAccess> addresses;
  ASSERT_EQ(decode_texel_records(bytes_of(raw), 1024, addresses, false), "");
  for (std::size_t i = 0; i < texels.size(); ++i)
    ASSERT_TRUE(addresses[i].level == texels[i].level && addresses[i].triangle == 0) << i;
  // A decoder for files before version 4 refuses the mode.
  EXPECT_EQ(decode_texel_records(bytes_of(raw), 1024, back, true, false), "bad column width 130 in the level column");
}

TEST(RunColumns, RunsOfEveryLengthRoundTripAcrossTheDecodersBlocks) {
  // 65536 records (a full chunk) of runs 1 to 600 long, a different pattern per field, so runs
  // start and end at every offset of the decoder's 512-record blocks and of its 8-record steps.
  std::vector<TexelAccess> texels(65536);
  std::uint64_t state = 7;
  const auto next = [&](std::uint64_t bound) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return (state >> 33) % bound;
  };
  std::uint32_t level_left = 0, pixel_left = 0, triangle_left = 0;
  TexelAccess current{};
  for (std::size_t i = 0; i < texels.size(); ++i) {
    if (level_left == 0)
      level_left = static_cast<std::uint32_t>(1 + next(12)), current.level = static_cast<std::uint8_t>(next(9));
    if (pixel_left == 0) {
      pixel_left = static_cast<std::uint32_t>(4 + next(9));
      current.pixel_x = static_cast<std::uint16_t>(next(1024));
      current.pixel_y = static_cast<std::uint16_t>(next(1024));
    }
    if (triangle_left == 0)
      triangle_left = static_cast<std::uint32_t>(1 + next(600)),
      current.triangle = static_cast<std::uint32_t>(next(1u << 30));
    current.x = static_cast<std::uint32_t>(next(4096));
    current.y = static_cast<std::uint32_t>(i / 3);
    texels[i] = current;
    --level_left, --pixel_left, --triangle_left;
  }
  std::string raw;
  encode_texel_records(texels, raw);
  EXPECT_EQ(static_cast<std::uint8_t>(raw[9]), 0x82);                  // the level column is stored as runs
  std::vector<TexelAccess> back(5, TexelAccess{9, 9, 9, 9, 9, 9, 9});  // stale records must go
  ASSERT_EQ(decode_texel_records(bytes_of(raw), 65536, back), "");
  expect_same(back, texels);
  // And in a file, through the reader.
  const testing::TempDir dir;
  {
    TraceWriter writer(dir.file("runs.rtrace"), {});
    writer.texel_accesses(texels);
    writer.finish();
  }
  TraceReader reader(dir.file("runs.rtrace"));
  EXPECT_EQ(reader.version(), kTraceVersion);
  expect_same(reader.read_chunk(0).texels, texels);
}

// The level column of footprints(): mode byte at 9, first value, u32 runs at 18, u32 escapes at
// 22, then 256 lengths from 26.
constexpr std::size_t kLevel = 9;

std::string damaged(std::size_t at, const void* bytes, std::size_t n) {
  std::string raw;
  encode_texel_records(footprints(), raw);
  std::memcpy(raw.data() + at, bytes, n);
  return raw;
}

std::string decode_error(const std::string& raw) {
  std::vector<TexelAccess> out;
  return decode_texel_records(bytes_of(raw), 1024, out);
}

TEST(RunColumns, DamagedRunColumnsAreErrorsNamingTheColumn) {
  const std::uint32_t zero = 0, too_many = 1025, escapes = 300;
  const std::uint8_t empty = 0, longer = 5, not_escaped = 9;
  EXPECT_EQ(
      decode_error(damaged(kLevel + 9, &zero, 4)),
      "0 runs with 0 escaped deltas for 1024 records in the level column (expected 1 to 1024 runs, fewer escapes)");
  EXPECT_THAT(decode_error(damaged(kLevel + 9, &too_many, 4)), HasSubstr("1025 runs"));
  EXPECT_THAT(decode_error(damaged(kLevel + 13, &escapes, 4)), HasSubstr("256 runs with 300 escaped deltas"));
  EXPECT_EQ(decode_error(damaged(kLevel + 17, &empty, 1)),
            "run lengths include 0 for 1024 records in the level column");
  EXPECT_EQ(decode_error(damaged(kLevel + 17 + 100, &longer, 1)),
            "run lengths add up to 1025 for 1024 records in the level column");
  // The triangle's one escaped delta (the last of its 4 deltas) made an ordinary one: the 8 bytes
  // stored for it are left over.
  std::string raw;
  encode_texel_records(footprints(), raw);
  EXPECT_EQ(decode_error(damaged(raw.size() - 34 + 25, &not_escaped, 1)),
            "escaped deltas do not match their escapes in the triangle column");
  // Cut inside the level's lengths.
  EXPECT_EQ(decode_error(raw.substr(0, kLevel + 17 + 100)), "record data ends inside the level");
  // Every truncation is an error, never a read past the end (ASan checks the reads).
  for (std::size_t cut = 0; cut < raw.size(); ++cut) ASSERT_NE(decode_error(raw.substr(0, cut)), "") << cut;
}

TEST(RunColumns, ARunColumnInAFileOfAnEarlierVersionIsRefused) {
  const testing::TempDir dir;
  const std::string path = dir.file("relabelled.rtrace");
  {
    TraceWriter writer(path, {});
    writer.texel_accesses(footprints());
    writer.finish();
  }
  std::string bytes = testing::slurp(path);
  const std::uint32_t two = 2;
  std::memcpy(bytes.data() + 8, &two, 4);  // the version field is outside every checksum
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << bytes;
  }
  TraceReader reader(path);
  ASSERT_EQ(reader.version(), 2u);
  try {
    reader.read_chunk(0);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("chunk 0: bad column width 130 in the level column"));
  }
}

}  // namespace
}  // namespace rastrace

// The column encoder works on lanes, in vector lanes, and finds runs from a list of changes: its
// bytes must be those of the format read plainly (chunk_codec.h), record by record, for every
// mode and at every boundary between modes, with and without its AVX2 paths; and a writer that
// starts from what an earlier writer left (kept compressors and chunks) must write the same file
// as one that starts afresh.
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <span>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/temp_dir.h"
#include "traces/append_bytes.h"
#include "traces/chunk_codec.h"
#include "traces/column_encoder.h"
#include "traces/trace_writer.h"

namespace rastrace {
namespace {

// The format, written the plain way: one pass per mode, one record at a time.

std::uint64_t zigzag(std::uint64_t d) {
  return (d << 1) ^ static_cast<std::uint64_t>(static_cast<std::int64_t>(d) >> 63);
}

void put_escapable(std::string& bytes, std::string& escaped, std::uint64_t z) {
  if (z < 0xFF) {
    bytes.push_back(static_cast<char>(z));
    return;
  }
  bytes.push_back(static_cast<char>(0xFF));
  append_bytes(escaped, z);
}

std::string plain_column(const std::vector<std::uint64_t>& v) {
  const std::size_t n = v.size();
  std::vector<std::uint64_t> z;
  for (std::size_t i = 1; i < n; ++i) z.push_back(zigzag(v[i] - v[i - 1]));
  std::uint64_t widest = 0, large = 0;
  for (std::uint64_t d : z) {
    widest |= d;
    large += d >= 0xFF;
  }
  // Runs: a new one where the value changes or the current one holds 255 records.
  std::vector<std::uint64_t> lengths{1};
  std::vector<std::uint64_t> run_deltas;
  for (std::uint64_t d : z) {
    if (d != 0 || lengths.back() == 255) {
      lengths.push_back(1);
      run_deltas.push_back(d);
    } else {
      ++lengths.back();
    }
  }
  const std::uint64_t width = widest == 0             ? 0
                              : widest < 0x100        ? 1
                              : widest < 0x10000      ? 2
                              : widest < (1ull << 32) ? 4
                                                      : 8;
  const std::uint64_t deltas = z.size();
  const bool escaped = width > 1 && deltas + 4 + 8 * large < deltas * width;
  const std::uint64_t plain = escaped ? deltas + 4 + 8 * large : deltas * width;
  const std::uint64_t runs = lengths.size();
  std::string out;
  if (width != 0 && runs * 4 <= n && 8 + 2 * runs - 1 + 8 * large < plain) {
    out.push_back(static_cast<char>(0x82));
    append_bytes<std::uint64_t>(out, v[0]);
    append_bytes<std::uint32_t>(out, static_cast<std::uint32_t>(runs));
    append_bytes<std::uint32_t>(out, static_cast<std::uint32_t>(large));
    for (std::uint64_t length : lengths) out.push_back(static_cast<char>(length));
    std::string bytes, escapes;
    for (std::uint64_t d : run_deltas) put_escapable(bytes, escapes, d);
    return out + bytes + escapes;
  }
  out.push_back(static_cast<char>(escaped ? 0x81 : width));
  append_bytes<std::uint64_t>(out, n ? v[0] : 0);
  if (width == 0) return out;
  if (escaped) {
    append_bytes<std::uint32_t>(out, static_cast<std::uint32_t>(large));
    std::string bytes, escapes;
    for (std::uint64_t d : z) put_escapable(bytes, escapes, d);
    return out + bytes + escapes;
  }
  for (std::uint64_t d : z) out.append(reinterpret_cast<const char*>(&d), width);  // little endian
  return out;
}

// Columns of every shape the modes split on, 32-bit values unless `wide`.
std::vector<std::uint64_t> random_column(std::mt19937_64& random, int shape, std::size_t n, bool wide) {
  std::vector<std::uint64_t> v(n);
  const std::uint64_t mask = wide ? ~0ull : 0xFFFFFFFFull;
  std::uint64_t value = random() & mask;
  std::size_t hold = 0;
  for (std::size_t i = 0; i < n; ++i) {
    switch (shape) {
      case 0:  // constant
        break;
      case 1:  // small steps both ways
        value += static_cast<std::uint64_t>(static_cast<std::int64_t>(random() % 9) - 4);
        break;
      case 2:  // runs of 1 to 600 records (some longer than a run can be), small steps between
        if (hold == 0) {
          hold = 1 + random() % (random() % 4 == 0 ? 600 : 12);
          value += 1 + random() % 200;
        }
        --hold;
        break;
      case 3:  // runs of exactly 254, 255, 256, 510 or 511 records
        if (hold == 0) {
          const std::size_t lengths[] = {254, 255, 256, 510, 511};
          hold = lengths[random() % 5];
          value += 1 + random() % 3;
        }
        --hold;
        break;
      case 4:  // small steps with a rare far jump (escapes)
        value += random() % 500 == 0 ? random() : random() % 7;
        break;
      case 5:  // steps of every width
        value += random() >> (random() % 64);
        break;
      default:  // values at both ends of the range: deltas past int32's range
        value = random() % 2 ? random() % 100 : mask - random() % 100;
        break;
    }
    v[i] = value & mask;
  }
  return v;
}

std::string encoded(const std::vector<std::uint64_t>& v, bool wide, ColumnScratch& scratch) {
  std::string out = "prefix";  // the encoder appends
  if (wide) {
    put_column(out, std::span<const std::uint64_t>(v), scratch);
  } else {
    const std::vector<std::uint32_t> narrow(v.begin(), v.end());
    put_column(out, std::span<const std::uint32_t>(narrow), scratch);
  }
  return out.substr(6);
}

TEST(ColumnEncoder, EveryColumnIsTheFormatReadPlainlyWithAndWithoutSimd) {
  std::mt19937_64 random(7);
  ColumnScratch scratch;  // kept across columns of every size, as a writer's thread keeps it
  int checked = 0;
  for (const bool simd : {true, false}) {
    use_column_encoder_simd(simd);
    for (int shape = 0; shape <= 6; ++shape)
      for (const std::size_t n : {std::size_t{0}, std::size_t{1}, std::size_t{2}, std::size_t{7}, std::size_t{8},
                                  std::size_t{9}, std::size_t{1000}, std::size_t{65536}})
        for (const bool wide : {false, true}) {
          const std::vector<std::uint64_t> v = random_column(random, shape, n, wide);
          ASSERT_EQ(encoded(v, wide, scratch), plain_column(v))
              << "shape " << shape << ", " << n << " records" << (wide ? ", 64-bit" : "") << (simd ? "" : ", portable");
          ++checked;
        }
  }
  use_column_encoder_simd(true);
  EXPECT_EQ(checked, 2 * 7 * 8 * 2);
}

TEST(ColumnEncoder, EveryModeIsChosenSomewhereInTheCheckedShapes) {
  std::mt19937_64 random(11);
  ColumnScratch scratch;
  std::vector<int> modes;
  for (int shape = 0; shape <= 6; ++shape)
    modes.push_back(static_cast<unsigned char>(encoded(random_column(random, shape, 5000, false), false, scratch)[0]));
  for (const int mode : {0, 1, 0x81, 0x82}) EXPECT_NE(std::find(modes.begin(), modes.end(), mode), modes.end()) << mode;
}

TEST(ColumnEncoder, TexelColumnsEncodeAsTheirRecords) {
  std::mt19937 random(3);
  std::vector<TexelAccess> records(5000);
  std::uint32_t x = 0;
  for (std::size_t i = 0; i < records.size(); ++i) {
    x += random() % 3;
    records[i] = TexelAccess{static_cast<std::uint16_t>(i / 1000), static_cast<std::uint8_t>(random() % 3),
                             static_cast<std::uint16_t>(x),        static_cast<std::uint16_t>(x / 7),
                             static_cast<std::uint16_t>(i / 8),    static_cast<std::uint16_t>(i / 640),
                             static_cast<std::uint32_t>(i / 24)};
  }
  TexelColumns columns;
  columns.reset(6000);
  columns.append(std::span<const TexelAccess>(records).first(1234));
  columns.append(std::span<const TexelAccess>(records).subspan(1234));
  ColumnScratch scratch;
  std::string from_columns, from_records;
  encode_texel_records(columns, from_columns, scratch);
  encode_texel_records(records, from_records, scratch);
  EXPECT_GT(from_records.size(), 5000u);
  EXPECT_EQ(from_columns, from_records);
  std::vector<TexelAccess> decoded;
  ASSERT_EQ(
      decode_texel_records(std::span(reinterpret_cast<const std::uint8_t*>(from_columns.data()), from_columns.size()),
                           5000, decoded),
      "");
  for (std::size_t i = 0; i < records.size(); ++i)
    ASSERT_TRUE(decoded[i].x == records[i].x && decoded[i].triangle == records[i].triangle &&
                decoded[i].level == records[i].level)
        << i;
}

std::string bytes_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

std::string write_file(const std::string& path, std::uint32_t chunk_records, unsigned threads, unsigned seed) {
  TraceMetadata meta;
  meta.tool_version = "test";
  TraceWriter writer(path, meta, TraceWriterOptions{.chunk_records = chunk_records, .compression_threads = threads});
  std::mt19937 random(seed);
  std::uint32_t x = 0;
  for (int burst = 0; burst < 60; ++burst) {
    std::vector<TexelAccess> texels(random() % 3000);
    for (TexelAccess& t : texels) {
      x += random() % 4;
      t = TexelAccess{0,
                      static_cast<std::uint8_t>(random() % 2),
                      static_cast<std::uint16_t>(x % 4096),
                      static_cast<std::uint16_t>(x / 4096),
                      static_cast<std::uint16_t>(x % 640),
                      0,
                      static_cast<std::uint32_t>(burst)};
    }
    writer.texel_accesses(texels);
    std::vector<VertexFetch> fetches(random() % 500);
    for (VertexFetch& f : fetches) f = VertexFetch{static_cast<std::uint32_t>(random() % 9000), random() % 3 == 0};
    writer.vertex_fetches(fetches);
  }
  writer.finish();
  return bytes_of(path);
}

TEST(ColumnEncoder, AWriterStartingFromAnEarlierWritersMemoryWritesTheSameFile) {
  testing::TempDir dir;
  // First in this process (or after whatever tests ran before): the reference.
  const std::string first = write_file(dir.file("a.rtrace"), 4096, 2, 5);
  ASSERT_GT(first.size(), 10000u);
  // A writer with other chunk sizes and threads leaves chunks and compressors of other shapes.
  write_file(dir.file("b.rtrace"), 1000, 3, 6);
  write_file(dir.file("c.rtrace"), 70000, 1, 7);
  EXPECT_EQ(write_file(dir.file("d.rtrace"), 4096, 2, 5), first);
  EXPECT_EQ(write_file(dir.file("e.rtrace"), 4096, 4, 5), first);
}

}  // namespace
}  // namespace rastrace

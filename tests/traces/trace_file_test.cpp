#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/error.h"
#include "tests/support/temp_dir.h"
#include "traces/crc32c.h"
#include "traces/memory_sink.h"
#include "traces/text_formats.h"
#include "traces/trace_reader.h"
#include "traces/trace_writer.h"

namespace rastrace {
namespace {

using ::testing::HasSubstr;

TraceMetadata sample_metadata() {
  TraceMetadata m;
  m.scene = "builtin:grid";
  m.ordering = "scanline";
  m.width = 640;
  m.height = 480;
  m.filter = "bilinear";
  m.textures = {{{64, 32}, {32, 16}, {16, 8}}, {{8, 8}}};
  m.extra["note"] = "test";
  return m;
}

// Two draws (a list and a strip), texels in a frame-like walk, a few raw addresses.
MemorySink sample_events() {
  MemorySink s;
  s.begin_draw({0, PrimitiveType::TriangleList, kNoRestart});
  std::vector<VertexFetch> list;
  for (std::uint32_t i = 0; i < 300; ++i) list.push_back({(i * 7919u) % 1000u, i % 3 == 0});
  s.vertex_fetches(list);
  s.end_draw();
  s.begin_draw({1, PrimitiveType::TriangleStrip, 0xFFFFu});
  std::vector<VertexFetch> strip;
  for (std::uint32_t i = 0; i < 50; ++i) strip.push_back({i, i == 0 || i == 25});
  s.vertex_fetches(strip);
  s.end_draw();
  std::vector<TexelAccess> texels;
  for (std::uint32_t i = 0; i < 1000; ++i)
    texels.push_back({static_cast<std::uint16_t>(i % 2), static_cast<std::uint8_t>(i % 2 ? 0 : (i / 7) % 3),
                      static_cast<std::uint16_t>((i * 3) % 8), static_cast<std::uint16_t>((i / 5) % 8),
                      static_cast<std::uint16_t>(i / 4), static_cast<std::uint16_t>(i / 40), i / 100});
  s.texel_accesses(texels);
  std::vector<AddressAccess> addresses = {{0x1000, 0}, {0xFFFFFFFFFFFFull, 1}, {0x40, 2}, {0, 0}};
  s.address_accesses(addresses);
  return s;
}

void write_sample(const std::string& path, std::uint32_t chunk_records = 64) {
  TraceWriter writer(path, sample_metadata(), {3, chunk_records});
  const MemorySink events = sample_events();
  writer.begin_draw(events.draws[0]);
  writer.vertex_fetches(std::span(events.fetches).subspan(0, 300));
  writer.end_draw();
  writer.begin_draw(events.draws[1]);
  writer.vertex_fetches(std::span(events.fetches).subspan(300));
  writer.end_draw();
  writer.texel_accesses(events.texels);
  writer.address_accesses({{{0x1000, 0}, {0xFFFFFFFFFFFFull, 1}, {0x40, 2}, {0, 0}}});
  writer.finish();
}

struct RecordingSink final : EventSink {
  MemorySink memory;
  std::vector<DrawInfo>& draws = memory.draws;
  std::vector<std::size_t>& draw_first_fetch = memory.draw_first_fetch;
  MemorySink::Events<VertexFetch>& fetches = memory.fetches;
  MemorySink::Events<TexelAccess>& texels = memory.texels;
  std::vector<AddressAccess> addresses;
  int ends = 0;
  bool finished = false;
  void begin_draw(const DrawInfo& d) override { memory.begin_draw(d); }
  void vertex_fetches(std::span<const VertexFetch> f) override { memory.vertex_fetches(f); }
  void texel_accesses(std::span<const TexelAccess> t) override { memory.texel_accesses(t); }
  void address_accesses(std::span<const AddressAccess> a) override {
    addresses.insert(addresses.end(), a.begin(), a.end());
  }
  void end_draw() override { ++ends; }
  void finish() override { finished = true; }
};

void expect_same_events(const RecordingSink& got, const MemorySink& want) {
  ASSERT_EQ(got.draws.size(), want.draws.size());
  for (std::size_t i = 0; i < want.draws.size(); ++i) {
    EXPECT_EQ(got.draws[i].draw, want.draws[i].draw);
    EXPECT_EQ(got.draws[i].type, want.draws[i].type);
    EXPECT_EQ(got.draws[i].restart_index, want.draws[i].restart_index);
    EXPECT_EQ(got.draw_first_fetch[i], want.draw_first_fetch[i]);
  }
  EXPECT_EQ(got.ends, 2);
  ASSERT_EQ(got.fetches.size(), want.fetches.size());
  for (std::size_t i = 0; i < want.fetches.size(); ++i) {
    EXPECT_EQ(got.fetches[i].vertex, want.fetches[i].vertex) << i;
    EXPECT_EQ(got.fetches[i].primitive_start, want.fetches[i].primitive_start) << i;
  }
  ASSERT_EQ(got.texels.size(), want.texels.size());
  for (std::size_t i = 0; i < want.texels.size(); ++i) {
    const TexelAccess &a = got.texels[i], &b = want.texels[i];
    EXPECT_TRUE(a.texture == b.texture && a.level == b.level && a.x == b.x && a.y == b.y && a.pixel_x == b.pixel_x &&
                a.pixel_y == b.pixel_y && a.triangle == b.triangle)
        << i;
  }
  ASSERT_EQ(got.addresses.size(), 4u);
  EXPECT_EQ(got.addresses[1].address, 0xFFFFFFFFFFFFull);
  EXPECT_EQ(got.addresses[2].label, 2);
}

TEST(Crc32c, MatchesTheCastagnoliCheckValue) {
  EXPECT_EQ(crc32c("123456789", 9), 0xE3069283u);
  EXPECT_EQ(crc32c("6789", 4, crc32c("12345", 5)), 0xE3069283u);
}

TEST(ChunkCodec, ColumnsRoundTripSmallStepsLargeJumpsAndExtremes) {
  // Mostly small steps with rare huge jumps: the escaped 1-byte column mode.
  std::vector<VertexFetch> fetches;
  for (std::uint32_t i = 0; i < 5000; ++i)
    fetches.push_back({i % 997 == 0 ? 0xFFFFFFFFu - i : (i % 13 == 0 ? 0u : i * 3), i % 3 == 0});
  std::string raw;
  encode_vertex_records({7, PrimitiveType::TriangleStrip, 0xFFFF}, fetches, raw);
  EXPECT_LT(raw.size(), 5000u * 3);  // 1 byte per delta + 8 per escape, not the 4 of fixed width
  DrawInfo draw;
  std::vector<VertexFetch> back;
  ASSERT_EQ(decode_vertex_records({reinterpret_cast<const std::uint8_t*>(raw.data()), raw.size()}, 5000, draw, back),
            "");
  EXPECT_EQ(draw.draw, 7u);
  EXPECT_EQ(draw.type, PrimitiveType::TriangleStrip);
  ASSERT_EQ(back.size(), fetches.size());
  for (std::size_t i = 0; i < fetches.size(); ++i) {
    ASSERT_EQ(back[i].vertex, fetches[i].vertex) << i;
    ASSERT_EQ(back[i].primitive_start, fetches[i].primitive_start) << i;
  }
  std::vector<AddressAccess> addresses = {{~std::uint64_t{0}, 2}, {0, 0}, {1ull << 63, 1}};
  encode_address_records(addresses, raw);
  std::vector<AddressAccess> addresses_back;
  ASSERT_EQ(decode_address_records({reinterpret_cast<const std::uint8_t*>(raw.data()), raw.size()}, 3, addresses_back),
            "");
  EXPECT_EQ(addresses_back[0].address, ~std::uint64_t{0});
  EXPECT_EQ(addresses_back[2].address, 1ull << 63);
  EXPECT_EQ(addresses_back[0].label, 2);
}

TEST(ChunkCodec, DecodersReportGarbageAsErrorsWithoutReadingPastTheEnd) {
  const MemorySink events = sample_events();
  std::string raw;
  encode_texel_records(events.texels, raw);
  std::uint64_t state = 42;
  int errors = 0;
  for (int trial = 0; trial < 300; ++trial) {
    std::string bad = raw;
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    if (trial % 3 == 0)
      bad.resize(static_cast<std::size_t>(state >> 33) % raw.size());
    else
      bad[static_cast<std::size_t>(state >> 33) % bad.size()] ^= static_cast<char>(1 + (state >> 20) % 255);
    std::vector<TexelAccess> out;
    errors += !decode_texel_records({reinterpret_cast<const std::uint8_t*>(bad.data()), bad.size()},
                                    static_cast<std::uint32_t>(events.texels.size()), out)
                   .empty();
  }
  EXPECT_GE(errors, 100);  // every truncation at least; flipped delta bytes may decode to other values
}

TEST(ChunkCodec, AddressOnlyTexelDecodingGivesTheAddressesAndZeroDetails) {
  const auto sample = sample_events().texels;
  std::vector<TexelAccess> texels(sample.begin(), sample.end());
  // Large jumps in every column (escaped deltas) and the extremes of each field.
  texels.push_back({0xFFFF, 255, 0xFFFF, 0, 0xFFFF, 0, 0xFFFFFFFFu});
  texels.push_back({0, 0, 0, 0xFFFF, 0, 0xFFFF, 0});
  std::string raw;
  encode_texel_records(texels, raw);
  const std::span<const std::uint8_t> bytes(reinterpret_cast<const std::uint8_t*>(raw.data()), raw.size());
  const auto n = static_cast<std::uint32_t>(texels.size());
  std::vector<TexelAccess> full, addresses(3, TexelAccess{1, 1, 1, 1, 7, 7, 7});  // stale values must go
  ASSERT_EQ(decode_texel_records(bytes, n, full), "");
  ASSERT_EQ(decode_texel_records(bytes, n, addresses, false), "");
  ASSERT_EQ(addresses.size(), texels.size());
  for (std::size_t i = 0; i < texels.size(); ++i) {
    const TexelAccess &a = addresses[i], &t = texels[i];
    ASSERT_TRUE(a.texture == t.texture && a.level == t.level && a.x == t.x && a.y == t.y) << i;
    ASSERT_TRUE(a.pixel_x == 0 && a.pixel_y == 0 && a.triangle == 0) << i;
    ASSERT_EQ(full[i].triangle, t.triangle) << i;
  }
  // The skipped columns' bytes must still all be there: a cut inside the last one is an error.
  EXPECT_THAT(decode_texel_records(bytes.first(bytes.size() - 1), n, addresses, false),
              HasSubstr("ends inside the triangle"));
  // And a cut inside an address column names it, as the full decoding does.
  EXPECT_THAT(decode_texel_records(bytes.first(20), n, addresses, false), HasSubstr("ends inside the texture"));
}

TEST(TraceFile, RoundTripKeepsEveryRecordAndTheMetadata) {
  const testing::TempDir dir;
  const std::string path = dir.file("roundtrip.rtrace");
  write_sample(path);
  TraceReader reader(path);
  EXPECT_EQ(reader.metadata().scene, "builtin:grid");
  EXPECT_EQ(reader.metadata().textures, sample_metadata().textures);
  EXPECT_EQ(reader.metadata().width, 640u);
  EXPECT_EQ(reader.metadata().filter, "bilinear");
  EXPECT_FALSE(reader.metadata().tool_version.empty());
  EXPECT_EQ(reader.records(RecordKind::Vertex), 350u);
  EXPECT_EQ(reader.records(RecordKind::Texel), 1000u);
  EXPECT_EQ(reader.records(RecordKind::Address), 4u);
  // 300 fetches in 64-record chunks = 5 chunks, 50 = 1, 1000 texels = 16, 4 addresses = 1.
  EXPECT_EQ(reader.chunks().size(), 23u);
  RecordingSink sink;
  replay_trace(reader, sink);
  EXPECT_TRUE(sink.finished);
  expect_same_events(sink, sample_events());
}

TEST(TraceFile, StreamingReadersSeeDrawsAndTexelsInOrder) {
  const testing::TempDir dir;
  const std::string path = dir.file("stream.rtrace");
  write_sample(path, 100);
  VertexTraceReader vertices(path);
  VertexBatch batch;
  std::vector<std::uint32_t> starts_of_draw;
  std::uint64_t fetched = 0;
  int ends = 0;
  while (vertices.next(batch)) {
    if (batch.starts_draw) starts_of_draw.push_back(batch.draw.draw);
    ends += batch.ends_draw;
    fetched += batch.fetches.size();
  }
  EXPECT_EQ(starts_of_draw, (std::vector<std::uint32_t>{0, 1}));
  EXPECT_EQ(ends, 2);
  EXPECT_EQ(fetched, 350u);
  TexelTraceReader texels(path);
  std::span<const TexelAccess> t;
  std::uint64_t count = 0, x_sum = 0;
  while (texels.next(t)) {
    count += t.size();
    for (const auto& a : t) x_sum += a.x;
  }
  EXPECT_EQ(count, 1000u);
  std::uint64_t want = 0;
  for (std::uint32_t i = 0; i < 1000; ++i) want += (i * 3) % 8;
  EXPECT_EQ(x_sum, want);
}

TEST(TraceFile, WriterWithoutFinishLeavesNoFile) {
  const testing::TempDir dir;
  const std::string path = dir.file("unfinished.rtrace");
  {
    TraceWriter writer(path, sample_metadata());
    writer.texel_accesses(sample_events().texels);
  }
  EXPECT_FALSE(std::filesystem::exists(path));
}

std::string bytes_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}
void put_bytes(const std::string& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }
std::string open_error(const std::string& path) {
  try {
    TraceReader reader(path);
    RecordingSink sink;
    replay_trace(reader, sink);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(TraceFile, WrongMagicIsNamed) {
  const testing::TempDir dir;
  const std::string path = dir.file("magic.rtrace");
  put_bytes(path, "NOTATRACEFILE AT ALL");
  EXPECT_THAT(open_error(path), HasSubstr("byte 0: not a rastrace trace"));
}

TEST(TraceFile, UnknownVersionIsNamed) {
  const testing::TempDir dir;
  const std::string path = dir.file("version.rtrace");
  write_sample(path);
  std::string bytes = bytes_of(path);
  bytes[8] = 7;
  put_bytes(path, bytes);
  EXPECT_THAT(open_error(path), HasSubstr("byte 8: unknown trace version 7"));
}

TEST(TraceFile, TruncatedFileNamesTheTruncatedChunkAndItsOffset) {
  const testing::TempDir dir;
  const std::string path = dir.file("truncated.rtrace");
  write_sample(path);
  const std::string bytes = bytes_of(path);
  TraceReader reader(path);
  const ChunkInfo third = reader.chunks()[2];
  put_bytes(path, bytes.substr(0, third.offset + 40));
  EXPECT_THAT(open_error(path), HasSubstr("byte " + std::to_string(third.offset) + ": truncated trace: chunk 2 needs"));
  // Cut exactly between chunks: no index.
  put_bytes(path, bytes.substr(0, third.offset));
  EXPECT_THAT(open_error(path), HasSubstr("no chunk index and footer after chunk 2"));
}

TEST(TraceFile, AddressOnlyTexelReadersSeeTheSameAddressesAndStillCheckEveryChunk) {
  const testing::TempDir dir;
  const std::string path = dir.file("addresses.rtrace");
  write_sample(path, 100);
  const MemorySink events = sample_events();
  for (const bool ahead : {false, true}) {
    TexelTraceReader texels(path);
    texels.set_read_ahead(ahead);
    texels.set_addresses_only(true);
    std::span<const TexelAccess> batch;
    std::size_t i = 0;
    while (texels.next(batch))
      for (const TexelAccess& a : batch) {
        const TexelAccess& t = events.texels.at(i++);
        ASSERT_TRUE(a.texture == t.texture && a.level == t.level && a.x == t.x && a.y == t.y) << i;
        ASSERT_TRUE(a.pixel_x == 0 && a.pixel_y == 0 && a.triangle == 0) << i;
      }
    EXPECT_EQ(i, events.texels.size()) << "read-ahead " << ahead;
  }
  // A flipped byte in a texel chunk fails its checksum whatever columns the reader decodes.
  std::string bytes = bytes_of(path);
  const TraceReader clean(path);
  std::size_t chunk = 0;
  while (clean.chunks()[chunk].kind != RecordKind::Texel) ++chunk;
  const std::uint64_t offset = clean.chunks()[chunk].offset;
  bytes[offset + kChunkHeaderBytes + clean.chunks().size() % 5] ^= 0x10;
  put_bytes(path, bytes);
  TexelTraceReader damaged(path);
  damaged.set_addresses_only(true);
  std::span<const TexelAccess> batch;
  try {
    while (damaged.next(batch)) {
    }
    ADD_FAILURE() << "the damaged chunk was read";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("byte " + std::to_string(offset) + ": chunk " + std::to_string(chunk) +
                                    ": checksum mismatch"));
  }
}

TEST(TraceFile, CorruptedPayloadIsAChecksumMismatchNamingTheChunk) {
  const testing::TempDir dir;
  const std::string path = dir.file("corrupt.rtrace");
  write_sample(path);
  std::string bytes = bytes_of(path);
  const ChunkInfo fifth = TraceReader(path).chunks()[4];
  bytes[fifth.offset + kChunkHeaderBytes + 3] ^= 0x20;
  put_bytes(path, bytes);
  EXPECT_THAT(open_error(path), HasSubstr("byte " + std::to_string(fifth.offset) + ": chunk 4: checksum mismatch"));
}

TEST(TraceFile, CsvExportImportRoundTrip) {
  const testing::TempDir dir;
  const std::string path = dir.file("csv.rtrace"), csv = dir.file("export.csv"), back = dir.file("back.rtrace");
  write_sample(path);
  {
    TraceReader reader(path);
    std::ofstream out(csv);
    export_csv(reader, out);
  }
  EXPECT_EQ(read_csv_metadata(csv), [&] {
    TraceMetadata m = sample_metadata();
    m.tool_version = TraceReader(dir.file("csv.rtrace")).metadata().tool_version;
    return m;
  }());
  {
    TraceWriter writer(back, read_csv_metadata(csv), {3, 64});
    import_csv(csv, writer);
  }
  TraceReader reader(back);
  RecordingSink sink;
  replay_trace(reader, sink);
  expect_same_events(sink, sample_events());
}

TEST(TraceFile, CsvErrorsNameTheLine) {
  const testing::TempDir dir;
  const std::string csv = dir.file("bad.csv");
  put_bytes(csv,
            "event,draw,type,restart,vertex,primitive_start,texture,level,x,y,pixel_x,pixel_y,triangle,address,label\n"
            "vertex,,,,12,1,,,,,,,,,\nvertex,,,,x12,0,,,,,,,,,\n");
  MemorySink sink;
  try {
    import_csv(csv, sink);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_THAT(std::string(e.what()), HasSubstr(":3: column vertex: 'x12' is not an unsigned number"));
  }
}

// A texel's texture, x and y are 16-bit fields: 65535 is read, 65536 is an error naming the line,
// the column and the range.
TEST(TraceFile, CsvTexelColumnsBeyond16BitsAreErrorsNamingTheLineAndTheRange) {
  const testing::TempDir dir;
  const std::string header =
      "event,draw,type,restart,vertex,primitive_start,texture,level,x,y,pixel_x,pixel_y,triangle,address,label,mask\n";
  const std::string good = dir.file("good.csv");
  put_bytes(good, header + "texel,,,,,,65535,3,65535,65535,1,2,7,,,\n");
  MemorySink sink;
  import_csv(good, sink);
  ASSERT_EQ(sink.texels.size(), 1u);
  EXPECT_TRUE(sink.texels[0].texture == 65535 && sink.texels[0].x == 65535 && sink.texels[0].y == 65535);
  for (const char* column : {"texture", "x", "y"}) {
    std::string row = "texel,,,,,,1,0,2,3,1,2,7,,,\n";
    const std::size_t field = std::string(column) == "texture" ? 6 : std::string(column) == "x" ? 8 : 9;
    std::size_t at = 0;
    for (std::size_t k = 0; k < field; ++k) at = row.find(',', at) + 1;
    row.replace(at, row.find(',', at) - at, "65536");
    const std::string bad = dir.file(std::string("bad_") + column + ".csv");
    put_bytes(bad, header + row);
    try {
      import_csv(bad, sink);
      FAIL() << column;
    } catch (const InputError& e) {
      EXPECT_THAT(std::string(e.what()), HasSubstr(":2: column " + std::string(column) +
                                                   ": '65536' is not an unsigned number in range (0 to 65535)"));
    }
  }
}

TEST(TraceFile, DinImportReadsLabelsAndHexAddresses) {
  const testing::TempDir dir;
  const std::string din = dir.file("in.din");
  put_bytes(din, "0 1000\n1 0x2000\n\n2 ffffffff\n3 0\n0 40\n");
  RecordingSink sink;
  EXPECT_EQ(import_din(din, sink), 4u);
  ASSERT_EQ(sink.addresses.size(), 4u);
  EXPECT_EQ(sink.addresses[0].address, 0x1000u);
  EXPECT_EQ(sink.addresses[1].address, 0x2000u);
  EXPECT_EQ(sink.addresses[2].address, 0xFFFFFFFFu);
  EXPECT_EQ(sink.addresses[2].label, 2);
  EXPECT_EQ(sink.addresses[3].address, 0x40u);
  put_bytes(din, "0 1000\n0 zz\n");
  try {
    import_din(din, sink);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_THAT(std::string(e.what()), HasSubstr("in.din:2: column address: 'zz' is not a hexadecimal number"));
  }
}

}  // namespace
}  // namespace rastrace

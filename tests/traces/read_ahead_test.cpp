// TraceReader's read-ahead (a second thread decoding the next chunks): the records must be the
// same in every reading order, errors must surface at the chunk they belong to, and a reader
// destroyed anywhere must stop its thread cleanly (these tests also run under ASan and TSan).
#include <algorithm>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <thread>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/error.h"
#include "tests/support/synthetic_frame.h"
#include "tests/support/temp_dir.h"
#include "traces/crc32c.h"
#include "traces/trace_reader.h"
#include "traces/trace_writer.h"

namespace rastrace {
namespace {

using ::testing::HasSubstr;

// Vertex, texel and address chunks interleaved, 128 records per chunk: 275 chunks.
void write_mixed_trace(const std::string& path) {
  const testing::SyntheticFrame frame = testing::make_synthetic_frame(64, 64, 64);  // 16,384 texels
  TraceMetadata m;
  m.scene = "read-ahead test";
  m.textures = frame.textures;
  TraceWriter writer(path, m, {1, 128});
  std::vector<AddressAccess> addresses;
  for (std::uint32_t draw = 0; draw < 8; ++draw) {
    std::vector<VertexFetch> fetches;
    for (std::uint32_t i = 0; i < 2000; ++i) fetches.push_back({(i * 2654435761u + draw) % 5000u, i % 3 == 0});
    writer.begin_draw({draw, draw % 2 ? PrimitiveType::TriangleStrip : PrimitiveType::TriangleList, 0xFFFFu});
    writer.vertex_fetches(fetches);
    writer.end_draw();
    writer.texel_accesses(std::span(frame.texels).subspan(draw * 2048, 2048));
    addresses.clear();
    for (std::uint64_t i = 0; i < 300; ++i)
      addresses.push_back({(i * 0x9E3779B97F4A7C15ull) >> draw, static_cast<std::uint8_t>(i % 3)});
    writer.address_accesses(addresses);
  }
  writer.finish();
}

// One decoded chunk, copied out of the reader (whose result only lives until the next call).
struct ChunkCopy {
  RecordKind kind = RecordKind::Vertex;
  std::uint8_t flags = 0;
  std::uint64_t first_record = 0;
  std::uint32_t draw = 0;
  PrimitiveType type = PrimitiveType::TriangleList;
  std::vector<std::uint64_t> values;  // every field of every record, in order
};

ChunkCopy copy_of(const DecodedChunk& c) {
  ChunkCopy copy{c.kind, c.flags, c.first_record, 0, PrimitiveType::TriangleList, {}};
  switch (c.kind) {
    case RecordKind::Vertex:
      copy.draw = c.draw.draw;
      copy.type = c.draw.type;
      for (const VertexFetch& f : c.vertices) copy.values.insert(copy.values.end(), {f.vertex, f.primitive_start});
      break;
    case RecordKind::Texel:
      for (const TexelAccess& t : c.texels)
        copy.values.insert(copy.values.end(), {t.texture, t.level, t.x, t.y, t.pixel_x, t.pixel_y, t.triangle});
      break;
    default:
      for (const AddressAccess& a : c.addresses) copy.values.insert(copy.values.end(), {a.address, a.label});
      break;
  }
  return copy;
}

bool operator==(const ChunkCopy& a, const ChunkCopy& b) {
  return a.kind == b.kind && a.flags == b.flags && a.first_record == b.first_record && a.draw == b.draw &&
         a.type == b.type && a.values == b.values;
}

// Every chunk read one by one in file order without read-ahead: what every other way must give.
std::vector<ChunkCopy> reference_chunks(const std::string& path) {
  TraceReader reader(path);
  reader.set_read_ahead(false);
  std::vector<ChunkCopy> chunks;
  for (std::size_t i = 0; i < reader.chunks().size(); ++i) chunks.push_back(copy_of(reader.read_chunk(i)));
  return chunks;
}

std::string error_of(TraceReader& reader, std::size_t chunk) {
  try {
    reader.read_chunk(chunk);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

class ReadAhead : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new testing::TempDir;
    path_ = new std::string(dir_->file("mixed.rtrace"));
    write_mixed_trace(*path_);
    reference_ = new std::vector<ChunkCopy>(reference_chunks(*path_));
  }
  static void TearDownTestSuite() {
    delete path_;
    delete dir_;
    delete reference_;
  }
  static testing::TempDir* dir_;
  static std::string* path_;
  static std::vector<ChunkCopy>* reference_;
};
testing::TempDir* ReadAhead::dir_ = nullptr;
std::string* ReadAhead::path_ = nullptr;
std::vector<ChunkCopy>* ReadAhead::reference_ = nullptr;

TEST_F(ReadAhead, TheTestTraceInterleavesAllThreeKinds) {
  const TraceReader reader(*path_);
  // 8 draws x (16 vertex + 16 texel chunks) + 19 address chunks (the writer carries partial
  // address chunks over to the next draw).
  EXPECT_EQ(reader.chunks().size(), 275u);
  EXPECT_EQ(reader.records(RecordKind::Vertex), 16000u);
  EXPECT_EQ(reader.records(RecordKind::Texel), 16384u);
  EXPECT_EQ(reader.records(RecordKind::Address), 2400u);
  EXPECT_EQ(reader.chunks()[15].kind, RecordKind::Vertex);
  EXPECT_EQ(reader.chunks()[16].kind, RecordKind::Texel);
}

TEST_F(ReadAhead, InOrderOutOfOrderAndInterruptedRunsGiveTheSameChunks) {
  const std::vector<ChunkCopy>& want = *reference_;
  const std::size_t n = want.size();
  std::vector<std::vector<std::size_t>> orders;
  std::vector<std::size_t> in_order(n);
  for (std::size_t i = 0; i < n; ++i) in_order[i] = i;
  orders.push_back(in_order);
  orders.emplace_back(in_order.rbegin(), in_order.rend());
  std::vector<std::size_t> shuffled = in_order;
  std::uint64_t state = 7;
  for (std::size_t i = n - 1; i > 0; --i) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    std::swap(shuffled[i], shuffled[(state >> 33) % (i + 1)]);
  }
  orders.push_back(shuffled);
  // Runs in order of 1 to 12 chunks from random places, going back and forth: read-ahead starts,
  // is dropped and starts again, sometimes over chunks it had already decoded.
  std::vector<std::size_t> runs;
  while (runs.size() < 3 * n) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    const std::size_t start = (state >> 33) % n, length = 1 + (state >> 20) % 12;
    for (std::size_t i = start; i < std::min(n, start + length); ++i) runs.push_back(i);
  }
  orders.push_back(runs);
  for (std::size_t o = 0; o < orders.size(); ++o) {
    TraceReader reader(*path_);
    reader.set_read_ahead(true);
    for (const std::size_t i : orders[o])
      ASSERT_TRUE(copy_of(reader.read_chunk(i)) == want[i]) << "order " << o << ", chunk " << i;
  }
  // Reading only texel chunks in order (the other kinds skipped) is in order for the read-ahead.
  TraceReader reader(*path_);
  reader.set_read_ahead(true);
  reader.set_read_ahead_kinds({false, true, false});
  std::size_t texel_chunks = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (reader.chunks()[i].kind != RecordKind::Texel) continue;
    ASSERT_TRUE(copy_of(reader.read_chunk(i)) == want[i]) << "texel chunk " << i;
    ++texel_chunks;
  }
  EXPECT_EQ(texel_chunks, 128u);
}

TEST_F(ReadAhead, StreamingReadersGiveTheSameRecordsWithAndWithoutReadAhead) {
  for (const bool ahead : {false, true}) {
    TexelTraceReader texels(*path_);
    texels.set_read_ahead(ahead);
    std::uint64_t count = 0, sum = 0;
    std::span<const TexelAccess> batch;
    while (texels.next(batch)) {
      count += batch.size();
      for (const TexelAccess& t : batch) sum += t.x * 3 + t.y * 5 + t.level * 7 + t.pixel_x + t.triangle;
    }
    VertexTraceReader vertices(*path_);
    vertices.set_read_ahead(ahead);
    VertexBatch vb;
    std::uint64_t fetches = 0, vertex_sum = 0, draws = 0;
    while (vertices.next(vb)) {
      draws += vb.starts_draw;
      fetches += vb.fetches.size();
      for (const VertexFetch& f : vb.fetches) vertex_sum += f.vertex + f.primitive_start;
    }
    std::uint64_t want_sum = 0, want_vertex_sum = 0;
    for (const ChunkCopy& c : *reference_) {
      if (c.kind == RecordKind::Texel)
        for (std::size_t i = 0; i < c.values.size(); i += 7)
          want_sum +=
              c.values[i + 2] * 3 + c.values[i + 3] * 5 + c.values[i + 1] * 7 + c.values[i + 4] + c.values[i + 6];
      if (c.kind == RecordKind::Vertex)
        for (const std::uint64_t v : c.values) want_vertex_sum += v;
    }
    EXPECT_EQ(count, 16384u) << ahead;
    EXPECT_EQ(sum, want_sum) << ahead;
    EXPECT_EQ(draws, 8u) << ahead;
    EXPECT_EQ(fetches, 16000u) << ahead;
    EXPECT_EQ(vertex_sum, want_vertex_sum) << ahead;
  }
}

std::string bytes_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}
void put_bytes(const std::string& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }

// Damages chunk `chunk`'s payload; with `fix_crc` the checksum is recomputed so that zstd or the
// column decoder finds the damage instead.
void damage_chunk(const std::string& from, const std::string& to, std::size_t chunk, bool fix_crc) {
  std::string bytes = bytes_of(from);
  const TraceReader reader(from);
  const std::uint64_t offset = reader.chunks()[chunk].offset;
  const std::uint64_t end = chunk + 1 < reader.chunks().size() ? reader.chunks()[chunk + 1].offset : offset + 64;
  const std::size_t payload = static_cast<std::size_t>(end - offset - kChunkHeaderBytes);
  for (std::size_t k = payload / 3; k < payload / 3 + 8; ++k) bytes[offset + kChunkHeaderBytes + k] ^= 0x5A;
  if (fix_crc) {
    const std::uint32_t crc =
        crc32c(bytes.data() + offset + kChunkHeaderBytes, payload, crc32c(bytes.data() + offset, 28));
    std::memcpy(bytes.data() + offset + 28, &crc, 4);
  }
  put_bytes(to, bytes);
}

TEST_F(ReadAhead, FileCutShortAfterOpeningIsAReadErrorAtTheFirstMissingChunk) {
  const testing::TempDir dir;
  for (const bool ahead : {false, true}) {
    const std::string cut = dir.file(ahead ? "cut-ahead.rtrace" : "cut.rtrace");
    std::filesystem::copy_file(*path_, cut, std::filesystem::copy_options::overwrite_existing);
    TraceReader reader(cut);
    reader.set_read_ahead(ahead);
    const std::size_t last_whole = 10;
    std::filesystem::resize_file(cut, reader.chunks()[last_whole + 1].offset);  // chunks 0-10 left
    for (std::size_t i = 0; i <= last_whole; ++i) ASSERT_TRUE(copy_of(reader.read_chunk(i)) == (*reference_)[i]) << i;
    const std::string error = error_of(reader, last_whole + 1);
    EXPECT_THAT(error,
                HasSubstr("byte " + std::to_string(reader.chunks()[last_whole + 1].offset) + ": chunk 11: read failed"))
        << (ahead ? "read-ahead" : "plain");
  }
}

TEST_F(ReadAhead, DamagedChunkInTheMiddleIsReportedAtThatChunkAfterTheEarlierOnes) {
  const testing::TempDir dir;
  const std::string damaged = dir.file("damaged.rtrace");
  const std::size_t bad = 137;
  for (const bool fix_crc : {false, true}) {
    damage_chunk(*path_, damaged, bad, fix_crc);
    TraceReader plain(damaged);
    plain.set_read_ahead(false);
    const std::string want = error_of(plain, bad);
    const std::string where = "byte " + std::to_string(plain.chunks()[bad].offset) + ": chunk 137: ";
    EXPECT_THAT(want, HasSubstr(where + (fix_crc ? "" : "checksum mismatch (stored 0x")));
    if (fix_crc) {
      EXPECT_THAT(want, ::testing::Not(HasSubstr("checksum")));
    }

    TraceReader reader(damaged);
    reader.set_read_ahead(true);
    for (std::size_t i = 0; i < bad; ++i) {
      ASSERT_TRUE(copy_of(reader.read_chunk(i)) == (*reference_)[i]) << i;
      // Give the read-ahead thread time to reach the damaged chunk before the caller asks.
      if (i + 2 == bad) std::this_thread::sleep_for(std::chrono::milliseconds(30));
    }
    EXPECT_EQ(error_of(reader, bad), want);
    // The same error again when asked again, and the chunks after it still read.
    EXPECT_EQ(error_of(reader, bad), want);
    for (std::size_t i = bad + 1; i < reader.chunks().size(); ++i)
      ASSERT_TRUE(copy_of(reader.read_chunk(i)) == (*reference_)[i]) << i;

    // replay_trace: the sink has every record of the chunks before the damaged one.
    struct Counter final : EventSink {
      std::uint64_t records = 0;
      void begin_draw(const DrawInfo&) override {}
      void vertex_fetches(std::span<const VertexFetch> f) override { records += f.size(); }
      void texel_accesses(std::span<const TexelAccess> t) override { records += t.size(); }
      void address_accesses(std::span<const AddressAccess> a) override { records += a.size(); }
      void end_draw() override {}
      void finish() override {}
    } counter;
    TraceReader replayed(damaged);
    try {
      replay_trace(replayed, counter);
      ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()), want);
    }
    std::uint64_t before = 0;
    for (std::size_t i = 0; i < bad; ++i) before += replayed.chunks()[i].records;
    EXPECT_EQ(counter.records, before);
  }
}

TEST_F(ReadAhead, DestroyingAReaderAnywhereStopsItsThreadCleanly) {
  // Destroyed with the read-ahead thread busy, waiting for a free slot, or never started; after
  // an error; after read-ahead was switched off in the middle.
  for (const std::size_t stop :
       {std::size_t{0}, std::size_t{1}, std::size_t{2}, std::size_t{3}, std::size_t{40}, std::size_t{274}}) {
    for (const int pause_ms : {0, 5}) {
      TraceReader reader(*path_);
      reader.set_read_ahead(true);
      for (std::size_t i = 0; i <= stop; ++i) ASSERT_TRUE(copy_of(reader.read_chunk(i)) == (*reference_)[i]);
      if (pause_ms) std::this_thread::sleep_for(std::chrono::milliseconds(pause_ms));
    }
  }
  { TraceReader reader(*path_); }
  const testing::TempDir dir;
  const std::string damaged = dir.file("destroy_damaged.rtrace");
  damage_chunk(*path_, damaged, 5, false);
  {
    TraceReader reader(damaged);
    reader.set_read_ahead(true);
    for (std::size_t i = 0; i < 5; ++i) reader.read_chunk(i);
    EXPECT_THAT(error_of(reader, 5), HasSubstr("chunk 5: checksum mismatch"));
  }
  TraceReader reader(*path_);
  reader.set_read_ahead(true);
  for (std::size_t i = 0; i < 10; ++i) reader.read_chunk(i);
  reader.set_read_ahead(false);
  for (std::size_t i = 10; i < 20; ++i) ASSERT_TRUE(copy_of(reader.read_chunk(i)) == (*reference_)[i]) << i;
}

}  // namespace
}  // namespace rastrace

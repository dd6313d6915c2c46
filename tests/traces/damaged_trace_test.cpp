// Damaged traces never pass as sound. A small rendered trace (builtin:grid at 16x16, a few KB)
// gets every single-bit flip and every truncation; a larger one (builtin:bunny at 128x128) gets
// random multi-byte damage. Each damaged file must make the reader throw an InputError that
// names a byte offset (and the chunk, when the damage is inside one), whichever path reads it:
// the full verification (`trace info`, `trace verify`), a replay of one kind that only checks
// the chunks it skips (`sweep`), and the command line itself.
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/error.h"
#include "tests/support/run_rastrace.h"
#include "tests/support/temp_dir.h"
#include "traces/memory_sink.h"
#include "traces/trace_reader.h"

namespace rastrace {
namespace {

using ::testing::HasSubstr;
using testing::run_rastrace;
using testing::TempDir;

std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

std::string render_trace(const TempDir& dir, const std::string& scene, const std::string& size) {
  const std::string trace = dir.file(scene.substr(8) + ".rtrace");
  const auto run = run_rastrace({"render", scene, "--size", size, "-o", dir.file("frame.png"), "--trace", trace});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  return trace;
}

// Reads the whole file as `trace verify` does; "" when it reads as sound, else the error.
std::string verify_error(const std::string& path) {
  try {
    TraceReader reader(path);
    reader.set_read_ahead(false);
    verify_trace(reader);
    return "";
  } catch (const InputError& e) {
    return e.what();
  }
}

// Replays only the texel chunks, as a texture sweep does: the others are checked, not decoded.
std::string texel_replay_error(const std::string& path) {
  try {
    TraceReader reader(path);
    MemorySink sink;
    replay_trace(reader, sink, ReplayKinds{false, true, false, false});
    return "";
  } catch (const InputError& e) {
    return e.what();
  }
}

// Replays the texel chunks for their addresses alone, as `sweep --sample` does: the pixel and
// triangle columns are not decoded, so only the checksum can find their damage.
std::string texel_address_replay_error(const std::string& path) {
  try {
    TraceReader reader(path);
    MemorySink sink;
    ReplayKinds kinds{false, true, false, false};
    kinds.texel_details = false;
    replay_trace(reader, sink, kinds);
    return "";
  } catch (const InputError& e) {
    return e.what();
  }
}

// The byte ranges of the chunks (header and payload), to tell which chunk a damaged byte is in.
std::vector<std::pair<std::uint64_t, std::uint64_t>> chunk_ranges(const std::string& path) {
  TraceReader reader(path);
  std::vector<std::pair<std::uint64_t, std::uint64_t>> ranges;
  std::uint64_t index_offset = 0;
  const std::string bytes = read_bytes(path);
  std::memcpy(&index_offset, bytes.data() + bytes.size() - kFooterBytes, 8);
  for (std::size_t i = 0; i < reader.chunks().size(); ++i)
    ranges.emplace_back(reader.chunks()[i].offset,
                        i + 1 < reader.chunks().size() ? reader.chunks()[i + 1].offset : index_offset);
  return ranges;
}

// One small rendered trace for the suite (rendering is most of a test's time).
class DamagedTrace : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    suite_dir_ = new TempDir;
    small_ = new std::string(render_trace(*suite_dir_, "builtin:grid", "16x16"));
  }
  static void TearDownTestSuite() {
    delete small_;
    delete suite_dir_;
  }
  static const std::string& small_trace() { return *small_; }

 private:
  static inline TempDir* suite_dir_ = nullptr;
  static inline std::string* small_ = nullptr;
};

// Flips every bit of the trace (or of the bytes of `only`, [first, end) ranges) in turn: each
// damaged file is an error naming a byte, and the chunk when the bit is inside one.
void expect_every_bit_flip_named(const std::string& trace,
                                 std::vector<std::pair<std::uint64_t, std::uint64_t>> only = {}) {
  const TempDir dir;
  const std::string sound = read_bytes(trace);
  ASSERT_EQ(verify_error(trace), "");
  ASSERT_LT(sound.size(), 4096u) << "keep the exhaustive test small";
  const auto chunks = chunk_ranges(trace);
  ASSERT_GE(chunks.size(), 3u);  // vertex, texel and framebuffer chunks
  const std::string damaged = dir.file("damaged.rtrace");
  if (only.empty()) only.emplace_back(0, sound.size());
  std::uint64_t flips = 0, bytes_flipped = 0;
  for (const auto& [first, end] : only) {
    bytes_flipped += end - first;
    for (std::size_t byte = first; byte < end; ++byte) {
      for (int bit = 0; bit < 8; ++bit) {
        std::string bytes = sound;
        bytes[byte] = static_cast<char>(bytes[byte] ^ (1 << bit));
        write_bytes(damaged, bytes);
        const std::string error = verify_error(damaged);
        ASSERT_THAT(error, HasSubstr(": byte ")) << "bit " << bit << " of byte " << byte << " passed as sound";
        for (std::size_t c = 0; c < chunks.size(); ++c) {
          if (byte >= chunks[c].first && byte < chunks[c].second) {
            ASSERT_THAT(error, HasSubstr("chunk " + std::to_string(c) + ": ")) << "byte " << byte;
          }
        }
        ++flips;
      }
    }
  }
  EXPECT_EQ(flips, bytes_flipped * 8);
}

TEST_F(DamagedTrace, EverySingleBitFlipOfASmallRenderedTraceIsAnErrorNamingItsByteAndChunk) {
  expect_every_bit_flip_named(small_trace());
}

// Several frames: frame numbers in the chunk headers and the index.
TEST_F(DamagedTrace, EverySingleBitFlipOfATwoFrameTraceIsAnErrorNamingItsByteAndChunk) {
  const TempDir dir;
  const std::string trace = dir.file("frames.rtrace");
  const auto run = run_rastrace(
      {"render", "builtin:grid", "--size", "16x12", "--frames", "2", "-o", dir.file("frame.png"), "--trace", trace});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  // The version field, every chunk header (frame included) and the index with its frames and the
  // footer; the payloads are damaged like version 2's (the test above).
  const TraceReader reader(trace);
  ASSERT_EQ(reader.version(), 4u);
  ASSERT_EQ(reader.frames(), 2u);
  std::vector<std::pair<std::uint64_t, std::uint64_t>> ranges = {{8, 12}};
  for (const ChunkInfo& c : reader.chunks()) ranges.emplace_back(c.offset, c.offset + kChunkHeaderBytes);
  std::uint64_t index_offset = 0;
  const std::string bytes = read_bytes(trace);
  std::memcpy(&index_offset, bytes.data() + bytes.size() - kFooterBytes, 8);
  ranges.emplace_back(index_offset, bytes.size());
  expect_every_bit_flip_named(trace, ranges);
}

TEST_F(DamagedTrace, EveryBitFlipOfATexelChunkIsFoundWhenOnlyItsAddressesAreDecoded) {
  const TempDir dir;
  const std::string& trace = small_trace();
  const std::string sound = read_bytes(trace);
  ASSERT_EQ(texel_address_replay_error(trace), "");
  const auto chunks = chunk_ranges(trace);
  const TraceReader reader(trace);
  const std::string damaged = dir.file("damaged.rtrace");
  std::uint64_t flips = 0;
  for (std::size_t c = 0; c < chunks.size(); ++c) {
    if (reader.chunks()[c].kind != RecordKind::Texel) continue;
    // Two bits of every byte (the exhaustive flips of the whole file are the tests above).
    for (std::uint64_t byte = chunks[c].first; byte < chunks[c].second; ++byte)
      for (const int bit : {static_cast<int>(byte % 8), static_cast<int>((byte + 3) % 8)}) {
        std::string bytes = sound;
        bytes[byte] = static_cast<char>(bytes[byte] ^ (1 << bit));
        write_bytes(damaged, bytes);
        ASSERT_THAT(texel_address_replay_error(damaged), HasSubstr(": chunk " + std::to_string(c) + ": "))
            << "bit " << bit << " of byte " << byte;
        ++flips;
      }
  }
  EXPECT_GT(flips, 0u);
}

TEST_F(DamagedTrace, EveryTruncationOfASmallRenderedTraceIsAnError) {
  const TempDir dir;
  const std::string& trace = small_trace();
  const std::string sound = read_bytes(trace);
  const std::string damaged = dir.file("short.rtrace");
  for (std::size_t size = 0; size < sound.size(); ++size) {
    write_bytes(damaged, sound.substr(0, size));
    ASSERT_THAT(verify_error(damaged), HasSubstr(damaged + ": ")) << "truncated to " << size << " bytes";
  }
}

TEST_F(DamagedTrace, SkippedChunksAreStillCheckedWhenOneKindIsReplayed) {
  const TempDir dir;
  const std::string& trace = small_trace();
  std::string bytes = read_bytes(trace);
  const TraceReader reader(trace);
  ASSERT_EQ(reader.chunks()[0].kind, RecordKind::Vertex);
  // The last payload byte of the vertex chunk, which a texel replay does not decode.
  const std::uint64_t last = reader.chunks()[1].offset - 1;
  bytes[last] = static_cast<char>(bytes[last] ^ 0x10);
  const std::string damaged = dir.write("vertex-damaged.rtrace", bytes);
  EXPECT_THAT(texel_replay_error(damaged), HasSubstr(": byte " + std::to_string(reader.chunks()[0].offset) +
                                                         ": chunk 0: checksum mismatch"));
  for (const std::vector<std::string>& command :
       {std::vector<std::string>{"trace", "info", damaged}, {"trace", "verify", damaged},
        {"replay", damaged, "--cache", "size=1KiB,line=64B"}, {"sweep", damaged, "--cache", "size=1KiB..4KiB"}}) {
    const auto run = run_rastrace(command);
    EXPECT_EQ(run.exit_code, 1) << command[0] << " " << command[1] << "\n" << run.out;
    EXPECT_THAT(run.err, HasSubstr("chunk 0: checksum mismatch")) << command[0] << " " << command[1];
  }
}

TEST_F(DamagedTrace, RandomMultiByteDamageOfARenderedFrameIsAlwaysFound) {
  const TempDir dir;
  const std::string trace = render_trace(dir, "builtin:bunny", "128x128");
  const std::string sound = read_bytes(trace);
  ASSERT_EQ(verify_error(trace), "");
  const std::string damaged = dir.file("damaged.rtrace");
  std::mt19937_64 rng(20);
  for (int trial = 0; trial < 24; ++trial) {
    std::string bytes = sound;
    const std::size_t at = std::uniform_int_distribution<std::size_t>(0, bytes.size() - 1)(rng);
    const std::size_t length = std::uniform_int_distribution<std::size_t>(2, 64)(rng);
    for (std::size_t i = at; i < std::min(bytes.size(), at + length); ++i)
      bytes[i] = static_cast<char>(bytes[i] ^ static_cast<char>(1 + rng() % 255));
    write_bytes(damaged, bytes);
    ASSERT_THAT(verify_error(damaged), HasSubstr(": byte ")) << "damage at " << at << " (" << length << " bytes)";
    ASSERT_THAT(texel_replay_error(damaged), HasSubstr(": byte ")) << "damage at " << at;
  }
}

TEST_F(DamagedTrace, GarbageAfterTheFooterIsTrailingDataNotATruncation) {
  const TempDir dir;
  const std::string& trace = small_trace();
  const std::string sound = read_bytes(trace);
  const std::string damaged = dir.write("trailing.rtrace", sound + "garbage\n");
  EXPECT_EQ(verify_error(damaged), damaged + ": byte " + std::to_string(sound.size()) +
                                       ": trailing data: 8 bytes after the trace's footer (the trace of 3 chunks "
                                       "ends at byte " +
                                       std::to_string(sound.size()) + ")");
}

TEST_F(DamagedTrace, NonZeroReservedFooterBytesAreDamage) {
  const TempDir dir;
  const std::string& trace = small_trace();
  std::string bytes = read_bytes(trace);
  bytes[bytes.size() - kFooterBytes + 12] = 1;
  const std::string damaged = dir.write("reserved.rtrace", bytes);
  EXPECT_EQ(verify_error(damaged),
            damaged + ": byte " + std::to_string(bytes.size() - kFooterBytes + 12) + ": reserved footer bytes are not zero");
}

}  // namespace
}  // namespace rastrace

// Traces of several frames (trace container version 3 on): the writer ends its chunks at every
// frame boundary and stamps them with the frame, readers report the frames and replays announce
// them (a single frame announces none), and damaged frame numbers are errors naming the byte.
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/error.h"
#include "tests/support/temp_dir.h"
#include "traces/crc32c.h"
#include "traces/text_formats.h"
#include "traces/trace_reader.h"
#include "traces/trace_writer.h"

namespace rastrace {
namespace {

using ::testing::HasSubstr;
using testing::TempDir;

// Records what a replay delivers: frames announced, and per frame the records of each kind.
class FrameLog final : public EventSink {
 public:
  void begin_frame(std::uint32_t frame) override {
    frames.push_back(frame);
    texels.push_back(0);
    vertices.push_back(0);
    draws.push_back(0);
  }
  void begin_draw(const DrawInfo&) override { ++back(draws); }
  void vertex_fetches(std::span<const VertexFetch> f) override { back(vertices) += f.size(); }
  void texel_accesses(std::span<const TexelAccess> t) override { back(texels) += t.size(); }

  std::vector<std::uint32_t> frames;
  std::vector<std::uint64_t> texels, vertices, draws;

 private:
  std::uint64_t& back(std::vector<std::uint64_t>& v) {
    if (v.empty()) v.push_back(0);
    return v.back();
  }
};

// Frame f: one draw of 5 + f fetches and 7 * (f + 1) texel accesses, in chunks of 4 records.
void write_frames(const std::string& path, std::uint32_t frames, bool announce_frame_zero = true) {
  TraceWriter writer(path, TraceMetadata{}, {3, 4});
  for (std::uint32_t f = 0; f < frames; ++f) {
    if (f > 0 || announce_frame_zero) writer.begin_frame(f);
    writer.begin_draw(DrawInfo{0, PrimitiveType::TriangleList, kNoRestart});
    std::vector<VertexFetch> fetches(5 + f, VertexFetch{f, true});
    writer.vertex_fetches(fetches);
    std::vector<TexelAccess> texels(7 * (f + 1), TexelAccess{0, 0, static_cast<std::uint16_t>(f), 1, 2, 3, 0});
    writer.texel_accesses(texels);
    writer.end_draw();
  }
  writer.finish();
}

void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

template <typename T>
T load(const std::string& bytes, std::size_t at) {
  T value;
  std::memcpy(&value, bytes.data() + at, sizeof(T));
  return value;
}

template <typename T>
void store(std::string& bytes, std::size_t at, T value) {
  std::memcpy(bytes.data() + at, &value, sizeof(T));
}

// Sets the frame of chunk index entry i and the index checksum to match.
void set_index_frame(std::string& bytes, std::size_t i, std::uint16_t frame) {
  const std::size_t footer = bytes.size() - kFooterBytes;
  const auto index = static_cast<std::size_t>(load<std::uint64_t>(bytes, footer));
  store<std::uint16_t>(bytes, index + 16 + i * 24 + 21, frame);
  store<std::uint32_t>(bytes, footer + 8, crc32c(bytes.data() + index, footer - index));
}

std::string open_error(const std::string& path) {
  try {
    TraceReader reader(path);
    verify_trace(reader);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(TraceFrames, EveryFramesChunksCarryItsNumberAndNoChunkSpansTwoFrames) {
  const TempDir dir;
  const std::string path = dir.file("frames.rtrace");
  write_frames(path, 3);
  TraceReader reader(path);
  EXPECT_EQ(reader.version(), 4u);
  EXPECT_EQ(reader.frames(), 3u);
  // Texels per frame 7, 14, 21 in chunks of 4: 2 + 4 + 6 chunks (the last of each frame partial).
  std::vector<std::uint32_t> texel_chunks(3, 0), texel_records(3, 0);
  std::uint16_t previous = 0;
  for (const ChunkInfo& c : reader.chunks()) {
    EXPECT_GE(c.frame, previous);  // the writer's frames never decrease over the whole file
    previous = c.frame;
    if (c.kind != RecordKind::Texel) continue;
    ++texel_chunks.at(c.frame);
    texel_records.at(c.frame) += c.records;
  }
  EXPECT_EQ(texel_chunks, (std::vector<std::uint32_t>{2, 4, 6}));
  EXPECT_EQ(texel_records, (std::vector<std::uint32_t>{7, 14, 21}));
  EXPECT_EQ(verify_trace(reader), (5u + 6u + 7u) + (7u + 14u + 21u));
}

TEST(TraceFrames, ReplayAnnouncesEachFrameBeforeItsRecords) {
  const TempDir dir;
  const std::string path = dir.file("frames.rtrace");
  write_frames(path, 4);
  TraceReader reader(path);
  FrameLog log;
  replay_trace(reader, log);
  EXPECT_EQ(log.frames, (std::vector<std::uint32_t>{0, 1, 2, 3}));
  EXPECT_EQ(log.texels, (std::vector<std::uint64_t>{7, 14, 21, 28}));
  EXPECT_EQ(log.vertices, (std::vector<std::uint64_t>{5, 6, 7, 8}));
  EXPECT_EQ(log.draws, (std::vector<std::uint64_t>{1, 1, 1, 1}));
  // Replaying one kind still announces every frame.
  TraceReader again(path);
  FrameLog texels_only;
  replay_trace(again, texels_only, {false, true, false, false});
  EXPECT_EQ(texels_only.frames, log.frames);
  EXPECT_EQ(texels_only.texels, log.texels);
}

TEST(TraceFrames, OneFrameIsTheSameFileAndReplaysWithoutFramesWhetherOrNotFrameZeroIsAnnounced) {
  const TempDir dir;
  write_frames(dir.file("announced.rtrace"), 1, true);
  write_frames(dir.file("silent.rtrace"), 1, false);
  const std::string bytes = testing::slurp(dir.file("silent.rtrace"));
  EXPECT_EQ(load<std::uint32_t>(bytes, 8), 4u);
  EXPECT_EQ(testing::slurp(dir.file("announced.rtrace")), bytes);
  TraceReader reader(dir.file("silent.rtrace"));
  EXPECT_EQ(reader.version(), 4u);
  EXPECT_EQ(reader.frames(), 1u);
  FrameLog log;
  replay_trace(reader, log);
  EXPECT_TRUE(log.frames.empty());  // a single-frame replay announces no frame
  EXPECT_EQ(log.texels, (std::vector<std::uint64_t>{7}));
}

TEST(TraceFrames, CsvExportRefusesSeveralFramesItCouldNotSeparate) {
  const TempDir dir;
  write_frames(dir.file("three.rtrace"), 3);
  TraceReader reader(dir.file("three.rtrace"));
  std::ostringstream out;
  try {
    export_csv(reader, out);
    ADD_FAILURE() << "exported";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("three.rtrace: a trace of 3 frames: CSV has no frame boundaries"));
  }
  EXPECT_EQ(out.str(), "");
}

TEST(TraceFrames, TheWriterRefusesDecreasingOrOversizedFrames) {
  const TempDir dir;
  TraceWriter writer(dir.file("bad.rtrace"), TraceMetadata{});
  writer.begin_frame(2);
  writer.begin_frame(2);  // the same frame again is no boundary
  EXPECT_THROW(writer.begin_frame(1), std::invalid_argument);
  EXPECT_THROW(writer.begin_frame(65536), std::invalid_argument);
  EXPECT_EQ(writer.frame(), 2u);
}

TEST(TraceFrames, ADecreasingFrameIsAnErrorNamingTheChunkAndItsByte) {
  const TempDir dir;
  const std::string path = dir.file("frames.rtrace");
  write_frames(path, 3);
  std::string bytes = testing::slurp(path);
  TraceReader reader(path);
  // The last texel chunk (frame 2) claims frame 1, after texel chunks of frame 2.
  std::size_t last_texel = 0;
  for (std::size_t i = 0; i < reader.chunks().size(); ++i)
    if (reader.chunks()[i].kind == RecordKind::Texel) last_texel = i;
  set_index_frame(bytes, last_texel, 1);
  write_bytes(dir.file("decreasing.rtrace"), bytes);
  EXPECT_THAT(open_error(dir.file("decreasing.rtrace")),
              HasSubstr("byte " + std::to_string(reader.chunks()[last_texel].offset) + ": chunk " +
                        std::to_string(last_texel) + ": frame 1 after frame 2 in an earlier chunk of its kind"));
}

TEST(TraceFrames, AChunkHeaderDisagreeingWithTheIndexFrameIsAnError) {
  const TempDir dir;
  const std::string path = dir.file("frames.rtrace");
  write_frames(path, 3);
  std::string bytes = testing::slurp(path);
  // The last texel chunk of frame 1 is said to be of frame 2 by the index (whose frames still
  // rise): its checksummed header says 1.
  TraceReader reader(path);
  std::size_t chunk = 0;
  for (std::size_t i = 0; i < reader.chunks().size(); ++i)
    if (reader.chunks()[i].kind == RecordKind::Texel && reader.chunks()[i].frame == 1) chunk = i;
  set_index_frame(bytes, chunk, 2);
  write_bytes(dir.file("mismatch.rtrace"), bytes);
  EXPECT_THAT(open_error(dir.file("mismatch.rtrace")),
              HasSubstr("byte " + std::to_string(reader.chunks()[chunk].offset + 6) + ": chunk " +
                        std::to_string(chunk) + ": frame 1 disagrees with the chunk index's frame 2"));
}

TEST(TraceFrames, AVersionFieldFlippedBetweenTwoAndThreeIsAnError) {
  const TempDir dir;
  write_frames(dir.file("one.rtrace"), 1);
  std::string one = testing::slurp(dir.file("one.rtrace"));
  store<std::uint32_t>(one, 8, 3);
  write_bytes(dir.file("one_as_3.rtrace"), one);
  EXPECT_THAT(open_error(dir.file("one_as_3.rtrace")),
              HasSubstr("byte 8: version 3 (several frames) but every chunk is of frame 0"));
  write_frames(dir.file("three.rtrace"), 3);
  std::string three = testing::slurp(dir.file("three.rtrace"));
  store<std::uint32_t>(three, 8, 2);
  write_bytes(dir.file("three_as_2.rtrace"), three);
  EXPECT_THAT(open_error(dir.file("three_as_2.rtrace")), HasSubstr("reserved bytes are not zero"));
}

}  // namespace
}  // namespace rastrace

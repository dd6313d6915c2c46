// Trace container versions: version 2 adds framebuffer chunks; files of version 1 (written by
// rastrace before framebuffer events existed) still read, record for record.
#include <bit>
#include <filesystem>
#include <fstream>
#include <span>
#include <sstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/error.h"
#include "tests/support/temp_dir.h"
#include "traces/memory_sink.h"
#include "traces/text_formats.h"
#include "traces/trace_reader.h"
#include "traces/trace_writer.h"

namespace rastrace {
namespace {

// Made by the rastrace of the main branch before this version existed: builtin:grid at 16x12,
// file order, trilinear, rendered by render_scene into its TraceWriter (897 bytes).
std::string version_1_file() {
  return (std::filesystem::path(RASTRACE_TEST_FILES_DIR) / "traces" / "data" / "v1_grid_16x12.rtrace").string();
}

std::vector<FramebufferAccess> sample_framebuffer_events() {
  std::vector<FramebufferAccess> events;
  for (std::uint32_t i = 0; i < 700; ++i) {
    FramebufferAccess a;
    a.x = static_cast<std::uint16_t>((i * 2) % 64);
    a.y = static_cast<std::uint16_t>(2 * (i / 32));
    a.op = static_cast<FramebufferOp>(i % 3);
    a.mask = static_cast<std::uint8_t>(1 + i % 15);
    a.triangle = i / 9;
    events.push_back(a);
  }
  events.back().x = 16382;  // the largest quad coordinate a 16384-pixel frame has
  events.back().triangle = 0xFFFFFFFFu;
  return events;
}

void expect_same(std::span<const FramebufferAccess> got, std::span<const FramebufferAccess> want) {
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < want.size(); ++i)
    EXPECT_TRUE(got[i].x == want[i].x && got[i].y == want[i].y && got[i].op == want[i].op &&
                got[i].mask == want[i].mask && got[i].triangle == want[i].triangle)
        << i;
}

TEST(TraceVersion, Version1FilesStillReadRecordForRecord) {
  TraceReader reader(version_1_file());
  EXPECT_EQ(reader.version(), 1u);
  EXPECT_EQ(reader.metadata().scene, "builtin:grid");
  EXPECT_EQ(reader.metadata().width, 16u);
  EXPECT_EQ(reader.metadata().height, 12u);
  // The counts the writing render reported: 6144 indices fetched, 672 texel reads.
  EXPECT_EQ(reader.records(RecordKind::Vertex), 6144u);
  EXPECT_EQ(reader.records(RecordKind::Texel), 672u);
  EXPECT_EQ(reader.records(RecordKind::Framebuffer), 0u);
  MemorySink events;
  replay_trace(reader, events);
  EXPECT_EQ(events.draws.size(), 1u);
  EXPECT_EQ(events.fetches.size(), 6144u);
  EXPECT_EQ(events.texels.size(), 672u);
  EXPECT_TRUE(events.framebuffer.empty());
  std::uint64_t triangles = 0;
  for (const VertexFetch& f : events.fetches) triangles += f.primitive_start;
  EXPECT_EQ(triangles, 2048u);

  // And it converts to CSV and back into a file of today's version with the same records.
  const testing::TempDir dir;
  {
    std::ofstream out(dir.file("v1.csv"));
    TraceReader again(version_1_file());
    export_csv(again, out);
  }
  {
    TraceWriter writer(dir.file("v2.rtrace"), read_csv_metadata(dir.file("v1.csv")));
    import_csv(dir.file("v1.csv"), writer);
  }
  TraceReader converted(dir.file("v2.rtrace"));
  EXPECT_EQ(converted.version(), kTraceVersion);
  MemorySink back;
  replay_trace(converted, back);
  ASSERT_EQ(back.texels.size(), events.texels.size());
  for (std::size_t i = 0; i < back.texels.size(); ++i) EXPECT_EQ(back.texels[i].x, events.texels[i].x) << i;
}

TEST(TraceVersion, FramebufferRecordsRoundTripThroughFileAndCsv) {
  const testing::TempDir dir;
  const std::vector<FramebufferAccess> events = sample_framebuffer_events();
  {
    TraceWriter writer(dir.file("fb.rtrace"), TraceMetadata{}, {3, 256});
    EXPECT_TRUE(writer.wants_framebuffer_events());
    writer.texel_accesses(std::vector<TexelAccess>(10));
    writer.framebuffer_accesses(events);
    writer.finish();
  }
  TraceReader reader(dir.file("fb.rtrace"));
  EXPECT_EQ(reader.version(), kTraceVersion);
  EXPECT_EQ(reader.records(RecordKind::Framebuffer), 700u);
  EXPECT_EQ(reader.chunks().size(), 1u + 3u);  // 700 records in chunks of 256
  MemorySink got;
  replay_trace(reader, got);
  expect_same(got.framebuffer, events);
  EXPECT_EQ(got.texels.size(), 10u);

  // Replaying without framebuffer records leaves them out.
  MemorySink texels_only;
  ReplayKinds kinds;
  kinds.framebuffer = false;
  TraceReader again(dir.file("fb.rtrace"));
  replay_trace(again, texels_only, kinds);
  EXPECT_TRUE(texels_only.framebuffer.empty());

  std::stringstream csv;
  {
    TraceReader third(dir.file("fb.rtrace"));
    export_csv(third, csv);
  }
  EXPECT_THAT(csv.str(), ::testing::HasSubstr("\ndepth_read,,,,,,,,,,0,0,0,,,1\n"));
  {
    std::ofstream out(dir.file("fb.csv"));
    out << csv.str();
  }
  MemorySink imported;
  import_csv(dir.file("fb.csv"), imported);
  expect_same(imported.framebuffer, events);
}

TEST(TraceVersion, AnOperationOrMaskOutOfRangeIsACorruptChunk) {
  std::vector<FramebufferAccess> events = sample_framebuffer_events();
  std::string raw;
  encode_framebuffer_records(events, raw);
  std::vector<FramebufferAccess> decoded;
  EXPECT_EQ(decode_framebuffer_records(std::span(reinterpret_cast<const std::uint8_t*>(raw.data()), raw.size()),
                                       static_cast<std::uint32_t>(events.size()), decoded),
            "");
  expect_same(decoded, events);
  events[5].mask = 16;
  encode_framebuffer_records(events, raw);
  EXPECT_EQ(decode_framebuffer_records(std::span(reinterpret_cast<const std::uint8_t*>(raw.data()), raw.size()),
                                       static_cast<std::uint32_t>(events.size()), decoded),
            "a value in the mask column is out of range (at most 15)");
  events[5].mask = 1;
  events[9].op = static_cast<FramebufferOp>(3);
  encode_framebuffer_records(events, raw);
  EXPECT_EQ(decode_framebuffer_records(std::span(reinterpret_cast<const std::uint8_t*>(raw.data()), raw.size()),
                                       static_cast<std::uint32_t>(events.size()), decoded),
            "operation 3 in record 9: expected 0 (depth read), 1 (depth write) or 2 (colour write)");
}

TEST(TraceVersion, AVersion1FileWithAFramebufferChunkIsRefused) {
  // Version 1 knew three chunk kinds: a file that says version 1 and holds kind 4 is corrupt.
  const testing::TempDir dir;
  {
    TraceWriter writer(dir.file("mixed.rtrace"), TraceMetadata{});
    writer.framebuffer_accesses(sample_framebuffer_events());
    writer.finish();
  }
  std::string bytes;
  {
    std::ifstream in(dir.file("mixed.rtrace"), std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  bytes[8] = 1;  // the version field
  {
    std::ofstream out(dir.file("mixed.rtrace"), std::ios::binary);
    out << bytes;
  }
  try {
    TraceReader reader(dir.file("mixed.rtrace"));
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_THAT(std::string(e.what()), ::testing::HasSubstr("chunk index entry 0 is invalid"));
  }
}

}  // namespace
}  // namespace rastrace

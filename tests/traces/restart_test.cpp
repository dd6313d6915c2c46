// A draw's primitive restart in trace files: "no restart" and "restart at 0xFFFFFFFF" are told
// apart, and files written before the two were told apart still read as they were meant.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "traces/chunk_codec.h"
#include "traces/memory_sink.h"
#include "traces/text_formats.h"
#include "traces/trace_reader.h"
#include "traces/trace_writer.h"

namespace rastrace {
namespace {

std::string temp_path(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("rastrace_restart_" + std::to_string(::getpid()) + "_" + name))
      .string();
}

// Every kind of draw header: a list, strips restarting at 0xFFFFFFFF and at 0xFFFF, a strip
// without restart.
const std::vector<DrawInfo> kDraws = {{0, PrimitiveType::TriangleList, kNoRestart},
                                      {1, PrimitiveType::TriangleStrip, kStripRestart},
                                      {2, PrimitiveType::TriangleStrip, 0xFFFFu},
                                      {3, PrimitiveType::TriangleStrip, kNoRestart}};

// The 9 header bytes of a vertex chunk: u32 draw, u8 type, u32 restart (little endian).
std::string header_bytes(std::uint32_t draw, std::uint8_t type, std::uint32_t restart) {
  std::string bytes;
  for (int i = 0; i < 4; ++i) bytes += static_cast<char>((draw >> (8 * i)) & 0xFF);
  bytes += static_cast<char>(type);
  for (int i = 0; i < 4; ++i) bytes += static_cast<char>((restart >> (8 * i)) & 0xFF);
  return bytes;
}

TEST(TraceRestart, ChunkHeadersOfListsAndRestartingStripsAreTheVersion1BytesAndReadBack) {
  const std::vector<VertexFetch> fetches = {{4, true}, {5, false}, {6, false}};
  // What version-1 writers wrote (kNoRestart was 0xFFFFFFFF then): unchanged, so old files and
  // new ones agree byte for byte. Only a strip without restart is new: type byte 1 | 0x80.
  const std::vector<std::string> want = {header_bytes(0, 0, 0xFFFFFFFFu), header_bytes(1, 1, 0xFFFFFFFFu),
                                         header_bytes(2, 1, 0xFFFFu), header_bytes(3, 0x81, 0xFFFFFFFFu)};
  for (std::size_t d = 0; d < kDraws.size(); ++d) {
    std::string raw;
    encode_vertex_records(kDraws[d], fetches, raw);
    EXPECT_EQ(raw.substr(0, 9), want[d]) << "draw " << d;
    DrawInfo got;
    got.restart_index = 12345u;
    std::vector<VertexFetch> out;
    ASSERT_EQ(decode_vertex_records({reinterpret_cast<const std::uint8_t*>(raw.data()), raw.size()}, 3, got, out), "");
    EXPECT_EQ(got.draw, kDraws[d].draw);
    EXPECT_EQ(got.type, kDraws[d].type);
    EXPECT_EQ(got.restart_index, kDraws[d].restart_index) << "draw " << d;
  }
  // The flag belongs to strips only.
  std::string raw;
  encode_vertex_records(kDraws[3], fetches, raw);
  raw[4] = static_cast<char>(0x80);
  DrawInfo got;
  std::vector<VertexFetch> out;
  EXPECT_EQ(decode_vertex_records({reinterpret_cast<const std::uint8_t*>(raw.data()), raw.size()}, 3, got, out),
            "unknown primitive type byte 128 (expected 0, 1, 2 or 129)");
}

TEST(TraceRestart, TraceFileAndCsvKeepEveryDrawsRestart) {
  const std::string path = temp_path("draws.rtrace"), csv = temp_path("draws.csv"), back = temp_path("back.rtrace");
  {
    TraceWriter writer(path, TraceMetadata{});
    for (const DrawInfo& d : kDraws) {
      writer.begin_draw(d);
      writer.vertex_fetches({{{0, true}, {1, false}, {2, false}}});
      writer.end_draw();
    }
    writer.finish();
  }
  {
    TraceReader reader(path);
    std::ofstream out(csv);
    export_csv(reader, out);
  }
  {
    TraceWriter writer(back, read_csv_metadata(csv));
    import_csv(csv, writer);
  }
  for (const std::string& file : {path, back}) {
    TraceReader reader(file);
    MemorySink sink;
    replay_trace(reader, sink);
    ASSERT_EQ(sink.draws.size(), kDraws.size()) << file;
    for (std::size_t d = 0; d < kDraws.size(); ++d)
      EXPECT_EQ(sink.draws[d].restart_index, kDraws[d].restart_index) << file << " draw " << d;
  }
  for (const auto& p : {path, csv, back}) std::filesystem::remove(p);
}

TEST(TraceRestart, CsvWrittenWithTheOldNoRestartValueStillReads) {
  // Before the restart column could be empty, every draw stored 4294967295 when it had none.
  const std::string csv = temp_path("old.csv");
  std::ofstream(csv) << "event,draw,type,restart,vertex,primitive_start,texture,level,x,y,pixel_x,pixel_y,triangle,"
                        "address,label\n"
                        "begin_draw,0,0,4294967295,,,,,,,,,,,\nvertex,,,,7,1,,,,,,,,,\nend_draw,,,,,,,,,,,,,,\n"
                        "begin_draw,1,1,4294967295,,,,,,,,,,,\nvertex,,,,7,1,,,,,,,,,\nend_draw,,,,,,,,,,,,,,\n"
                        "begin_draw,2,1,,,,,,,,,,,,\nvertex,,,,7,1,,,,,,,,,\nend_draw,,,,,,,,,,,,,,\n";
  MemorySink sink;
  import_csv(csv, sink);
  ASSERT_EQ(sink.draws.size(), 3u);
  EXPECT_EQ(sink.draws[0].restart_index, kNoRestart);     // a list has none
  EXPECT_EQ(sink.draws[1].restart_index, kStripRestart);  // a strip restarted at the stored index
  EXPECT_EQ(sink.draws[2].restart_index, kNoRestart);
  std::filesystem::remove(csv);
}

}  // namespace
}  // namespace rastrace

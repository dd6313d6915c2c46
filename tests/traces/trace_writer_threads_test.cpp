// The writer compresses chunks on several threads and writes them in order: its file must not
// depend on how many threads compress (chunk order, offsets, index and bytes), must read back
// with every event, and a failed write must still be reported, with no file left behind.
#include <sys/resource.h>

#include <csignal>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "tests/support/temp_dir.h"
#include "traces/memory_sink.h"
#include "traces/replay_file.h"
#include "traces/trace_writer.h"

namespace rastrace {
namespace {

// A few frames of draws whose fetches, texels, framebuffer events and addresses interleave in
// runs of random length, so that chunks of every kind fill and end in a mixed order.
void write_stream(EventSink& writer, unsigned seed) {
  std::mt19937 random(seed);
  std::uint32_t x = 0, y = 0;
  for (std::uint32_t frame = 0; frame < 3; ++frame) {
    writer.begin_frame(frame);
    for (std::uint32_t draw = 0; draw < 4; ++draw) {
      writer.begin_draw(DrawInfo{draw, PrimitiveType::TriangleList, kNoRestart});
      for (int burst = 0; burst < 40; ++burst) {
        std::vector<VertexFetch> fetches(random() % 50);
        for (std::size_t i = 0; i < fetches.size(); ++i)
          fetches[i] = VertexFetch{static_cast<std::uint32_t>(random() % 5000), i % 3 == 0};
        writer.vertex_fetches(fetches);
        std::vector<TexelAccess> texels(random() % 300);
        for (TexelAccess& t : texels) {
          x += random() % 3;
          y += random() % 2;
          t.texture = draw % 2;
          t.level = static_cast<std::uint8_t>(random() % 4);
          t.x = x % 1024;
          t.y = y % 1024;
          t.pixel_x = static_cast<std::uint16_t>(x % 640);
          t.pixel_y = static_cast<std::uint16_t>(y % 480);
          t.triangle = static_cast<std::uint32_t>(burst);
        }
        writer.texel_accesses(texels);
        std::vector<FramebufferAccess> events(random() % 60);
        for (FramebufferAccess& e : events) {
          e.x = static_cast<std::uint16_t>((random() % 320) * 2);
          e.y = static_cast<std::uint16_t>((random() % 240) * 2);
          e.op = static_cast<FramebufferOp>(random() % kFramebufferOps);
          e.mask = static_cast<std::uint8_t>(1 + random() % 15);
          e.triangle = static_cast<std::uint32_t>(burst);
        }
        writer.framebuffer_accesses(events);
        if (burst % 9 == 0) {
          std::vector<AddressAccess> addresses(random() % 40);
          for (AddressAccess& a : addresses) a = AddressAccess{random() * 64ull, static_cast<std::uint8_t>(random() % 3)};
          writer.address_accesses(addresses);
        }
      }
      writer.end_draw();
    }
  }
}

std::string bytes_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

std::string written_with(const testing::TempDir& dir, unsigned threads, unsigned seed) {
  const std::string path = dir.file("t" + std::to_string(threads) + ".rtrace");
  TraceMetadata meta;
  meta.tool_version = "test";  // the version string is in the header: pin it
  TraceWriter writer(path, meta, TraceWriterOptions{.chunk_records = 97, .compression_threads = threads});
  write_stream(writer, seed);
  writer.finish();
  return path;
}

TEST(TraceWriterThreads, TheFileIsTheSameForAnyNumberOfCompressionThreads) {
  testing::TempDir dir;
  for (unsigned seed = 1; seed <= 2; ++seed) {
    const std::string one = bytes_of(written_with(dir, 1, seed));
    ASSERT_GT(one.size(), 10000u);
    for (unsigned threads = 2; threads <= 5; ++threads)
      EXPECT_EQ(bytes_of(written_with(dir, threads, seed)), one) << threads << " threads, seed " << seed;
  }
}

TEST(TraceWriterThreads, WhatFourThreadsWroteReadsBackEventForEvent) {
  testing::TempDir dir;
  MemorySink sent, read;
  write_stream(sent, 3);
  replay_file(written_with(dir, 4, 3), read);
  ASSERT_GT(sent.texels.size(), 1000u);
  ASSERT_EQ(read.draws.size(), sent.draws.size());
  ASSERT_EQ(read.fetches.size(), sent.fetches.size());
  ASSERT_EQ(read.texels.size(), sent.texels.size());
  ASSERT_EQ(read.framebuffer.size(), sent.framebuffer.size());
  for (std::size_t i = 0; i < sent.fetches.size(); ++i) {
    ASSERT_EQ(read.fetches[i].vertex, sent.fetches[i].vertex) << i;
    ASSERT_EQ(read.fetches[i].primitive_start, sent.fetches[i].primitive_start) << i;
  }
  for (std::size_t i = 0; i < sent.texels.size(); ++i) {
    const TexelAccess &a = read.texels[i], &b = sent.texels[i];
    ASSERT_TRUE(a.texture == b.texture && a.level == b.level && a.x == b.x && a.y == b.y && a.pixel_x == b.pixel_x &&
                a.pixel_y == b.pixel_y && a.triangle == b.triangle)
        << i;
  }
  for (std::size_t i = 0; i < sent.framebuffer.size(); ++i) {
    const FramebufferAccess &a = read.framebuffer[i], &b = sent.framebuffer[i];
    ASSERT_TRUE(a.x == b.x && a.y == b.y && a.op == b.op && a.mask == b.mask && a.triangle == b.triangle) << i;
  }
}

// A disk that fills: RLIMIT_FSIZE in a child (SIGXFSZ ignored, so the write fails with EFBIG).
// The failure surfaces from a later submission or from finish(), and nothing is left behind.
// Returns the child's exit code: 0 when both hold.
int write_to_a_full_disk(const std::string& path, const std::filesystem::path& folder) {
  std::signal(SIGXFSZ, SIG_IGN);
  const rlimit limit{16384, 16384};
  if (setrlimit(RLIMIT_FSIZE, &limit) != 0) return 2;
  bool reported = false;
  try {
    TraceMetadata meta;
    meta.tool_version = "test";
    TraceWriter writer(path, meta, TraceWriterOptions{.chunk_records = 97, .compression_threads = 3});
    write_stream(writer, 1);
    writer.finish();
  } catch (const std::exception& error) {
    reported = std::string(error.what()).find("write failed") != std::string::npos;
  }
  return reported && std::filesystem::is_empty(folder) ? 0 : 1;
}

TEST(TraceWriterThreads, AFailedWriteIsReportedAndLeavesNoFile) {
  testing::TempDir dir;
  EXPECT_EXIT(std::exit(write_to_a_full_disk(dir.file("full.rtrace"), dir.path())), ::testing::ExitedWithCode(0), "");
}

}  // namespace
}  // namespace rastrace

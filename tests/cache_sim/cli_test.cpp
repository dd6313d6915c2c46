// `rastrace replay` and `rastrace sweep` end to end, through the built tool.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cache_sim/live_bank_sink.h"
#include "naive_cache.h"
#include "support/run_rastrace.h"
#include "support/temp_dir.h"
#include "support/test_data.h"
#include "tests/support/synthetic_frame.h"
#include "traces/trace_reader.h"
#include "traces/trace_writer.h"

namespace rastrace {
namespace {

using ::testing::HasSubstr;

using ToolRun = testing::CommandRun;
ToolRun run(const std::vector<std::string>& arguments) { return testing::run_rastrace(arguments); }

TEST(SweepCommand, DinSweepGivesTheNaiveReferenceMissesForEveryConfiguration) {
  std::mt19937_64 rng(2024);
  std::vector<std::uint64_t> addresses;
  for (int i = 0; i < 1200; ++i) addresses.push_back(rng() % 3 ? 0x10000 + rng() % 3000 : rng() % 0x40000);
  const testing::TempDir dir;
  const std::string din = dir.file("trace.din");
  {
    std::ofstream out(din);
    for (const std::uint64_t a : addresses) out << (a % 3) << ' ' << std::hex << a << std::dec << '\n';
  }
  const ToolRun r = run({"sweep", din, "--cache",
                         "size=256B..2KiB,line=16B/64B,assoc=1/2/full,policy=fifo/lru/random/opt", "--format", "json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json rows = nlohmann::json::parse(r.out);
  ASSERT_EQ(rows.size(), 4u * 2 * 3 * 4);
  for (const auto& row : rows) {
    const std::uint64_t size = row.at("size_bytes"), line = row.at("line_bytes"), assoc = row.at("assoc");
    const std::string policy = row.at("policy");
    EXPECT_EQ(row.at("accesses").get<std::uint64_t>(), addresses.size());
    EXPECT_EQ(row.at("misses").get<std::uint64_t>(), testing::naive_misses(addresses, size, line, assoc, policy, 1))
        << size << "/" << line << "/" << assoc << "/" << policy;
    EXPECT_EQ(row.at("source"), "address");
    EXPECT_EQ(row.at("trace_format"), "din");
  }
}

TEST(ReplayCommand, ReplayTableStatesItsParametersAndMatchesTheLiveBank) {
  const testing::SyntheticFrame frame = testing::make_synthetic_frame(64, 64, 256);
  TraceMetadata meta;
  meta.scene = "synthetic";
  meta.ordering = "scanline";
  meta.width = meta.height = 64;
  meta.filter = "bilinear";
  meta.textures = frame.textures;
  const testing::TempDir dir;
  const std::string path = dir.file("frame.rtrace");
  {
    TraceWriter writer(path, meta);
    writer.texel_accesses(frame.texels);
    writer.finish();
  }
  CacheBankConfig bank;
  bank.texture.push_back({CacheConfig{4096, 64, 2, ReplacementPolicy::Lru, 1}, parse_layout("block4")});
  bank.texture.push_back({CacheConfig{4096, 64, 0, ReplacementPolicy::Opt, 1}, parse_layout("morton")});
  LiveBankSink live(bank, frame.textures);
  live.texel_accesses(frame.texels);
  live.finish();

  const ToolRun r = run({"replay", path, "--cache", "size=4KiB,line=64B,assoc=2,policy=lru,layout=block4", "--cache",
                         "size=4KiB,assoc=full,policy=opt,layout=morton", "--format", "csv"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* parameter :
       {"# scene: synthetic", "# ordering: scanline", "# resolution: 64x64", "# filter: bilinear", "# texel_bytes: 4",
        "# level_alignment_bytes: 4096", "# source: texel"})
    EXPECT_THAT(r.out, HasSubstr(parameter));
  EXPECT_THAT(r.out, HasSubstr("4096,64,2,lru,block4,16384," + std::to_string(live.texture_stats()[0].hits) + "," +
                               std::to_string(live.texture_stats()[0].misses) + ","));
  EXPECT_THAT(r.out, HasSubstr("4096,64,0,opt,morton,16384," + std::to_string(live.texture_stats()[1].hits) + "," +
                               std::to_string(live.texture_stats()[1].misses) + ","));

  const std::string plot = dir.file("plot.svg");
  const ToolRun s = run({"sweep", path, "--cache", "size=1KiB..8KiB,policy=lru/fifo,layout=linear/morton", "--plot",
                         plot, "--format", "latex"});
  EXPECT_EQ(s.exit_code, 0) << s.err;
  EXPECT_THAT(s.out, HasSubstr("\\toprule"));
  EXPECT_TRUE(std::filesystem::exists(plot));
  std::ifstream svg(plot);
  const std::string text((std::istreambuf_iterator<char>(svg)), {});
  EXPECT_THAT(text, HasSubstr("lru morton"));
  EXPECT_THAT(text, HasSubstr("fifo linear"));
}

TEST(ReplayCommand, BadInputsAreReportedWithExitCodeOne) {
  const testing::TempDir dir;
  const std::string path = dir.file("bad.rtrace");
  {
    TraceWriter writer(path, {});
    writer.address_accesses({{{1, 0}, {2, 0}}});
    writer.finish();
  }
  ToolRun r = run({"replay", path, "--cache", "size=3KiB,line=64B,assoc=32"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("48 lines do not divide into 32-way sets"));
  r = run({"replay", path, "--cache", "size=4KiB,colour=red"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("unknown key 'colour'"));
  r = run({"sweep", path, "--cache", "size=1KiB..3KiB"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("--cache size: '1KiB..3KiB': expected a range between two powers of two"));
  // Flip a payload byte: the replay names the chunk.
  std::string bytes;
  {
    std::ifstream in(path, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  const std::uint64_t offset = TraceReader(path).chunks()[0].offset;
  bytes[offset + kChunkHeaderBytes + 2] ^= 1;
  std::ofstream(path, std::ios::binary) << bytes;
  r = run({"replay", path, "--cache", "size=4KiB"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("byte " + std::to_string(offset) + ": chunk 0: checksum mismatch"));
}

TEST(CacheSpecCommands, OldSpellingsFailShowingTheSpecToWrite) {
  const testing::TempDir dir;
  const std::string path = dir.file("old.rtrace"), image = dir.file("old.png");
  {
    TraceWriter writer(path, {});
    writer.address_accesses({{{1, 0}, {2, 0}}});
    writer.finish();
  }
  ToolRun r = run({"sweep", path, "--size", "1KiB..64KiB", "--assoc", "1,2,full", "--policy", "fifo,lru"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("--size 1KiB..64KiB, --assoc 1,2,full, --policy fifo,lru: write --cache "
                               "size=1KiB..64KiB,assoc=1/2/full,policy=fifo/lru"));
  r = run({"sweep", path, "--entries", "4..64", "--policy", "fifo,lru"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("--entries 4..64, --policy fifo,lru: write --cache entries=4..64,policy=fifo/lru"));
  r = run({"replay", path, "--cache", "16KiB,64B,4way,lru"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("--cache '16KiB,64B,4way,lru': write size=16KiB,line=64B,assoc=4,policy=lru"));
  r = run({"render", "builtin:grid", "-o", image, "--vcache", "fifo:16"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("--vcache 'fifo:16': write entries=16,policy=fifo"));
  r = run({"render", "builtin:grid", "-o", image, "--tcache", "16KiB,64B,4way,lru"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("--tcache '16KiB,64B,4way,lru': write size=16KiB,line=64B,assoc=4,policy=lru"));
  r = run({"render", "builtin:grid", "-o", image, "--layout", "morton"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("--layout 'morton': write the layout in the texture cache spec"));
  EXPECT_FALSE(std::filesystem::exists(image));
}

TEST(CacheSpecCommands, SweepAndReplayTakeAlternativesAndVertexCaches) {
  // Two draws of a strip restarting at 0xFFFFFFFF: replay and sweep agree on every cache.
  const testing::TempDir dir;
  const std::string path = dir.file("vertex.rtrace");
  {
    TraceWriter writer(path, {});
    for (std::uint32_t d = 0; d < 2; ++d) {
      writer.begin_draw({d, PrimitiveType::TriangleStrip, kStripRestart});
      writer.vertex_fetches({{{0, true}, {1, false}, {2, false}, {3, false}, {1, true}, {2, false}, {4, false}}});
      writer.end_draw();
    }
    writer.finish();
  }
  const ToolRun replay = run({"replay", path, "--cache", "entries=2/4,policy=fifo/lru", "--format", "csv"});
  const ToolRun sweep = run({"sweep", path, "--cache", "entries=2/4,policy=fifo/lru", "--format", "csv"});
  ASSERT_EQ(replay.exit_code, 0) << replay.err;
  ASSERT_EQ(sweep.exit_code, 0) << sweep.err;
  // Per draw, the cache emptied: 0 1 2 3 | 1 2 4, three triangles. Two entries miss all 7 under
  // either policy; four entries miss 5. Rows in the order policy, entries.
  for (const ToolRun* t : {&replay, &sweep}) {
    EXPECT_THAT(t->out, HasSubstr("fifo,2,14,14,6,0,"));
    EXPECT_THAT(t->out, HasSubstr("fifo,4,14,10,6,0,"));
    EXPECT_THAT(t->out, HasSubstr("lru,2,14,14,6,0,"));
    EXPECT_THAT(t->out, HasSubstr("lru,4,14,10,6,0,"));
    EXPECT_LT(t->out.find("fifo,4,"), t->out.find("lru,2,"));
  }
}

}  // namespace
}  // namespace rastrace

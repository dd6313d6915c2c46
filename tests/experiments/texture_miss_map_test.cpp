// The texture miss map (experiments/texture_miss_map.h): its per-pixel misses add up to the
// replay's misses for the same cache, and the image and its legend file are written.
#include <filesystem>
#include <fstream>
#include <numeric>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "experiments/texture_miss_map.h"
#include "support/run_rastrace.h"
#include "support/temp_dir.h"

namespace rastrace {
namespace {

TEST(TextureMissMap, PixelMissesAddUpToTheReplayAndTheImageHasItsLegend) {
  const testing::TempDir dir;
  const std::string trace = dir.file("bunny.rtrace");
  ASSERT_EQ(testing::run_rastrace({"render", "builtin:bunny", "--size", "160x120", "-o", dir.file("b.png"), "--trace",
                                   trace})
                .exit_code,
            0);
  const std::string spec = "size=4KiB,line=64B,assoc=2,policy=lru,layout=block4";
  const testing::CommandRun replay =
      testing::run_rastrace({"replay", trace, "--cache", spec, "--format", "json", "--miss-map", dir.file("m.png")});
  ASSERT_EQ(replay.exit_code, 0) << replay.err;
  const nlohmann::json rows = nlohmann::json::parse(replay.out);
  CacheConfig cache;
  cache.size_bytes = 4096;
  cache.line_bytes = 64;
  cache.assoc = 2;
  LayoutSpec layout;
  layout.kind = LayoutKind::Block;
  layout.block = 4;
  const TextureMissMap map = texture_miss_map(trace, cache, layout);
  EXPECT_EQ(map.width, 160u);
  EXPECT_EQ(map.height, 120u);
  const std::uint64_t total = std::accumulate(map.misses.begin(), map.misses.end(), std::uint64_t{0});
  EXPECT_EQ(total, rows[0].at("misses").get<std::uint64_t>());
  EXPECT_EQ(map.stats.accesses, rows[0].at("accesses").get<std::uint64_t>());
  EXPECT_EQ(map.pixels_with(-1) + map.pixels_with(0) + map.pixels_with(1) + map.pixels_with(2) + map.pixels_with(3),
            160u * 120u);
  EXPECT_GT(map.pixels_with(3), 0u);
  for (std::size_t p = 0; p < map.misses.size(); ++p) {
    if (!map.textured[p]) {
      ASSERT_EQ(map.misses[p], 0u);
    }
  }
  ASSERT_TRUE(std::filesystem::exists(dir.file("m.png")));
  std::ifstream legend(dir.file("m.png.txt"));
  std::stringstream text;
  text << legend.rdbuf();
  EXPECT_NE(text.str().find("cache: " + spec), std::string::npos) << text.str();
  EXPECT_NE(text.str().find("red     3 or more  " + std::to_string(map.pixels_with(3))), std::string::npos);
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(TextureMissMap, RenderDrawsTheSameMapLiveAsTheReplayOfItsTraceAtOneAndTwoThreads) {
  const testing::TempDir dir;
  const std::string spec = "size=8KiB,line=64B,assoc=2,policy=fifo,layout=morton";
  for (const char* threads : {"1", "2"}) {
    const std::string trace = dir.file(std::string("spider") + threads + ".rtrace");
    const std::string live = dir.file(std::string("live") + threads + ".png");
    const testing::CommandRun render =
        testing::run_rastrace({"render", "builtin:spider", "--size", "200x150", "-o", dir.file("s.png"), "--trace", trace,
                               "--tcache", spec, "--threads", threads, "--miss-map", live});
    ASSERT_EQ(render.exit_code, 0) << render.err;
    const testing::CommandRun replay =
        testing::run_rastrace({"replay", trace, "--cache", spec, "--miss-map", dir.file("replayed.png")});
    ASSERT_EQ(replay.exit_code, 0) << replay.err;
    ASSERT_FALSE(read_file(live).empty());
    EXPECT_EQ(read_file(live), read_file(dir.file("replayed.png"))) << threads << " threads";
    // The legends differ only in the file name on their first line.
    const std::string live_text = read_file(live + ".txt");
    const std::string replay_text = read_file(dir.file("replayed.png.txt"));
    EXPECT_EQ(live_text.substr(live_text.find('\n')), replay_text.substr(replay_text.find('\n')));
    EXPECT_NE(live_text.find("cache: " + spec), std::string::npos) << live_text;
  }
}

TEST(TextureMissMap, RenderRefusesALiveMapUnderOpt) {
  const testing::TempDir dir;
  const testing::CommandRun render =
      testing::run_rastrace({"render", "builtin:bunny", "--size", "64x48", "-o", dir.file("b.png"), "--tcache",
                             "size=8KiB,line=64B,assoc=2,policy=opt", "--miss-map", dir.file("m.png")});
  EXPECT_EQ(render.exit_code, 1);
  EXPECT_NE(render.err.find("--miss-map with --tcache policy=opt"), std::string::npos) << render.err;
  EXPECT_FALSE(std::filesystem::exists(dir.file("m.png")));
}

}  // namespace
}  // namespace rastrace

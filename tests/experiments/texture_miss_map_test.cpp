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

}  // namespace
}  // namespace rastrace

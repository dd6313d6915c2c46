// `rastrace vipm` through the built binary: JSON output with its keys, bad method names, bad caches.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>

#include "tests/support/run_rastrace.h"
#include "tests/support/temp_dir.h"

namespace rastrace {
namespace {

using ::testing::HasSubstr;
using testing::run_rastrace;

TEST(VipmCommand, GridJsonHasLodsAndSummary) {
  const auto result = run_rastrace({"vipm", "grid:16x16", "--format", "json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto json = nlohmann::json::parse(result.out);
  ASSERT_TRUE(json.contains("lods"));
  ASSERT_TRUE(json.contains("summary"));
  // The rows' keys are checked on the experiment itself (tests/experiments/vipm_experiment_test.cpp).
  EXPECT_FALSE(json["lods"].empty());
  EXPECT_EQ(json["summary"].size(), 6u);
  EXPECT_EQ(json["parameters"]["cache"], "entries=16,policy=fifo");
}

TEST(VipmCommand, UnknownMethodIsAnErrorNamingTheAcceptedNames) {
  const auto result = run_rastrace({"vipm", "grid:8x8", "--methods", "vanilla,skip"});
  EXPECT_TRUE(result.exit_code == 1 || result.exit_code == 2) << result.exit_code;
  EXPECT_THAT(result.err, HasSubstr("--methods 'skip'"));
  EXPECT_THAT(result.err, HasSubstr("vanilla, skipstrips, skiplists, mixed, mixedstrips, sliding"));
}

TEST(VipmCommand, CacheMustBeOneVertexCache) {
  for (const char* spec : {"entries=16/32", "size=16KiB"}) {
    const auto result = run_rastrace({"vipm", "grid:8x8", "--cache", spec});
    EXPECT_EQ(result.exit_code, 1) << spec;
    EXPECT_THAT(result.err, HasSubstr("--cache")) << spec;
  }
}

// The texel trace of a VIPM frame is swept like any other: replaying it under the render's texture
// cache gives the render's own live counts.
TEST(RenderVipm, TraceOfALodReplaysToTheLiveTextureMisses) {
  const testing::TempDir dir;
  const std::string trace = dir.file("grid-lod.rtrace");
  const char* cache = "size=8KiB,line=64B,assoc=2,policy=lru,layout=block4";
  const auto render = run_rastrace({"render", "builtin:grid", "-o", dir.file("grid.png"), "--vipm", "mixedstrips",
                                    "--lod", "300", "--tcache", cache, "--trace", trace, "--format", "json"});
  ASSERT_EQ(render.exit_code, 0) << render.err;
  const auto frame = nlohmann::json::parse(render.out);
  const auto& row = frame.at(0);
  EXPECT_EQ(row["vipm"], "mixedstrips");
  EXPECT_EQ(row["order"], "vipm:mixedstrips");
  EXPECT_THAT(row["vipm_lod"].get<std::string>(), HasSubstr("grid32x32 300/"));
  EXPECT_EQ(row["triangles"], 1469);
  EXPECT_GT(row["degenerate"], 0);

  const auto replay = run_rastrace({"replay", trace, "--cache", cache, "--format", "json"});
  ASSERT_EQ(replay.exit_code, 0) << replay.err;
  const auto replayed = nlohmann::json::parse(replay.out).at(0);
  EXPECT_EQ(replayed["misses"], row["texture_misses"]);
  EXPECT_EQ(replayed["accesses"], row["texel_accesses"]);
  EXPECT_EQ(replayed["ordering"], "vipm:mixedstrips");
}

TEST(RenderVipm, LodWithoutVipmOrWithAnOrderIsAnError) {
  const testing::TempDir dir;
  auto result = run_rastrace({"render", "builtin:grid", "-o", dir.file("a.png"), "--lod", "5"});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_THAT(result.err, HasSubstr("--lod '5': the level of detail needs --vipm METHOD"));
  result = run_rastrace({"render", "builtin:grid", "-o", dir.file("a.png"), "--vipm", "vanilla", "--order", "tipsy"});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_THAT(result.err, HasSubstr("--order tipsy with --vipm"));
  result = run_rastrace({"render", "builtin:grid", "-o", dir.file("a.png"), "--lod-formula", "max"});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_THAT(result.err, HasSubstr("--lod-formula 'max': expected lengths or max_component"));
  EXPECT_FALSE(std::filesystem::exists(dir.file("a.png")));
}

}  // namespace
}  // namespace rastrace

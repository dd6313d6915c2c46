// Yang, Mitra and Huang's texture experiment: texture-grouped strips against strips on the
// four-colour bunny, determinism, and live simulation against replay.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "experiments/texture_experiment.h"
#include "support/run_rastrace.h"
#include "support/temp_dir.h"
#include "support/test_data.h"
#include "traces/trace_reader.h"

namespace rastrace {
namespace {

// The command's stdout; its exit code must be 0.
std::string run(const std::vector<std::string>& arguments) {
  const testing::CommandRun result = testing::run_rastrace(arguments);
  EXPECT_EQ(result.exit_code, 0) << ::testing::PrintToString(arguments) << "\n" << result.err;
  return result.out;
}

TextureExperiment bunny_strip_against_texgroup(const std::string& trace_dir) {
  TextureExperiment experiment;
  experiment.title = "fig9";
  experiment.render.scene = "builtin:bunny";
  experiment.render.cull = "back";
  experiment.orders = {"strip", "texgroup"};
  experiment.rasters = {"scanline"};
  experiment.vertex_cache = vertex_cache_spec(VertexCachePolicy::Fifo, 16);
  experiment.sweep.sizes = {1024, 2048, 4096, 8192, 16384};
  experiment.sweep.lines = {64};
  experiment.sweep.assocs = {0};
  experiment.sweep.policies = {ReplacementPolicy::Lru};
  experiment.sweep.layouts = {LayoutSpec{}};
  experiment.trace_dir = trace_dir;
  return experiment;
}

TEST(TextureExperiment, TexgroupHasFewerTextureMissesThanStripOnTheFourColourBunny) {
  (void)testing::data_file("meshes/bunny00.off");
  const testing::TempDir dir;
  const std::vector<TextureRun> runs = run_texture_experiment(bunny_strip_against_texgroup(dir.path().string()));
  ASSERT_EQ(runs.size(), 2u);
  const TextureRun& strip = runs[0];
  const TextureRun& grouped = runs[1];
  ASSERT_EQ(strip.order, "strip");
  ASSERT_EQ(strip.sweep.rows.size(), 5u);
  ASSERT_EQ(grouped.sweep.rows.size(), 5u);
  int fewer = 0;
  for (std::size_t i = 0; i < 5; ++i) {
    ASSERT_EQ(strip.sweep.rows[i].cache.size_bytes, grouped.sweep.rows[i].cache.size_bytes);
    if (grouped.sweep.rows[i].stats.misses < strip.sweep.rows[i].stats.misses) ++fewer;
    std::printf("%6llu B: strip %llu misses, texgroup %llu\n",
                static_cast<unsigned long long>(strip.sweep.rows[i].cache.size_bytes),
                static_cast<unsigned long long>(strip.sweep.rows[i].stats.misses),
                static_cast<unsigned long long>(grouped.sweep.rows[i].stats.misses));
  }
  EXPECT_GE(fewer, 3) << "texgroup must beat strip at 3 or more sizes from 1 KiB to 16 KiB";
  EXPECT_LE(grouped.vertex.acmr(), 1.03 * strip.vertex.acmr());
  // Both orders draw every face once: the same triangles reach the vertex cache.
  EXPECT_EQ(strip.vertex.triangles, 75408u);
  EXPECT_EQ(grouped.vertex.triangles, 75408u);
}

TEST(TextureExperiment, LiveRenderAgreesWithTheSweptTraceToTheMiss) {
  // `render` simulates its texture cache live; `texsweep` records the trace and replays it.
  // The spider's strips run across its five materials: every triangle keeps its face's texture.
  const testing::TempDir dir;
  for (const auto& [scene, order] : {std::pair{"builtin:bunny", "strip"},
                                     {"builtin:bunny", "texgroup"},
                                     {"builtin:spider", "strip"},
                                     {"builtin:spider", "texgroup"}}) {
    const auto live = nlohmann::json::parse(
        run({"render", scene, "--order", order, "--cull", "back", "--tcache",
             "size=4KiB,line=64B,assoc=full,policy=lru,layout=linear", "-o", dir.file("frame.png"), "--json"}));
    const auto swept = nlohmann::json::parse(
        run({"texsweep", scene, "--order", order, "--cull", "back", "--raster", "scanline", "--tcache",
             "size=4KiB,line=64B,assoc=full,policy=lru,layout=linear", "--format", "json"}));
    // One sweep row, then the frame-traffic row of the same render.
    ASSERT_EQ(swept.size(), 2u);
    EXPECT_EQ(live[0]["texture_misses"], swept[0]["misses"]) << scene << " " << order;
    EXPECT_EQ(live[0]["texel_accesses"], swept[0]["accesses"]) << scene << " " << order;
    EXPECT_NEAR(live[0]["acmr"].get<double>(), swept[0]["vertex_acmr"].get<double>(), 1e-12) << scene << " " << order;
    for (const char* key : {"vertex_bytes", "depth_read_bytes", "depth_write_bytes", "colour_write_bytes", "overdraw"})
      EXPECT_EQ(live[0][key], swept[1][key]) << scene << " " << order << " " << key;
  }
}

TEST(TextureExperiment, JsonRowsSplitByKindIntoOneSchemaPerTable) {
  // Texture-cache rows and frame-traffic rows share one array: each names its kind, and every
  // row of a kind has the same keys in the same order (what pandas needs for one DataFrame each).
  const auto rows = nlohmann::ordered_json::parse(
      run({"texsweep", "builtin:grid", "--order", "tipsy,texgroup", "--base", "tipsy", "--raster", "scanline,tiled8",
           "--tcache", "size=1KiB..4KiB,assoc=full,policy=fifo/lru,layout=linear/morton", "--format", "json"}));
  std::map<std::string, std::vector<std::string>> keys_of_kind;
  std::map<std::string, int> rows_of_kind;
  for (const auto& row : rows) {
    ASSERT_TRUE(row.contains("kind")) << row.dump();
    std::vector<std::string> keys;
    for (auto it = row.begin(); it != row.end(); ++it) keys.push_back(it.key());
    const std::string kind = row["kind"];
    ++rows_of_kind[kind];
    const auto [known, inserted] = keys_of_kind.emplace(kind, keys);
    EXPECT_EQ(known->second, keys) << kind;
  }
  // 2 orders x 2 rasters: 3 sizes x 2 policies x 2 layouts texture-cache rows each, one frame row each.
  EXPECT_EQ(rows_of_kind, (std::map<std::string, int>{{"frame_traffic", 4}, {"texture_sweep", 48}}));
  EXPECT_NE(std::find(keys_of_kind["texture_sweep"].begin(), keys_of_kind["texture_sweep"].end(), "miss_rate"),
            keys_of_kind["texture_sweep"].end());
  EXPECT_NE(std::find(keys_of_kind["frame_traffic"].begin(), keys_of_kind["frame_traffic"].end(), "overdraw"),
            keys_of_kind["frame_traffic"].end());
}

TEST(TextureExperiment, RerunningTheSameCommandGivesByteIdenticalTables) {
  for (const char* format : {"md", "json"}) {
    const std::vector<std::string> command = {
        "texsweep", "builtin:grid",
        "--order",  "tipsy,texgroup",
        "--base",   "tipsy",
        "--raster", "scanline,tiled8",
        "--tcache", "size=1KiB..4KiB,assoc=full,policy=fifo/lru/opt,layout=linear/morton",
        "--format", format};
    const std::string first = run(command);
    EXPECT_FALSE(first.empty());
    EXPECT_EQ(first, run(command)) << format;
  }
}

TEST(TextureExperiment, TheRetiredPerAxisSweepFlagsShowTheCacheSpecToWrite) {
  const testing::CommandRun r =
      testing::run_rastrace({"texsweep", "builtin:grid", "--size", "1KiB,4KiB", "--policy", "lru"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("write --tcache size=1KiB/4KiB,policy=lru"), std::string::npos) << r.err;
  const testing::CommandRun vertex = testing::run_rastrace({"report", "builtin:grid", "--tcache", "entries=16"});
  EXPECT_EQ(vertex.exit_code, 1);
  EXPECT_NE(vertex.err.find("expected a byte-cache spec"), std::string::npos) << vertex.err;
}

TEST(TextureExperiment, ASceneWithoutTexturesIsAClearError) {
  const testing::TempDir dir;
  TextureExperiment experiment = bunny_strip_against_texgroup(dir.path().string());
  experiment.render.scene = testing::data_file("meshes/fandisk.off");
  try {
    run_texture_experiment(experiment);
    FAIL() << "expected an InputError";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("has no texture"), std::string::npos) << e.what();
  }
}

// One metadata builder: a texsweep or report trace states the same settings, cull, lod and
// lighting included, as `rastrace render --trace` of the same frame.
TEST(TextureExperiment, TracesCarryTheSameMetadataAsRenderTraces) {
  const testing::TempDir dir;
  const testing::CommandRun rendered =
      testing::run_rastrace({"render", "builtin:grid", "--order", "strip", "--cull", "back", "--raster", "tiled8", "-o",
                             dir.file("frame.png"), "--trace", dir.file("render.rtrace")});
  ASSERT_EQ(rendered.exit_code, 0) << rendered.err;

  TextureExperiment experiment;
  experiment.render.scene = "builtin:grid";
  experiment.render.cull = "back";
  experiment.orders = {"strip"};
  experiment.rasters = {"tiled8"};
  experiment.vertex_cache = vertex_cache_spec(VertexCachePolicy::Fifo, 16);
  experiment.sweep.sizes = {1024};
  experiment.trace_dir = dir.file("texsweep");
  const std::vector<TextureRun> runs = run_texture_experiment(experiment);
  ASSERT_EQ(runs.size(), 1u);

  const TraceMetadata from_render = TraceReader(dir.file("render.rtrace")).metadata();
  const TraceMetadata from_experiment = TraceReader(runs[0].trace_path).metadata();
  EXPECT_EQ(from_experiment, from_render);
  EXPECT_EQ(from_experiment.extra.at("cull"), "back");
  EXPECT_EQ(from_experiment.extra.at("lod"), "lengths");
  EXPECT_EQ(from_experiment.extra.at("lighting"), "off");
  EXPECT_EQ(from_experiment.extra.at("raster"), "tiled8");
}

}  // namespace
}  // namespace rastrace

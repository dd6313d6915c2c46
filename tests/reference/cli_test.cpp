// `rastrace render` and `rastrace compare` as a user runs them.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/run_rastrace.h"
#include "support/temp_dir.h"
#include "support/test_data.h"

namespace rastrace {
namespace {

using testing::CommandRun;
CommandRun run(const std::vector<std::string>& arguments) { return testing::run_rastrace(arguments); }

TEST(RenderCommand, PrintsTheFrameCostsAsJsonAndWritesTheImageAndTrace) {
  const testing::TempDir dir;
  const std::string image = dir.file("grid.png"), trace = dir.file("grid.rtrace"), depth = dir.file("grid.exr");
  const CommandRun r = run({"render", "builtin:grid", "--size", "160x120", "-o", image, "--trace", trace, "--depth",
                            depth, "--raster", "tiled8", "--vcache", "entries=16,policy=fifo", "--tcache",
                            "size=8KiB,line=64B,assoc=2,policy=lru,layout=morton", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json rows = nlohmann::json::parse(r.out);
  ASSERT_EQ(rows.size(), 1u);
  const nlohmann::json& row = rows[0];
  EXPECT_EQ(row["triangles"], 2048);        // the 32x32 grid
  EXPECT_EQ(row["vertices_shaded"], 2112);  // scanline grid, FIFO 16: 33 * 64
  EXPECT_NEAR(row["acmr"].get<double>(), 1.031, 0.0005);
  EXPECT_GT(row["fragments_shaded"].get<std::int64_t>(), 5000);
  EXPECT_GT(row["texel_accesses"].get<std::int64_t>(), 4 * row["fragments_shaded"].get<std::int64_t>());
  EXPECT_GT(row["texture_misses"].get<std::int64_t>(), 0);
  EXPECT_NEAR(row["bytes_per_fragment"].get<double>(),
              row["texture_bytes"].get<double>() / row["fragments_shaded"].get<double>(), 1e-9);
  EXPECT_EQ(row["layout"], "morton");
  EXPECT_TRUE(std::filesystem::exists(image));
  EXPECT_GT(std::filesystem::file_size(trace), 1000u);
  EXPECT_GT(std::filesystem::file_size(depth), 1000u);
}

TEST(RenderCommand, BadOptionsAreErrorsAndLeaveNoFile) {
  const testing::TempDir dir;
  const std::string image = dir.file("bad.png");
  CommandRun r = run({"render", "builtin:grid", "-o", image, "--tcache", "size=16KiB,line=64B,assoc=4way,policy=lru"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("--tcache assoc: '4way': expected a whole number"), std::string::npos) << r.err;
  r = run({"render", "builtin:grid", "-o", image, "--raster", "zigzag"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("expected scanline, tiled8 or hilbert"), std::string::npos) << r.err;
  r = run({"render", "builtin:grid", "-o", image, "--size", "0x10"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_FALSE(std::filesystem::exists(image));
}

TEST(CompareCommand, GridAgainstSoftpipeMeetsTheAcceptanceThresholds) {
  const testing::TempDir dir;
  const std::string diff = dir.file("diff.png");
  const CommandRun r =
      run({"compare", "builtin:grid", "--size", "160x120", "--driver", "softpipe", "-o", diff, "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json row = nlohmann::json::parse(r.out).at(0);
  EXPECT_EQ(row["driver"], "softpipe");
  EXPECT_EQ(row["pixels"], 160 * 120);
  EXPECT_GT(row["covered"].get<std::int64_t>(), 5000);
  EXPECT_LE(row["diff_gt_2"].get<double>(), 0.01);
  EXPECT_LE(row["diff_gt_8"].get<double>(), row["diff_gt_2"].get<double>());
  EXPECT_GE(row["psnr"].get<double>(), 40.0);
  EXPECT_EQ(row["coverage_differs_off_edge"], 0);
  EXPECT_TRUE(std::filesystem::exists(diff));
  EXPECT_EQ(run({"compare", "builtin:grid", "--driver", "swrast"}).exit_code, 1);
}

TEST(RenderCommand, AnisoRecordsTheMaximumInTheTraceAndCountsTexelsPerTexturedFragment) {
  const testing::TempDir dir;
  const std::string trace = dir.file("grid.rtrace");
  const CommandRun r = run({"render", "builtin:grid", "--size", "160x120", "-o", dir.file("grid.png"), "--aniso", "4",
                            "--trace", trace, "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json row = nlohmann::json::parse(r.out).at(0);
  // The grid is seen at an angle: each ellipse holds more texels than trilinear's 8.
  EXPECT_GT(row["texels_per_textured_fragment"].get<double>(), 8.0);
  EXPECT_NEAR(row["texels_per_textured_fragment"].get<double>(),
              row["texel_accesses"].get<double>() / row["fragments_shaded"].get<double>(), 1e-9);
  const CommandRun trilinear = run({"render", "builtin:grid", "--size", "160x120", "-o", dir.file("t.png"), "--json"});
  ASSERT_EQ(trilinear.exit_code, 0) << trilinear.err;
  EXPECT_EQ(nlohmann::json::parse(trilinear.out).at(0)["texels_per_textured_fragment"].get<double>(), 8.0);
  const std::string csv = dir.file("grid.csv");
  const CommandRun convert = run({"trace", "convert", trace, csv});
  ASSERT_EQ(convert.exit_code, 0) << convert.err;
  std::ifstream in(csv);
  std::string metadata;
  std::getline(in, metadata);
  EXPECT_NE(metadata.find("\"aniso\":\"4\""), std::string::npos) << metadata;
}

TEST(RenderCommand, AnisoAbove16IsAUsageErrorNamingTheRange) {
  const testing::TempDir dir;
  for (const char* value : {"17", "0", "-1", "4.5"}) {
    const CommandRun r = run({"render", "builtin:grid", "-o", dir.file("a.png"), "--aniso", value});
    EXPECT_NE(r.exit_code, 0) << value;
    EXPECT_NE(r.err.find("--aniso: expected a whole number from 1 to 16"), std::string::npos) << r.err;
  }
  EXPECT_FALSE(std::filesystem::exists(dir.file("a.png")));
}

}  // namespace
}  // namespace rastrace

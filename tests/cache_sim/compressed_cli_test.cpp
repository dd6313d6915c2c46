// Compressed textures through the built tool: a rendered frame's trace replayed and swept as
// RGBA8, BC1 and BC7 (format=), and through a decoded L1 over a compressed L2 (--decoded-l1).
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/run_rastrace.h"
#include "support/temp_dir.h"

namespace rastrace {
namespace {

using ::testing::HasSubstr;

// The rows of a --format json output (an array of rows, each stating its parameters) that have
// the column `key`.
nlohmann::json rows_with(const std::string& out, const std::string& key) {
  nlohmann::json rows = nlohmann::json::array();
  for (const nlohmann::json& row : nlohmann::json::parse(out))
    if (row.contains(key)) rows.push_back(row);
  return rows;
}

TEST(CompressedReplay, SweepAndReplayAgreeAndBc1MissesLessThanRgba8) {
  const testing::TempDir dir;
  const std::string trace = dir.file("grid.rtrace");
  const auto render = testing::run_rastrace(
      {"render", "builtin:grid", "--size", "160x120", "-o", dir.file("grid.png"), "--trace", trace});
  ASSERT_EQ(render.exit_code, 0) << render.err;
  const std::string spec = "size=2KiB/8KiB,line=64B,assoc=4,layout=block4,format=rgba8/bc1/bc7";
  const auto replay = testing::run_rastrace({"replay", trace, "--cache", spec, "--format", "json"});
  const auto sweep = testing::run_rastrace({"sweep", trace, "--cache", spec, "--format", "json"});
  ASSERT_EQ(replay.exit_code, 0) << replay.err;
  ASSERT_EQ(sweep.exit_code, 0) << sweep.err;
  EXPECT_THAT(replay.out, HasSubstr("block4:bc1"));
  EXPECT_THAT(sweep.out, HasSubstr("block4:bc7"));
  const nlohmann::json swept = rows_with(sweep.out, "layout");
  ASSERT_EQ(swept.size(), 6u);
  std::map<std::string, std::uint64_t> misses;  // layout at 2 KiB
  for (const nlohmann::json& row : swept)
    if (row.at("size_bytes").get<std::uint64_t>() == 2048) misses[row.at("layout")] = row.at("misses");
  ASSERT_EQ(misses.size(), 3u);
  // Eight times fewer bytes per texel than RGBA8 for BC1, four for BC7.
  EXPECT_LT(misses["block4:bc1"], misses["block4:bc7"]);
  EXPECT_LT(misses["block4:bc7"], misses["block4:rgba8"]);
  std::size_t compared = 0;
  for (const nlohmann::json& row : rows_with(replay.out, "layout"))
    if (row.at("size_bytes").get<std::uint64_t>() == 2048) {
      EXPECT_EQ(row.at("misses").get<std::uint64_t>(), misses[row.at("layout")]) << row.at("layout");
      ++compared;
    }
  EXPECT_EQ(compared, 3u);
}

TEST(CompressedReplay, ADecodedL1ReportsDecodedAndCompressedTraffic) {
  const testing::TempDir dir;
  const std::string trace = dir.file("grid.rtrace");
  ASSERT_EQ(testing::run_rastrace({"render", "builtin:grid", "--size", "160x120", "-o", dir.file("g.png"), "--trace",
                                   trace})
                .exit_code,
            0);
  const auto run = testing::run_rastrace({"replay", trace, "--level", "size=2KiB,line=64B,assoc=4,format=bc1",
                                          "--level", "size=16KiB,line=64B,assoc=8", "--decoded-l1", "--format",
                                          "json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("L1 decoded 2KiB"));
  const nlohmann::json rows = rows_with(run.out, "level");
  ASSERT_EQ(rows.size(), 2u);
  // Each 64-byte decoded line comes from 8 compressed bytes of BC1.
  EXPECT_EQ(rows[1].at("bytes_requested").get<std::uint64_t>() * 8, rows[0].at("bytes_fetched").get<std::uint64_t>());

  const auto alone = testing::run_rastrace(
      {"replay", trace, "--level", "size=2KiB,line=64B,assoc=4,format=bc1", "--decoded-l1"});
  EXPECT_EQ(alone.exit_code, 1);
  EXPECT_THAT(alone.err, HasSubstr("decoded L1 needs a level of compressed blocks"));
  const auto no_hierarchy = testing::run_rastrace({"replay", trace, "--cache", "size=2KiB", "--decoded-l1"});
  EXPECT_EQ(no_hierarchy.exit_code, 1);
  EXPECT_THAT(no_hierarchy.err, HasSubstr("--decoded-l1: expected a hierarchy"));
  const auto lower_format = testing::run_rastrace({"replay", trace, "--level", "size=2KiB,line=64B,assoc=4",
                                                   "--level", "size=16KiB,line=64B,assoc=8,format=bc1"});
  EXPECT_EQ(lower_format.exit_code, 1);
  EXPECT_THAT(lower_format.err, HasSubstr("format= belong to the L1 spec"));
}

}  // namespace
}  // namespace rastrace

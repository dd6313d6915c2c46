// `rastrace replay` with sectored caches and --level hierarchies on a rendered bunny trace: the
// degenerate cases equal the plain cache the same command replays beside them, and the hierarchy's
// bytes add up from level to level.
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/run_rastrace.h"
#include "support/temp_dir.h"

namespace rastrace {
namespace {

nlohmann::json replay_json(const std::vector<std::string>& arguments) {
  const testing::CommandRun run = testing::run_rastrace(arguments);
  EXPECT_EQ(run.exit_code, 0) << run.err;
  return nlohmann::json::parse(run.out);
}

TEST(HierarchyReplay, OneSectorPerLineAndAOneLineL1EqualThePlainCacheOnTheBunny) {
  const testing::TempDir dir;
  const std::string trace = dir.file("bunny.rtrace");
  const testing::CommandRun render =
      testing::run_rastrace({"render", "builtin:bunny", "--size", "256x256", "-o", dir.file("bunny.png"), "--trace", trace});
  ASSERT_EQ(render.exit_code, 0) << render.err;
  const nlohmann::json rows = replay_json(
      {"replay", trace, "--format", "json", "--cache", "size=16KiB,line=128B,assoc=4,layout=block4", "--cache",
       "size=16KiB,line=128B,sector=128B/32B,assoc=4,layout=block4", "--level", "size=128B,line=128B,assoc=full,layout=block4",
       "--level", "size=16KiB,line=128B,assoc=4"});
  ASSERT_EQ(rows.size(), 5u);
  const std::uint64_t plain = rows[0].at("misses");
  EXPECT_GT(plain, 10000u);
  // sector=128B: one sector per line.
  EXPECT_EQ(rows[1].at("misses").get<std::uint64_t>(), plain);
  // sector=32B: the same lines resident, more (smaller) misses, fewer bytes.
  EXPECT_EQ(rows[2].at("line_misses").get<std::uint64_t>(), plain);
  EXPECT_GT(rows[2].at("misses").get<std::uint64_t>(), plain);
  EXPECT_LT(rows[2].at("bytes_fetched").get<std::uint64_t>(), rows[0].at("bytes_fetched").get<std::uint64_t>());
  // The hierarchy: L2 behind a one-line L1 is the plain cache.
  EXPECT_EQ(rows[3].at("level"), "L1");
  EXPECT_EQ(rows[4].at("level"), "L2");
  EXPECT_EQ(rows[4].at("misses").get<std::uint64_t>(), plain);
  EXPECT_EQ(rows[4].at("accesses"), rows[3].at("misses"));
  EXPECT_EQ(rows[4].at("bytes_requested"), rows[3].at("bytes_fetched"));
  EXPECT_EQ(rows[3].at("bytes_requested").get<std::uint64_t>(), 4 * rows[3].at("accesses").get<std::uint64_t>());
}

TEST(HierarchyReplay, UnitsSplitTheL1AccessesAndBadLevelsAreNamed) {
  const testing::TempDir dir;
  const std::string trace = dir.file("grid.rtrace");
  ASSERT_EQ(testing::run_rastrace({"render", "builtin:grid", "--size", "128x128", "-o", dir.file("grid.png"), "--trace",
                                   trace})
                .exit_code,
            0);
  const std::vector<std::string> levels = {"--level", "size=4KiB,line=64B,assoc=4,layout=block4", "--level",
                                           "size=64KiB,line=64B,assoc=8"};
  std::vector<std::string> one = {"replay", trace, "--format", "json"};
  one.insert(one.end(), levels.begin(), levels.end());
  std::vector<std::string> four = one;
  four.insert(four.end(), {"--units", "4", "--tile", "8", "--inclusion", "inclusive"});
  const nlohmann::json a = replay_json(one), b = replay_json(four);
  ASSERT_EQ(a.size(), 2u);
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(a[0].at("accesses"), b[0].at("accesses"));
  // Same line size at both levels: one L2 access per L1 miss, from every unit.
  EXPECT_EQ(b[1].at("accesses"), b[0].at("misses"));
  EXPECT_EQ(b[0].at("l1_units"), 4);
  EXPECT_EQ(b[0].at("level"), "L1 (4 units)");

  const testing::CommandRun bad = testing::run_rastrace(
      {"replay", trace, "--level", "size=4KiB,layout=block4", "--level", "size=64KiB,layout=morton"});
  EXPECT_NE(bad.exit_code, 0);
  EXPECT_NE(bad.err.find("(L2): layout=, texel=, align= and format= belong to the L1 spec"), std::string::npos) << bad.err;
  const testing::CommandRun none = testing::run_rastrace({"replay", trace});
  EXPECT_NE(none.exit_code, 0);
  EXPECT_NE(none.err.find("expected --cache SPEC or --level SPEC"), std::string::npos) << none.err;
}

TEST(HierarchyReplay, RenderSimulatesTheHierarchyLiveAsReplayDoesFromItsTrace) {
  const testing::TempDir dir;
  const std::string trace = dir.file("bunny.rtrace");
  const std::vector<std::string> hierarchy = {"--level",   "size=8KiB,line=128B,sector=32B,assoc=4,layout=block4",
                                              "--level",   "size=64KiB,line=128B,assoc=8",
                                              "--units",   "2",
                                              "--inclusion", "inclusive",
                                              "--format",  "json"};
  std::vector<std::string> render = {"render", "builtin:bunny", "--size", "192x192", "-o", dir.file("b.png"),
                                     "--trace", trace};
  render.insert(render.end(), hierarchy.begin(), hierarchy.end());
  const nlohmann::json live = replay_json(render);
  std::vector<std::string> replay = {"replay", trace};
  replay.insert(replay.end(), hierarchy.begin(), hierarchy.end());
  const nlohmann::json replayed = replay_json(replay);
  ASSERT_EQ(live.size(), 3u);  // the frame's row, then L1 and L2
  ASSERT_EQ(replayed.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k)
    for (const char* key : {"accesses", "misses", "line_misses", "bytes_requested", "bytes_fetched", "invalidations"})
      EXPECT_EQ(live[k + 1].at(key), replayed[k].at(key)) << "level " << k + 1 << " " << key;
  EXPECT_EQ(live[1].at("accesses"), live[0].at("texel_accesses"));
}

TEST(HierarchyReplay, AStaticCameraMissesInTheL2OnlyInTheFirstFrameWhenTheL2HoldsTheFrame) {
  const testing::TempDir dir;
  const std::string trace = dir.file("bunny.rtrace");
  const nlohmann::json rows = replay_json(
      {"render", "builtin:bunny", "--size", "192x192", "-o", dir.file("b.png"), "--trace", trace, "--level",
       "size=8KiB,line=128B,assoc=4,layout=block4", "--level", "size=4MiB,line=128B,assoc=16", "--frames", "3",
       "--format", "json"});
  ASSERT_EQ(rows.size(), 1u + 2u + 6u);  // the frame, the hierarchy (2 levels), 3 frames x 2 levels
  // The compulsory misses of the first frame: its distinct 128-byte lines.
  const nlohmann::json cold = replay_json(
      {"replay", trace, "--cache", "size=4MiB,line=128B,assoc=full,layout=block4", "--format", "json"});
  const std::uint64_t compulsory = cold[0].at("compulsory");
  EXPECT_GT(compulsory, 100u);
  for (std::size_t f = 0; f < 3; ++f) {
    const nlohmann::json& l1 = rows[3 + 2 * f];
    const nlohmann::json& l2 = rows[4 + 2 * f];
    EXPECT_EQ(l1.at("frame"), f);
    EXPECT_EQ(l2.at("level"), "L2");
    EXPECT_EQ(l2.at("accesses"), l1.at("misses"));
    EXPECT_EQ(l2.at("misses").get<std::uint64_t>(), f == 0 ? compulsory : 0u) << "frame " << f + 1;
  }
  // The trace holds the 3 frames; replay --per-frame gives the render's per-frame rows.
  const nlohmann::json per_frame =
      replay_json({"replay", trace, "--per-frame", "--level", "size=8KiB,line=128B,assoc=4,layout=block4", "--level",
                   "size=4MiB,line=128B,assoc=16", "--format", "json"});
  ASSERT_EQ(per_frame.size(), 6u);
  for (std::size_t r = 0; r < 6; ++r)
    for (const char* key : {"frame", "cache", "level", "accesses", "misses", "line_misses", "miss_rate", "bytes_fetched"})
      EXPECT_EQ(per_frame[r].at(key), rows[3 + r].at(key)) << "row " << r << " " << key;
  // Without --level, the frame table alone, its counts summed over the frames.
  const nlohmann::json plain = replay_json({"render", "builtin:bunny", "--size", "192x192", "-o", dir.file("c.png"),
                                            "--frames", "3", "--format", "json"});
  ASSERT_EQ(plain.size(), 1u);
  EXPECT_EQ(plain[0].at("texel_accesses"), rows[0].at("texel_accesses"));
  EXPECT_EQ(plain[0].at("texel_accesses"), rows[1].at("accesses"));  // the L1 of 3 frames
  EXPECT_EQ(rows[1].at("accesses").get<std::uint64_t>(),
            rows[3].at("accesses").get<std::uint64_t>() + rows[5].at("accesses").get<std::uint64_t>() +
                rows[7].at("accesses").get<std::uint64_t>());
}

}  // namespace
}  // namespace rastrace

// `rastrace vcache` and `rastrace reorder` as a user runs them: the built tool at RASTRACE_BINARY.
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/run_rastrace.h"
#include "support/temp_dir.h"
#include "support/test_data.h"

namespace {

using Result = rastrace::testing::CommandRun;
Result run(const std::vector<std::string>& arguments) { return rastrace::testing::run_rastrace(arguments); }

TEST(VcacheCli, CastanoRowsAsCsv) {
  const Result r = run({"vcache", "grid:16x16", "--algo", "scanline,grid", "--cache", "entries=12/16/20", "--format",
                        "csv", "--no-time"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("algo,policy,cache,target,triangles,vertices,misses,acmr,atvr,indices_per_triangle,vertices_"
                       "sent,restarts,bandwidth,fetch_bytes,overfetch\n"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("scanline,fifo,16,16,512,289,544,"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("grid,fifo,20,20,512,289,289,"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("grid,fifo,16,16,512,289,306,"), std::string::npos) << r.out;
}

TEST(VcacheCli, StripPrintsVerticesSentOnTriceratops) {
  // Yang et al., Table 1: 6,911 vertices sent by Evans et al.'s strips; ours send 6,820.
  const Result r = run({"vcache", rastrace::testing::data_file("meshes/triceratops.off"), "--algo", "strip", "--cache",
                        "entries=16", "--format", "csv", "--no-time"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("strip,fifo,16,16,5660,2832,"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(",6820,"), std::string::npos) << r.out;
}

TEST(VcacheCli, TargetSetsTheCacheTheOrderIsMadeFor) {
  const Result r = run({"vcache", "grid:16x16", "--algo", "grid", "--target", "8", "--cache", "entries=8/16",
                        "--format", "csv", "--no-time"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("grid,fifo,16,8,512,289,323,"), std::string::npos) << r.out;
}

TEST(VcacheCli, EvictionAccountingPrintsCastanosPublishedCounts) {
  const Result r = run({"vcache", "grid:16x16", "--algo", "grid", "--cache", "entries=12/16/20", "--accounting",
                        "evictions", "--format", "csv", "--no-time"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("# accounting: evictions (NVIDIA Mesh Tools)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("grid,fifo,12,12,512,289,307,"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("grid,fifo,16,16,512,289,306,"), std::string::npos) << r.out;
  const Result on16 = run({"vcache", "grid:16x16", "--algo", "grid", "--target", "8", "--cache", "entries=16",
                           "--accounting", "evictions", "--format", "csv", "--no-time"});
  EXPECT_NE(on16.out.find("grid,fifo,16,8,512,289,325,"), std::string::npos) << on16.out;
  EXPECT_EQ(
      run({"vcache", "grid:4x4", "--algo", "grid", "--cache", "entries=16,policy=lru", "--accounting", "evictions"})
          .exit_code,
      1);
  EXPECT_EQ(run({"vcache", "grid:4x4", "--algo", "grid", "--accounting", "hits"}).exit_code, 1);
}

TEST(VcacheCli, NoTimeOutputIsByteIdenticalBetweenRuns) {
  const std::vector<std::string> args = {"vcache",   "grid:12x12", "--algo",
                                         "all",      "--cache",    "entries=12/16,policy=fifo/lru",
                                         "--format", "json",       "--no-time"};
  const Result a = run(args), b = run(args);
  ASSERT_EQ(a.exit_code, 0) << a.err;
  EXPECT_EQ(a.out, b.out);
  EXPECT_NE(a.out.find("\"algo\": \"kcache\""), std::string::npos);
  EXPECT_NE(a.out.find("\"policy\": \"lru\""), std::string::npos);
}

TEST(VcacheCli, BadInputIsAnErrorWithExitCode1) {
  EXPECT_EQ(run({"vcache", "grid:16x", "--algo", "grid"}).exit_code, 1);
  EXPECT_EQ(run({"vcache", "grid:4x4", "--cache", "entries=0"}).exit_code, 1);
  // The spellings before the cache-spec grammar are errors that show the spec to write.
  Result old = run({"vcache", "grid:4x4", "--cache", "12,16"});
  EXPECT_EQ(old.exit_code, 1);
  EXPECT_NE(old.err.find("--cache '12,16': write entries=12/16"), std::string::npos) << old.err;
  old = run({"vcache", "grid:4x4", "--cache", "entries=12", "--policy", "fifo,lru"});
  EXPECT_EQ(old.exit_code, 1);
  EXPECT_NE(old.err.find("--policy 'fifo,lru': write the policy in the cache spec, e.g. --cache "
                         "entries=12/16,policy=fifo/lru"),
            std::string::npos)
      << old.err;
  EXPECT_EQ(run({"vcache", "grid:4x4", "--algo", "nosuch"}).exit_code, 1);
  const Result r = run({"vcache", rastrace::testing::data_file("meshes/triceratops.off"), "--algo", "grid"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("not a regular grid"), std::string::npos) << r.err;
}

TEST(VcacheCli, MissImageIsWrittenForOneOrderingAndRefusedForSeveral) {
  const rastrace::testing::TempDir dir;
  const std::string image = dir.file("grid-tipsy.png");
  const Result r = run({"vcache", "grid:16x16", "--algo", "greedy", "--cache", "entries=12", "--format", "csv",
                        "--no-time", "--miss-image", image});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(image));
  EXPECT_GT(std::filesystem::file_size(image), 1000u);
  // The strips' restarts are charged in bytes/triangle: 32 r + 2 (indices, restart markers included) / triangles.
  // 634 vertices sent + 39 restart indices = 673 indices for 512 triangles: b = 1.314, and
  // 32 * 313 / 512 + 2 * 673 / 512 = 22.19 bytes per triangle.
  EXPECT_NE(r.out.find("vertices_sent,restarts,bandwidth,fetch_bytes,overfetch\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("greedy,fifo,12,12,512,289,313,0.611328125,1.083044983,1.314453125,634,39,22.191406250"),
            std::string::npos)
      << r.out;
  const std::string refused = dir.file("two.png");
  const Result two =
      run({"vcache", "grid:16x16", "--algo", "greedy,tipsy", "--cache", "entries=12", "--miss-image", refused});
  EXPECT_EQ(two.exit_code, 1);
  EXPECT_NE(two.err.find("--miss-image"), std::string::npos) << two.err;
  EXPECT_FALSE(std::filesystem::exists(refused));
}

TEST(ReorderCli, WritesTheFacesInTheNewOrderAndReadsBack) {
  const rastrace::testing::TempDir dir;
  const std::string out = dir.file("fandisk-tipsy.off");
  const Result r = run(
      {"reorder", rastrace::testing::data_file("meshes/fandisk.off"), "--algo", "tipsy", "--cache", "16", "-o", out});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("12946 faces in tipsy order, ACMR 0.652"), std::string::npos) << r.out;
  // Read back: the written file in file order has tipsy's ACMR.
  const Result check =
      run({"vcache", out, "--algo", "original", "--cache", "entries=16", "--format", "csv", "--no-time"});
  EXPECT_NE(check.out.find("original,fifo,16,16,12946,6475,"), std::string::npos) << check.out;
  EXPECT_NE(check.out.find(",0.652"), std::string::npos) << check.out;
  EXPECT_EQ(run({"reorder", "grid:4x4", "--algo", "tipsy", "-o", "/nonexistent-dir/x.off"}).exit_code, 1);
}

}  // namespace

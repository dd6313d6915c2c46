// `rastrace vcache`'s vertex-fetch columns (cache_sim/vertex_fetch.h): meshoptimizer's model by
// default, equal to meshopt_analyzeVertexFetch in this process; --vertex-bytes and --fetch.
#include <meshoptimizer.h>

#include <gtest/gtest.h>

#include "support/run_rastrace.h"
#include "support/test_meshes.h"

namespace rastrace {
namespace {

TEST(VcacheFetchCli, FetchColumnsEqualMeshoptAnalyzeVertexFetch) {
  const Mesh& mesh = testing::cached_mesh("fandisk.off");
  for (const std::uint32_t vertex_bytes : {32u, 48u}) {
    const meshopt_VertexFetchStatistics theirs =
        meshopt_analyzeVertexFetch(mesh.indices.data(), mesh.indices.size(), mesh.vertex_count(), vertex_bytes);
    const testing::CommandRun r = testing::run_rastrace(
        {"vcache", testing::data_file("meshes/fandisk.off"), "--algo", "original", "--cache", "entries=16",
         "--vertex-bytes", std::to_string(vertex_bytes), "--format", "csv", "--no-time"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("," + std::to_string(theirs.bytes_fetched) + ","), std::string::npos)
        << vertex_bytes << " " << theirs.bytes_fetched << "\n"
        << r.out;
    EXPECT_NE(r.out.find("# vertex_bytes: " + std::to_string(vertex_bytes)), std::string::npos) << r.out;
  }
  // 32-byte vertices: 213,120 bytes, overfetch 1.029 (file order).
  const testing::CommandRun r = testing::run_rastrace(
      {"vcache", testing::data_file("meshes/fandisk.off"), "--algo", "original", "--cache", "entries=16", "--no-time"});
  EXPECT_NE(r.out.find("| 213120 | 1.029 |"), std::string::npos) << r.out;
}

TEST(VcacheFetchCli, AnotherFetchCacheAndBadValues) {
  // A 1 KiB fully associative LRU cache of 64-byte lines holds 16 lines: a random order refetches.
  const testing::CommandRun r =
      testing::run_rastrace({"vcache", "grid:16x16", "--algo", "scanline,random", "--cache", "entries=16", "--fetch",
                             "size=1KiB,line=64B,assoc=full", "--format", "csv", "--no-time"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("# fetch_cache: size=1KiB,line=64B,assoc=full,policy=lru"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(",17024,1.840830450\n"), std::string::npos) << r.out;  // scanline
  EXPECT_NE(r.out.find(",73152,7.910034602\n"), std::string::npos) << r.out;  // random
  EXPECT_EQ(testing::run_rastrace({"vcache", "grid:4x4", "--vertex-bytes", "0"}).exit_code, 1);
  const testing::CommandRun bad = testing::run_rastrace({"vcache", "grid:4x4", "--fetch", "entries=16"});
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.err.find("--fetch 'entries=16'"), std::string::npos) << bad.err;
}

}  // namespace
}  // namespace rastrace

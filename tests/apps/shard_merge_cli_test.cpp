// `sweep --shard K/N -o PART.json` and `rastrace merge`: the merged parts print exactly what the
// unsharded sweep prints, in every format, for byte caches and vertex caches; parts that do not
// belong together are refused with the reason.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "tests/support/run_rastrace.h"
#include "tests/support/temp_dir.h"

namespace rastrace {
namespace {

using ::testing::HasSubstr;
using testing::run_rastrace;

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

class ShardMerge : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new testing::TempDir;
    for (const char* order : {"original", "tipsy"}) {
      const auto r = run_rastrace({"render", "builtin:grid", "--size", "128x128", "--order", order, "-o",
                                   dir_->file(std::string(order) + ".png"), "--trace", trace(order)});
      ASSERT_EQ(r.exit_code, 0) << r.err;
    }
  }
  static void TearDownTestSuite() { delete dir_; }
  static std::string trace(const std::string& order) { return dir_->file(order + ".rtrace"); }

  // Writes shards 1..n of the sweep and returns their paths.
  static std::vector<std::string> write_parts(const std::string& trace_path, const std::string& cache, int n,
                                              const std::string& prefix) {
    std::vector<std::string> paths;
    for (int k = 1; k <= n; ++k) {
      paths.push_back(dir_->file(prefix + "-" + std::to_string(k) + ".json"));
      const auto r = run_rastrace({"sweep", trace_path, "--cache", cache, "--shard",
                                   std::to_string(k) + "/" + std::to_string(n), "-o", paths.back()});
      EXPECT_EQ(r.exit_code, 0) << r.err;
    }
    return paths;
  }

  static void expect_merge_equals_sweep(const std::string& cache, int shards, const std::string& prefix) {
    // Parts given out of order: the merge puts the rows back where the sweep has them.
    std::vector<std::string> parts = write_parts(trace("original"), cache, shards, prefix);
    std::reverse(parts.begin(), parts.end());
    for (const char* format : {"md", "csv", "latex", "json"}) {
      const auto whole = run_rastrace({"sweep", trace("original"), "--cache", cache, "--format", format});
      ASSERT_EQ(whole.exit_code, 0) << whole.err;
      std::vector<std::string> merge = {"merge"};
      merge.insert(merge.end(), parts.begin(), parts.end());
      merge.insert(merge.end(), {"--format", format});
      const auto merged = run_rastrace(merge);
      ASSERT_EQ(merged.exit_code, 0) << merged.err;
      EXPECT_EQ(merged.out, whole.out) << cache << " " << format;
      // The same impossible combinations are reported, by the merge instead of the sweep.
      EXPECT_EQ(count(merged.err, "rastrace merge: skipped"), count(whole.err, "rastrace sweep: skipped")) << format;
    }
  }

  static testing::TempDir* dir_;
};
testing::TempDir* ShardMerge::dir_ = nullptr;

TEST_F(ShardMerge, ByteCacheSweepMergesToTheUnshardedOutputInEveryFormat) {
  // 64 B with 4 ways of 64 B lines is impossible: skipped by the shard that owns it.
  expect_merge_equals_sweep("size=64B..16KiB,assoc=4/full,policy=fifo/lru/random", 3, "bytes");
}

TEST_F(ShardMerge, VertexCacheSweepMergesToTheUnshardedOutput) {
  expect_merge_equals_sweep("entries=4..64,policy=fifo/lru", 4, "vertex");
}

TEST_F(ShardMerge, MoreShardsThanConfigurationsStillMerge) { expect_merge_equals_sweep("size=4KiB/8KiB", 5, "sparse"); }

TEST_F(ShardMerge, SampledSweepMergesToTheUnshardedOutputThoughShardsStateDifferentMethods) {
  // A trace long enough to be sampled (1.57 M texel records x 48 configurations > 64 Mi). The size
  // varies fastest, so shard 1/2 holds every 2 KiB row (under 32 sampled lines at 10%: simulated,
  // `method: exact`) and shard 2/2 every 1 MiB row (`sampled`); the merge states
  // `sampled+exact-rows` like the unsharded sweep. The exact-sweep guard counts the whole sweep's
  // configurations, so each shard decides every row as the unsharded sweep does.
  const std::string bunny = dir_->file("bunny.rtrace");
  const auto rendered = run_rastrace({"render", "builtin:bunny", "--size", "1024x1024", "-o", dir_->file("bunny.png"),
                                      "--trace", bunny});
  ASSERT_EQ(rendered.exit_code, 0) << rendered.err;
  const std::string cache = "size=2KiB/1MiB,line=32B/64B/128B,assoc=4/8/16/full,policy=lru/fifo";
  std::vector<std::string> parts;
  for (int k = 1; k <= 2; ++k) {
    parts.push_back(dir_->file("sampled-" + std::to_string(k) + ".json"));
    const auto r = run_rastrace({"sweep", bunny, "--cache", cache, "--sample", "0.1", "--shard",
                                 std::to_string(k) + "/2", "-o", parts.back()});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::ifstream in(parts.back());
    const auto part = nlohmann::json::parse(in);
    std::string method;
    for (const auto& parameter : part["table"]["parameters"])
      if (parameter[0] == "method") method = parameter[1];
    EXPECT_EQ(method, k == 1 ? "exact" : "sampled") << k;
  }
  for (const char* format : {"md", "json"}) {
    const auto whole = run_rastrace({"sweep", bunny, "--cache", cache, "--sample", "0.1", "--format", format});
    ASSERT_EQ(whole.exit_code, 0) << whole.err;
    EXPECT_THAT(whole.out, HasSubstr("sampled+exact-rows"));
    std::vector<std::string> merge = {"merge"};
    merge.insert(merge.end(), parts.begin(), parts.end());
    merge.insert(merge.end(), {"--format", format});
    const auto merged = run_rastrace(merge);
    ASSERT_EQ(merged.exit_code, 0) << merged.err;
    EXPECT_EQ(merged.out, whole.out) << format;
  }
}

TEST_F(ShardMerge, PartsThatDoNotBelongTogetherAreRefused) {
  const std::string cache = "size=1KiB..8KiB";
  const auto a = write_parts(trace("original"), cache, 2, "a");
  const auto other_trace = write_parts(trace("tipsy"), cache, 2, "t");
  const auto other_set = write_parts(trace("original"), "size=1KiB..16KiB", 2, "s");
  const auto other_count = write_parts(trace("original"), cache, 3, "n");

  auto r = run_rastrace({"merge", a[0], other_trace[1]});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("trace digest"));
  r = run_rastrace({"merge", a[0], other_set[1]});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("configuration cache=size=1KiB..16KiB"));
  r = run_rastrace({"merge", a[0], other_count[1]});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("shard count 3"));
  r = run_rastrace({"merge", a[0], a[0]});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("are both shard 1/2"));
  r = run_rastrace({"merge", a[0]});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("shards 2 of 2 are missing"));

  // Another version's part.
  std::ifstream in(a[1]);
  std::stringstream text;
  text << in.rdbuf();
  std::string edited = text.str();
  const std::size_t at = edited.find("\"version\": \"");
  ASSERT_NE(at, std::string::npos);
  edited.insert(at + 12, "9.");
  const std::string old_version = dir_->write("old-version.json", edited);
  r = run_rastrace({"merge", a[0], old_version});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("has version 9."));

  const std::string broken = dir_->write("broken.json", edited.substr(0, edited.size() / 2));
  r = run_rastrace({"merge", a[0], broken});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("broken.json"));
  EXPECT_THAT(r.err, HasSubstr("not a sweep part"));
}

TEST_F(ShardMerge, BadShardsAreUsageErrorsNamingTheFlag) {
  for (const char* shard : {"0/4", "5/4", "4", "1/0", "a/b", "1/70000", "-1/4"}) {
    const auto r = run_rastrace({"sweep", trace("original"), "--shard", shard});
    EXPECT_EQ(r.exit_code, 1) << shard;
    EXPECT_THAT(r.err, HasSubstr("--shard '")) << shard;
  }
}

}  // namespace
}  // namespace rastrace

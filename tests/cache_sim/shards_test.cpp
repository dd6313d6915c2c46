// Sampled miss-ratio curves (cache_sim/shards.h): at rate 1 every estimator is the exact
// simulation; at a low rate on a rendered frame the SHARDS curve stays within a stated error of the
// exact one; `sweep --sample` states its sampling and each row's expected error.
#include <cmath>
#include <random>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cache_sim/byte_cache.h"
#include "cache_sim/shards.h"
#include "cache_sim/texture_layout.h"
#include "core/error.h"
#include "support/run_rastrace.h"
#include "support/temp_dir.h"
#include "tests/support/synthetic_frame.h"
#include "traces/trace_reader.h"

namespace rastrace {
namespace {

using ::testing::HasSubstr;

std::vector<std::uint64_t> frame_lines(std::uint32_t size, std::uint32_t line_bytes) {
  const testing::SyntheticFrame frame = testing::make_synthetic_frame(size, size, 1024);
  const TextureLayout layout(parse_layout("block4"), frame.textures);
  std::vector<std::uint64_t> lines;
  for (const TexelAccess& t : frame.texels) lines.push_back(layout.address(t.texture, t.level, t.x, t.y) / line_bytes);
  return lines;
}

std::vector<std::uint64_t> cache_sizes() {
  std::vector<std::uint64_t> sizes;
  for (std::uint64_t lines = 1; lines <= (1u << 16); lines *= 2) {
    sizes.push_back(lines);
    sizes.push_back(lines * 3 / 2 + 1);
  }
  return sizes;
}

TEST(Shards, FixedRateOneEqualsTheExactLruCurveAtEverySize) {
  const auto lines = frame_lines(256, 64);
  LruStackProfile exact;
  exact.access_lines(lines);
  ShardsProfile shards({1.0, 0});
  shards.access_lines(lines);
  EXPECT_EQ(shards.rate(), 1.0);
  for (const std::uint64_t c : cache_sizes())
    ASSERT_EQ(shards.miss_ratio(c), double(exact.misses(c)) / double(exact.accesses())) << c << " lines";
}

TEST(Shards, FixedSizeThatHoldsEveryLineAtRateOneIsExactToo) {
  const auto lines = frame_lines(128, 64);
  LruStackProfile exact;
  exact.access_lines(lines);
  ShardsProfile shards({1.0, 1u << 20});
  shards.access_lines(lines);
  for (const std::uint64_t c : cache_sizes())
    ASSERT_DOUBLE_EQ(shards.miss_ratio(c), double(exact.misses(c)) / double(exact.accesses())) << c << " lines";
}

TEST(Shards, FixedSizeKeepsItsLineBudgetAndLowersItsRate) {
  const auto lines = frame_lines(256, 64);
  ShardsProfile shards({1.0, 512});
  shards.access_lines(lines);
  LruStackProfile exact;
  exact.access_lines(lines);
  EXPECT_LE(shards.tracked_lines(), 512u);
  // The threshold ends at the 513th smallest hash of the lines: a rate of about 512 / lines.
  EXPECT_NEAR(shards.rate() * double(exact.distinct_lines()), 512.0, 100.0);
  double error = 0;
  for (std::uint64_t c = 64; c <= 8192; c *= 2)
    error += std::abs(shards.miss_ratio(c) - double(exact.misses(c)) / double(exact.accesses()));
  EXPECT_LT(error / 8, 0.02);
}

TEST(Shards, MiniSimulationsAtRateOneAreTheCachesThemselves) {
  const auto lines = frame_lines(128, 32);
  std::vector<CacheConfig> caches;
  for (const ReplacementPolicy policy : {ReplacementPolicy::Fifo, ReplacementPolicy::Random, ReplacementPolicy::Lru})
    for (const std::uint32_t assoc : {0u, 1u, 4u}) caches.push_back({8 * 1024, 32, assoc, policy, 3});
  MiniSimulations minis(caches, 1.0);
  minis.access_lines(lines);
  for (std::size_t i = 0; i < caches.size(); ++i) {
    ByteCache exact(caches[i]);
    exact.access_lines(lines);
    EXPECT_EQ(minis.miss_ratio(i), exact.stats().miss_rate()) << describe(caches[i]);
  }
}

TEST(Shards, ASampledBatchKeepsExactlyTheLinesWhoseHashIsBelowTheThresholdInOrder) {
  // Batches of changing sizes (the buffers grow and are reused), odd lengths for the vector
  // clone's tail, random lines and a rendered frame's.
  std::mt19937_64 random(7);
  std::vector<std::uint64_t> lines = frame_lines(128, 64);
  for (int i = 0; i < 5000; ++i) lines.push_back(random());
  for (const double rate : {0.01, 0.3, 1.0}) {
    SampledBatch batch(rate);
    const std::uint64_t threshold = sample_threshold(rate);
    std::size_t kept_total = 0;
    for (std::size_t begin = 0, n = 1; begin < lines.size(); begin += n, n = n * 3 % 9973 + 1) {
      const std::span<const std::uint64_t> part(lines.data() + begin, std::min(n, lines.size() - begin));
      batch.sample(part);
      std::vector<std::uint64_t> expected;
      for (const std::uint64_t line : part)
        if (rate >= 1.0 || sample_hash(line) < threshold) expected.push_back(line);
      ASSERT_EQ(batch.accesses(), part.size());
      ASSERT_EQ(std::vector<std::uint64_t>(batch.lines().begin(), batch.lines().end()), expected) << rate;
      for (std::size_t i = 0; i < expected.size(); ++i) ASSERT_EQ(batch.hashes()[i], sample_hash(expected[i]));
      kept_total += expected.size();
    }
    if (rate == 1.0) {
      EXPECT_EQ(kept_total, lines.size());
    }
    if (rate == 0.01) {
      EXPECT_LT(kept_total, lines.size() / 20);
    }
  }
}

TEST(Shards, OneBatchSampledAtAHigherRateFeedsEveryEstimatorAsItsOwnSamplingWould) {
  const auto lines = frame_lines(256, 64);
  std::vector<CacheConfig> caches;
  for (const ReplacementPolicy policy : {ReplacementPolicy::Fifo, ReplacementPolicy::Random})
    for (const std::uint32_t assoc : {0u, 4u}) caches.push_back({64 * 1024, 64, assoc, policy, 5});
  ShardsProfile own({0.05, 0}), shared({0.05, 0}), own_fixed({0.5, 256}), shared_fixed({0.5, 256});
  MiniSimulations own_minis(caches, 0.05), shared_minis(caches, 0.05);
  SampledBatch at_rate(0.05), higher(0.5);
  for (std::size_t begin = 0; begin < lines.size(); begin += 4096) {
    const std::span<const std::uint64_t> part(lines.data() + begin, std::min<std::size_t>(4096, lines.size() - begin));
    own.access_lines(part);
    own_fixed.access_lines(part);
    own_minis.access_lines(part);
    at_rate.sample(part);
    higher.sample(part);
    shared.access_sampled(higher);
    shared_fixed.access_sampled(higher);
    shared_minis.access_sampled(at_rate);
  }
  EXPECT_EQ(shared.accesses(), lines.size());
  for (const std::uint64_t c : cache_sizes()) {
    ASSERT_EQ(shared.miss_ratio(c), own.miss_ratio(c)) << c;
    ASSERT_EQ(shared.expected_error(c), own.expected_error(c)) << c;
    ASSERT_EQ(shared_fixed.miss_ratio(c), own_fixed.miss_ratio(c)) << c;
  }
  EXPECT_EQ(shared_fixed.rate(), own_fixed.rate());
  for (std::size_t i = 0; i < caches.size(); ++i) {
    ASSERT_EQ(shared_minis.miss_ratio(i), own_minis.miss_ratio(i)) << describe(caches[i]);
    ASSERT_EQ(shared_minis.expected_error(i), own_minis.expected_error(i)) << describe(caches[i]);
  }
  // A batch sampled more thinly than an estimator would miss lines it must see.
  SampledBatch thinner(0.01);
  thinner.sample(lines);
  EXPECT_THROW(shared.access_sampled(thinner), std::invalid_argument);
  EXPECT_THROW(shared_minis.access_sampled(thinner), std::invalid_argument);
}

TEST(Shards, ScaledCachesKeepWaysAndScaleSetsOrLines) {
  // 256 sets of 4 ways at 1%: 2.56 -> 3 sets; 1024 lines fully associative: 10.24 -> 10 lines.
  EXPECT_EQ(scale_cache({64 * 1024, 64, 4, ReplacementPolicy::Fifo, 1}, 0.01).size_bytes, 3u * 4 * 64);
  EXPECT_EQ(scale_cache({64 * 1024, 64, 0, ReplacementPolicy::Fifo, 1}, 0.01).size_bytes, 10u * 64);
  EXPECT_EQ(scale_cache({1024, 64, 0, ReplacementPolicy::Fifo, 1}, 0.01).size_bytes, 64u);  // at least one line
}

TEST(Shards, SampleSpecsParseAndBadOnesNameTheOption) {
  EXPECT_EQ(parse_sample_spec("1%", "--sample").rate, 0.01);
  EXPECT_EQ(parse_sample_spec("0.001", "--sample").rate, 0.001);
  const SampleSpec fixed = parse_sample_spec("0.5,max=8192", "--sample");
  EXPECT_EQ(fixed.max_lines, 8192u);
  for (const char* bad : {"0", "1.5", "abc", "%", "1%,max=1", "1%,lines=4", "-0.1"}) {
    try {
      parse_sample_spec(bad, "--sample");
      ADD_FAILURE() << bad;
    } catch (const InputError& e) {
      EXPECT_THAT(e.what(), HasSubstr("--sample")) << bad;
    }
  }
}

// A rendered bunny frame's trace, rendered once per process (its folder goes at exit).
const std::string& rendered_bunny_trace() {
  static const testing::TempDir dir;
  static const std::string trace = [] {
    const std::string path = dir.file("bunny.rtrace");
    const testing::CommandRun r = testing::run_rastrace(
        {"render", "builtin:bunny", "-o", dir.file("bunny.png"), "--trace", path, "--size", "512x512"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return path;
  }();
  return trace;
}

// Its texel lines (block4, 64-byte lines).
std::vector<std::uint64_t> rendered_bunny_lines() {
  std::vector<std::uint64_t> out;
  TexelTraceReader reader(rendered_bunny_trace());
  const TextureLayout layout(parse_layout("block4"), reader.metadata().textures);
  std::span<const TexelAccess> batch;
  while (reader.next(batch))
    for (const TexelAccess& t : batch) out.push_back(layout.address(t.texture, t.level, t.x, t.y) / 64);
  return out;
}

TEST(Shards, OnARenderedFrameTheTenPercentCurveIsWithinItsStatedErrorOfTheExactOne) {
  const auto lines = rendered_bunny_lines();
  ASSERT_GT(lines.size(), 300000u);
  LruStackProfile exact;
  exact.access_lines(lines);
  ShardsProfile shards({0.1, 0});
  shards.access_lines(lines);
  // Sizes 1 KiB .. 1 MiB of 64-byte lines, where the frame's curve falls from its top to its floor.
  double error = 0;
  int sizes = 0;
  for (std::uint64_t c = 16; c <= 16384; c *= 2, ++sizes)
    error += std::abs(shards.miss_ratio(c) - double(exact.misses(c)) / double(exact.accesses()));
  EXPECT_LT(error / sizes, 0.01);  // the bound this test states: mean absolute error under 0.01 at 10%
}

TEST(SweepSample, TheTableStatesTheSamplingAndEachRowsEstimateAndExpectedError) {
  const std::string& trace = rendered_bunny_trace();
  testing::CommandRun r = testing::run_rastrace({"sweep", trace, "--cache", "size=4KiB/64KiB,assoc=full/4,policy=lru/fifo", "--sample",
                             "100%", "--format", "json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const testing::CommandRun exact = testing::run_rastrace(
      {"sweep", trace, "--cache", "size=4KiB/64KiB,assoc=full/4,policy=lru/fifo", "--format", "json"});
  ASSERT_EQ(exact.exit_code, 0) << exact.err;
  const nlohmann::json rows = nlohmann::json::parse(r.out), exact_rows = nlohmann::json::parse(exact.out);
  ASSERT_EQ(rows.size(), 8u);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    EXPECT_THAT(rows[i].at("sampling").get<std::string>(), HasSubstr("fixed rate 1 of the lines by spatial hash"));
    // A trace this short is simulated exactly (SampleGuards::exact_accesses), which the rows say.
    EXPECT_EQ(rows[i].at("estimated_by"), "exact");
    EXPECT_EQ(rows[i].at("method"), "exact");
    EXPECT_EQ(rows[i].at("expected_error").get<double>(), 0.0);
    // At rate 1 the estimate is the simulation itself.
    EXPECT_EQ(rows[i].at("misses"), exact_rows[i].at("misses")) << i;
  }
  r = testing::run_rastrace({"sweep", trace, "--cache", "size=4KiB,policy=fifo", "--sample", "1%,max=4096"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("fixed-size sampling gives fully associative LRU only"));
}

}  // namespace
}  // namespace rastrace

// A sampled sweep (sweep --sample, cache_sim/sampled_sweep.h) never states less error than it
// has: on rendered traces of one frame and of many frames, every row's stated error is at least
// its measured distance from the exact sweep; a short trace is simulated exactly, and rows whose
// scaled cache holds under a few sampled lines are simulated exactly.
#include <cstdio>
#include <cmath>
#include <filesystem>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cache_sim/cache_spec.h"
#include "cache_sim/sweep.h"
#include "support/run_rastrace.h"
#include "support/temp_dir.h"

namespace rastrace {
namespace {

// A trace rendered once per process (its folder goes at exit).
std::string render_trace(const testing::TempDir& dir, const std::string& name, std::vector<std::string> args) {
  const std::string path = dir.file(name + ".rtrace");
  args.insert(args.begin(), "render");
  for (const std::string& more : {std::string("-o"), dir.file(name + ".png"), std::string("--trace"), path})
    args.push_back(more);
  const testing::CommandRun r = testing::run_rastrace(args);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return path;
}

const testing::TempDir& trace_dir() {
  static const testing::TempDir dir;
  return dir;
}

// One 256x256 spider frame (about 55,000 texel accesses).
const std::string& one_frame_trace() {
  static const std::string trace = render_trace(trace_dir(), "spider", {"builtin:spider", "--size", "256x256"});
  return trace;
}

// Eight 256x256 frames along the orbit of docs/orbit_scene.json, caches kept between frames.
const std::string& many_frames_trace() {
  static const std::string trace = render_trace(
      trace_dir(), "orbit",
      {(std::filesystem::path(RASTRACE_TEST_FILES_DIR).parent_path() / "docs" / "orbit_scene.json").string(), "--size",
       "256x256", "--frames", "8"});
  return trace;
}

SweepSpec spec_of(const std::string& cache) { return sweep_spec(parse_cache_spec(cache, "--cache"), SweepSource::Texel); }

struct Comparison {
  SweepResult sampled, exact;
  double mean_error = 0;     // mean |sampled - exact| miss rate over the rows
  double worst_excess = 0;   // the largest measured - stated (<= 0: never stated below measured)
  double mean_stated = 0;    // over the sampled rows
  int sampled_rows = 0, exceeded_rows = 0;
};

Comparison compare(const std::string& trace, const std::string& cache, SampleSpec sample, SampleGuards guards) {
  SweepSpec spec = spec_of(cache);
  Comparison c;
  c.exact = run_sweep(trace, spec, 2, false);
  spec.sample = sample;
  spec.sample_guards = guards;
  c.sampled = run_sweep(trace, spec, 2, false);
  EXPECT_EQ(c.sampled.rows.size(), c.exact.rows.size());
  c.worst_excess = -1;
  for (std::size_t i = 0; i < c.exact.rows.size(); ++i) {
    const SweepRow& s = c.sampled.rows[i];
    const double measured = std::abs(s.stats.miss_rate() - c.exact.rows[i].stats.miss_rate());
    c.mean_error += measured / double(c.exact.rows.size());
    c.worst_excess = std::max(c.worst_excess, measured - s.expected_error);
    if (s.sampled_as != "exact") {
      ++c.sampled_rows;
      c.mean_stated += s.expected_error;
      c.exceeded_rows += measured > s.expected_error;
    }
  }
  if (c.sampled_rows) c.mean_stated /= c.sampled_rows;
  std::printf("%d sampled rows: mean error %.5f, mean stated %.5f, %d exceeded, worst excess %.5f\n", c.sampled_rows,
              c.mean_error, c.mean_stated, c.exceeded_rows, c.worst_excess);
  return c;
}

constexpr const char* kCaches = "size=1KiB..256KiB,assoc=full/4,policy=lru/fifo";

TEST(SampledErrorBound, AOneFrameTraceIsSimulatedExactlyAndStatesNoError) {
  // 36 rows x the frame's texel accesses are far under the 64 Mi accesses of the default guard.
  const Comparison c = compare(one_frame_trace(), kCaches, {0.01, 0}, SampleGuards{});
  EXPECT_STREQ(sweep_method(c.sampled.rows), "exact");
  for (std::size_t i = 0; i < c.exact.rows.size(); ++i) {
    EXPECT_EQ(c.sampled.rows[i].sampled_as, "exact");
    EXPECT_EQ(c.sampled.rows[i].expected_error, 0.0);
    EXPECT_EQ(c.sampled.rows[i].stats.misses, c.exact.rows[i].stats.misses) << i;
  }
  EXPECT_EQ(c.mean_error, 0.0);
}

TEST(SampledErrorBound, ManyFramesSimulateTheSmallScaledCachesAndStateTheRest) {
  for (const double rate : {0.01, 0.1}) {
    const Comparison c = compare(many_frames_trace(), kCaches, {rate, 0}, SampleGuards{});
    EXPECT_STREQ(sweep_method(c.sampled.rows), "sampled+exact-rows");
    for (const SweepRow& row : c.sampled.rows) {
      const bool small = double(row.cache.lines()) * rate < 32;
      EXPECT_EQ(row.sampled_as == "exact", small) << describe(row.cache);
    }
    // Measured on this trace: the mean error to 3 decimals, and no sampled row measures more than
    // it states (the guards' rows state 0 and measure 0). The stated errors stay useful: 0.006 on
    // average at 1%, 0.012 at 10%.
    EXPECT_NEAR(c.mean_error, rate == 0.01 ? 0.000 : 0.001, 0.0005) << rate;
    EXPECT_EQ(c.exceeded_rows, 0) << rate;
    EXPECT_LE(c.worst_excess, 0.0) << rate;
    EXPECT_EQ(c.sampled_rows, rate == 0.01 ? 4 : 16);
    EXPECT_LT(c.mean_stated, 0.02) << rate;
  }
}

TEST(SampledErrorBound, DirectMappedAndTwoWayRowsAreSimulatedExactly) {
  // Hash sampling does not keep which lines share a set: a scaled 1- or 2-way cache sees
  // conflicts the full one does not, which the part samples share, so those rows run exactly.
  const Comparison c = compare(many_frames_trace(), "size=16KiB..256KiB,assoc=1/2/4/8,policy=lru/fifo", {0.1, 0},
                               SampleGuards{});
  EXPECT_STREQ(sweep_method(c.sampled.rows), "sampled+exact-rows");
  for (std::size_t i = 0; i < c.exact.rows.size(); ++i) {
    const SweepRow& row = c.sampled.rows[i];
    EXPECT_EQ(row.sampled_as == "exact", row.cache.assoc < 4 || double(row.cache.lines()) * 0.1 < 32)
        << describe(row.cache);
    if (row.sampled_as == "exact") {
      EXPECT_EQ(row.stats.misses, c.exact.rows[i].stats.misses) << describe(row.cache);
    }
  }
  EXPECT_EQ(c.sampled_rows, 16);
  EXPECT_EQ(c.exceeded_rows, 0);
}

TEST(SampledErrorBound, WithoutTheGuardsTheSmallScaledCachesStateLessThanTheyHave) {
  // Every row sampled at 1%, scaled caches down to one line: the bias of a scaled cache of a few
  // lines is not the parts' spread, and 2 of 36 rows measure more than they state.
  const Comparison c = compare(many_frames_trace(), kCaches, {0.01, 0}, {0, 0, 0});
  EXPECT_STREQ(sweep_method(c.sampled.rows), "sampled");
  EXPECT_NEAR(c.mean_error, 0.024, 0.0005);
  EXPECT_EQ(c.exceeded_rows, 2);
  EXPECT_NEAR(c.worst_excess, 0.032, 0.0005);
}

}  // namespace
}  // namespace rastrace

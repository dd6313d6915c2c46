// `rastrace vipm` through the built binary: JSON output with its keys, bad method names, bad caches.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/run_rastrace.h"

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

}  // namespace
}  // namespace rastrace

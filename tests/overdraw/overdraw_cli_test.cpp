// `rastrace overdraw`: the rows a user asks for with the keys the issue names (algo, overdraw,
// acmr), meshoptimizer's figure beside ours, byte-identical outputs with --no-time, and bad input
// as exit code 1 with a message naming the option.
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/run_rastrace.h"
#include "support/test_data.h"

namespace {

using Result = rastrace::testing::CommandRun;
Result run(const std::vector<std::string>& arguments) { return rastrace::testing::run_rastrace(arguments); }

TEST(OverdrawCli, JsonRowsCarryAlgoOverdrawAndAcmr) {
  const std::vector<std::string> args = {"overdraw", rastrace::testing::data_file("meshes/fandisk.off"), "--algo",
                                         "tipsy,tipsy-overdraw", "--format", "json", "--no-time"};
  const Result a = run(args), b = run(args);
  ASSERT_EQ(a.exit_code, 0) << a.err;
  EXPECT_EQ(a.out, b.out);
  const nlohmann::json rows = nlohmann::json::parse(a.out);
  ASSERT_EQ(rows.size(), 4u);  // two orderings, then meshopt-overdraw and meshopt-full
  EXPECT_EQ(rows[0]["algo"], "tipsy");
  EXPECT_EQ(rows[1]["algo"], "tipsy-overdraw");
  EXPECT_EQ(rows[2]["algo"], "meshopt-overdraw");
  EXPECT_NEAR(rows[0]["acmr"].get<double>(), 0.6525, 0.0001);
  EXPECT_NEAR(rows[0]["overdraw"].get<double>(), 1.0116, 0.0001);
  EXPECT_NEAR(rows[1]["acmr"].get<double>(), 0.6828, 0.0001);
  EXPECT_NEAR(rows[1]["overdraw"].get<double>(), 1.0080, 0.0001);
  EXPECT_LT(rows[1]["overdraw"].get<double>(), rows[0]["overdraw"].get<double>());
  EXPECT_TRUE(rows[0].contains("overdraw_meshopt"));
}

TEST(OverdrawCli, Meshopt018RulesPrintMeshoptimizersOwnFigure) {
  const Result r = run({"overdraw", rastrace::testing::data_file("meshes/fandisk.off"), "--algo", "tipsy", "--rules",
                        "meshopt-0.18", "--no-peer", "--format", "json", "--no-time"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json rows = nlohmann::json::parse(r.out);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0]["shaded"], 166168);
  EXPECT_EQ(rows[0]["covered"], 164332);
  EXPECT_EQ(rows[0]["overdraw"], rows[0]["overdraw_meshopt"]);
}

TEST(OverdrawCli, BadInputIsExitCode1NamingTheOption) {
  const std::string mesh = "grid:4x4";
  Result r = run({"overdraw", mesh, "--view", "0,0"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("--view '0,0'"), std::string::npos) << r.err;
  r = run({"overdraw", mesh, "--algo", "front-to-back", "--view", "0,0,0"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("--view"), std::string::npos) << r.err;
  r = run({"overdraw", mesh, "--algo", "tipsy-overdraw", "--lambda", "0"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("--lambda"), std::string::npos) << r.err;
  r = run({"overdraw", mesh, "--rules", "meshopt-0.18", "--resolution", "128"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("--resolution 256"), std::string::npos) << r.err;
}

}  // namespace

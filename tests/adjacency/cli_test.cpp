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

TEST(AdjacencyCommand, JsonRowsCarryCoverBoundCacheMissesAndGain) {
  const std::string mesh = testing::data_file("meshes/triceratops.off");
  const testing::TempDir dir;
  const std::string output = dir.file("careful.txt");
  const CommandRun r = run({"adjacency", mesh, "--format", "json", "--no-time", "-o", output});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json rows = nlohmann::json::parse(r.out);
  ASSERT_EQ(rows.size(), 5u);
  const char* orders[] = {"careful", "fast", "baseline", "baseline-mesh", "naive"};
  for (std::size_t i = 0; i < 5; ++i) {
    const auto& row = rows[i];
    EXPECT_EQ(row.at("order"), orders[i]);
    EXPECT_EQ(row.at("faces"), 5660);
    EXPECT_EQ(row.at("cover"), 3125);
    EXPECT_NEAR(row.at("lower_bound").get<double>(), (8490.0 + 637.0) / 3.0, 1e-9);
    EXPECT_NEAR(row.at("c_over_b").get<double>(), 3125.0 / ((8490.0 + 637.0) / 3.0), 1e-9);
    EXPECT_EQ(row.at("cache"), 24);
  }
  EXPECT_EQ(rows[0].at("primitives"), 3125);
  EXPECT_EQ(rows[4].at("primitives"), 5660);
  EXPECT_NEAR(rows[0].at("cm_per_v").get<double>(), 1.442, 0.0005);
  EXPECT_NEAR(rows[1].at("cm_per_v").get<double>(), 1.680, 0.0005);
  EXPECT_NEAR(rows[2].at("cm_per_v").get<double>(), 2.458, 0.0005);
  EXPECT_NEAR(rows[3].at("cm_per_v").get<double>(), 2.785, 0.0005);
  EXPECT_DOUBLE_EQ(rows[2].at("gain").get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(rows[3].at("gain_mesh").get<double>(), 1.0);
  EXPECT_NEAR(rows[0].at("gain").get<double>(), 6962.0 / 4084.0, 1e-9);       // misses of baseline / careful
  EXPECT_NEAR(rows[0].at("gain_mesh").get<double>(), 7886.0 / 4084.0, 1e-9);  // baseline-mesh / careful
  EXPECT_DOUBLE_EQ(rows[4].at("gain_naive").get<double>(), 1.0);
  EXPECT_NEAR(rows[0].at("gain_naive").get<double>(), 10865.0 / 4084.0, 1e-9);  // naive / careful
  EXPECT_NEAR(rows[0].at("gain_naive").get<double>(), 2.660, 0.0005);
  EXPECT_NEAR(rows[2].at("gain_naive").get<double>(), 1.561, 0.0005);  // even the baseline beats one per face
  EXPECT_LT(rows[4].at("gain").get<double>(), 1.0);  // one primitive per face is worse than both baselines
  EXPECT_LT(rows[4].at("gain_mesh").get<double>(), 1.0);

  // -o: the careful index buffer, one primitive per line after the header.
  std::ifstream in(output);
  std::string line;
  std::size_t lines = 0;
  std::getline(in, line);
  EXPECT_EQ(line.rfind("# GL_TRIANGLES_ADJACENCY", 0), 0u) << line;
  while (std::getline(in, line)) ++lines;
  EXPECT_EQ(lines, 3125u);
}

TEST(AdjacencyCommand, EdgeStageCountsEveryFaceAndEdgeOnceAndWritesTheLines) {
  const std::string mesh = testing::data_file("meshes/triceratops.off");
  const testing::TempDir dir;
  const std::string image = dir.file("lines.png");
  const CommandRun r = run({"adjacency", mesh, "--order", "careful", "--edges", "--size", "256", "--lines", image,
                            "--format", "json", "--no-time"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json rows = nlohmann::json::parse(r.out);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].at("faces_processed"), 5660);
  EXPECT_EQ(rows[0].at("edges_processed"), 8490);
  EXPECT_EQ(rows[0].at("shader_invocations"), rows[0].at("misses"));  // the pipeline's cache = the simulation
  EXPECT_GT(rows[0].at("silhouette_edges").get<int>(), 100);
  EXPECT_GT(std::filesystem::file_size(image), 100u);
}

TEST(AdjacencyCommand, BadInputIsAnErrorWithExitCodeOne) {
  const std::string mesh = testing::data_file("meshes/triceratops.off");
  CommandRun r = run({"adjacency", mesh, "--order", "bogus"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("expected careful, fast, baseline, baseline-mesh or all"), std::string::npos) << r.err;
  r = run({"adjacency", mesh, "--cache", "entries=0"});
  EXPECT_EQ(r.exit_code, 1);
  r = run({"adjacency", mesh, "--cache", "24"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("--cache '24': write entries=24"), std::string::npos) << r.err;
  r = run({"adjacency", mesh, "--cache", "entries=24,policy=lru"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("write entries=24,policy=fifo"), std::string::npos) << r.err;
  EXPECT_EQ(r.exit_code, 1);
  r = run({"adjacency", "/nonexistent/mesh.off"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("/nonexistent/mesh.off"), std::string::npos) << r.err;
  r = run({"adjacency", mesh, "--format", "xml"});
  EXPECT_EQ(r.exit_code, 1);
}

TEST(AdjacencyCommand, MarkdownTableShowsEveryOrderingOnAGrid) {
  const CommandRun r = run({"adjacency", "grid:8x8", "--order", "fast", "--iterations", "100", "--no-time"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("| fast |"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("| careful |"), std::string::npos);
  EXPECT_NE(r.out.find("- cache: 24"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace rastrace

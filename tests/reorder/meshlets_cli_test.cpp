// `rastrace meshlets` as a user runs it: the table with meshoptimizer's peers as builders, the
// written meshlets (JSON and binary), and the errors.
#include <cstring>
#include <fstream>
#include <iterator>

#include <gtest/gtest.h>

#include "support/run_rastrace.h"
#include "support/temp_dir.h"
#include "support/test_data.h"

namespace rastrace {
namespace {

using testing::run_rastrace;

TEST(MeshletsCli, JsonRowsCarryEveryBuilderAndThePeers) {
  const std::string mesh = testing::data_file("meshes/triceratops.off");
  const testing::CommandRun r = run_rastrace({"meshlets", mesh, "--order", "original,tipsy", "--format", "json",
                                              "--no-time"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* builder : {"scan", "greedy", "spatial", "meshopt", "meshopt-scan"})
    EXPECT_NE(r.out.find(std::string("\"builder\": \"") + builder + "\""), std::string::npos) << builder << r.out;
  EXPECT_NE(r.out.find("\"meshlets\": "), std::string::npos);
  EXPECT_NE(r.out.find("\"vertices_per_triangle\": 0.66"), std::string::npos);
  EXPECT_NE(r.out.find("\"order\": \"tipsy\""), std::string::npos);
  EXPECT_EQ(r.out.find("\"seconds\""), std::string::npos);
  // Markdown rows: the greedy builder on the file order (vertices per triangle to three decimals).
  const testing::CommandRun md = run_rastrace({"meshlets", mesh, "--builder", "greedy,meshopt", "--no-time"});
  ASSERT_EQ(md.exit_code, 0) << md.err;
  EXPECT_NE(md.out.find("| original | greedy |"), std::string::npos) << md.out;
  EXPECT_NE(md.out.find("| 0.665 |"), std::string::npos) << md.out;
  EXPECT_NE(md.out.find("| 0.681 |"), std::string::npos) << md.out;
  // 126 triangles: meshoptimizer 0.18 cannot build them, so "all" leaves the peers out.
  const testing::CommandRun odd = run_rastrace({"meshlets", mesh, "--max-triangles", "126", "--format", "csv"});
  ASSERT_EQ(odd.exit_code, 0) << odd.err;
  EXPECT_NE(odd.out.find(",greedy,"), std::string::npos);
  EXPECT_EQ(odd.out.find(",meshopt,"), std::string::npos);
}

TEST(MeshletsCli, WritesTheMeshletsAsJsonAndBinary) {
  const testing::TempDir dir;
  const std::string mesh = testing::data_file("meshes/triceratops.off");
  const std::string json = dir.file("m.json"), binary = dir.file("m.bin");
  testing::CommandRun r = run_rastrace({"meshlets", mesh, "--builder", "greedy", "--max-triangles", "64", "--format",
                                        "csv", "--no-time", "-o", json});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream in(json);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text.rfind("{", 0), 0u);
  EXPECT_NE(text.find("\"format\":\"rastrace-meshlets\""), std::string::npos);
  EXPECT_NE(text.find("\"builder\":\"greedy\""), std::string::npos);
  EXPECT_NE(text.find("\"max_triangles\":64"), std::string::npos);
  r = run_rastrace({"meshlets", mesh, "--builder", "meshopt", "--no-time", "-o", binary});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream bin(binary, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(bin)), std::istreambuf_iterator<char>());
  ASSERT_GE(bytes.size(), 32u);
  EXPECT_EQ(std::memcmp(bytes.data(), "RTMSHLT\0", 8), 0);
  std::uint32_t header[6];
  std::memcpy(header, bytes.data() + 8, sizeof header);  // little-endian host (x86-64, AArch64)
  EXPECT_EQ(header[0], 1u);
  EXPECT_EQ(header[1], 64u);
  EXPECT_EQ(header[2], 124u);
  EXPECT_EQ(header[5], 5660u);  // every triangle
  EXPECT_EQ(bytes.size(), 32u + 16u * header[3] + 4u * header[4] + 3u * header[5]);
}

TEST(MeshletsCli, BadOptionsAreClearErrors) {
  const std::string mesh = testing::data_file("meshes/triceratops.off");
  testing::CommandRun r = run_rastrace({"meshlets", mesh, "--max-vertices", "300"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("--max-vertices 300"), std::string::npos) << r.err;
  r = run_rastrace({"meshlets", mesh, "--builder", "kmeans"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("--builder 'kmeans'"), std::string::npos) << r.err;
  r = run_rastrace({"meshlets", mesh, "--order", "nosuch"});
  EXPECT_EQ(r.exit_code, 1);
  const testing::TempDir dir;
  r = run_rastrace({"meshlets", mesh, "-o", dir.file("x.json")});  // several builders: which to write?
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("--builder NAME"), std::string::npos) << r.err;
  r = run_rastrace({"meshlets", mesh, "--builder", "meshopt", "--max-triangles", "126"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("multiple of 4"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace rastrace

// `rastrace info` and `rastrace convert` through the built binary: output, exit codes, help.
#include <filesystem>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/run_rastrace.h"
#include "tests/support/temp_dir.h"
#include "tests/support/test_data.h"

namespace rastrace {
namespace {

using testing::data_file;
using ::testing::HasSubstr;
using testing::run_rastrace;
using testing::TempDir;

TEST(InfoCommand, FandiskJsonReports6475VerticesAnd12946Faces) {
  const auto result = run_rastrace({"info", data_file("meshes/fandisk.off"), "--json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto json = nlohmann::json::parse(result.out);
  EXPECT_EQ(json["vertices"], 6475);
  EXPECT_EQ(json["faces"], 12946);
  EXPECT_EQ(json["boundary_edges"], 0);
  EXPECT_EQ(json["non_manifold_edges"], 0);
  EXPECT_EQ(json["connected_components"], 1);
  EXPECT_EQ(json["materials"], 0);
  EXPECT_EQ(json["textures"], 0);
  EXPECT_EQ(json["bounds"]["max"][2], 0.5);
  EXPECT_EQ(json["objects"].size(), 1u);
}

TEST(InfoCommand, BuiltinBunnyPrintsATableWithItsCounts) {
  const auto result = run_rastrace({"info", "builtin:bunny"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_THAT(result.out, HasSubstr("| 37706 | 75408 | 1 | 1 |"));
  EXPECT_THAT(result.out, HasSubstr("boundary edges"));
}

TEST(InfoCommand, MultiObjectSceneGivesTotalsAndPerObjectFigures) {
  const std::string example =
      (std::filesystem::path(__FILE__).parent_path().parent_path().parent_path() / "docs" / "example_scene.json")
          .string();
  const auto result = run_rastrace({"info", example, "--json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto json = nlohmann::json::parse(result.out);
  ASSERT_EQ(json["objects"].size(), 3u);
  EXPECT_EQ(json["objects"][1]["faces"], 75408);
  EXPECT_EQ(json["faces"], 128 + 75408 + 1280);
  EXPECT_EQ(json["vertices"], 81 + 37706 + 642);
  EXPECT_EQ(json["textures"], 3);
  EXPECT_EQ(json["boundary_edges"], 32);
  EXPECT_EQ(json["viewport"]["width"], 640);
  const auto text = run_rastrace({"info", example});
  EXPECT_THAT(text.out, HasSubstr("| total | 38429 | 76816 |"));
}

TEST(InfoCommand, SpiderObjReportsFiveMaterialsAndTextures) {
  const auto result = run_rastrace({"info", data_file("assimp/OBJ/spider.obj"), "--json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto json = nlohmann::json::parse(result.out);
  EXPECT_EQ(json["materials"], 5);
  EXPECT_EQ(json["textures"], 5);
  EXPECT_EQ(json["faces"], 1368);
}

TEST(ConvertCommand, OffToBinaryPlyToObjToOffGivesTheSameBytes) {
  TempDir dir;
  const std::string fandisk = data_file("meshes/fandisk.off");
  ASSERT_EQ(run_rastrace({"convert", fandisk, dir.file("direct.off")}).exit_code, 0);
  ASSERT_EQ(run_rastrace({"convert", fandisk, dir.file("a.ply")}).exit_code, 0);
  EXPECT_THAT(testing::slurp(dir.file("a.ply")), HasSubstr("format binary_little_endian 1.0"));
  ASSERT_EQ(run_rastrace({"convert", dir.file("a.ply"), dir.file("b.obj")}).exit_code, 0);
  const auto last = run_rastrace({"convert", dir.file("b.obj"), dir.file("c.off")});
  ASSERT_EQ(last.exit_code, 0) << last.err;
  EXPECT_THAT(last.out, HasSubstr("6475 vertices, 12946 faces"));
  EXPECT_EQ(testing::slurp(dir.file("c.off")), testing::slurp(dir.file("direct.off")));
}

TEST(ConvertCommand, AsciiFlagWritesAsciiPly) {
  TempDir dir;
  const auto result = run_rastrace({"convert", data_file("meshes/triceratops.off"), dir.file("t.ply"), "--ascii"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_THAT(testing::slurp(dir.file("t.ply")), HasSubstr("format ascii 1.0\n"));
}

TEST(ConvertCommand, UnwritableOutputFailsWithoutLeavingAPartialFile) {
  TempDir dir;
  const auto bad_format = run_rastrace({"convert", data_file("meshes/fandisk.off"), dir.file("out.stl")});
  EXPECT_EQ(bad_format.exit_code, 1);
  EXPECT_THAT(bad_format.err, HasSubstr("out.stl: cannot write format '.stl': expected .off, .ply or .obj"));
  const auto no_folder = run_rastrace({"convert", data_file("meshes/fandisk.off"), dir.file("missing/out.off")});
  EXPECT_EQ(no_folder.exit_code, 1);
  EXPECT_THAT(no_folder.err, HasSubstr("cannot open for writing"));
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

TEST(CommandLine, HelpShowsAnExampleForInfoAndConvert) {
  for (const char* command : {"info", "convert"}) {
    const auto result = run_rastrace({command, "--help"});
    EXPECT_EQ(result.exit_code, 0) << command;
    EXPECT_THAT(result.out, HasSubstr(std::string("rastrace ") + command + " ")) << command;
    EXPECT_THAT(result.out, HasSubstr("Example")) << command;
  }
}

TEST(CommandLine, UsageErrorsExitWithCode2) {
  EXPECT_EQ(run_rastrace({"info"}).exit_code, 2);
  EXPECT_EQ(run_rastrace({"info", "a.off", "--jsn"}).exit_code, 2);
  EXPECT_EQ(run_rastrace({"convert", "a.off"}).exit_code, 2);
  const auto ascii = run_rastrace({"convert", data_file("meshes/fandisk.off"), "x.off", "--ascii"});
  EXPECT_EQ(ascii.exit_code, 2);
  EXPECT_THAT(ascii.err, HasSubstr("--ascii"));
  EXPECT_FALSE(std::filesystem::exists("x.off"));
}

}  // namespace
}  // namespace rastrace

// Naming a texture's storage format: the scene JSON's "format" key on a texture object and the
// --texture-format option of render and texsweep, including the error a bad name gives.
#include <gtest/gtest.h>

#include "core/error.h"
#include "scenes/scene_io.h"
#include "support/run_rastrace.h"
#include "support/temp_dir.h"
#include "support/test_data.h"

namespace rastrace {
namespace {

std::string scene_json(const std::string& texture) {
  return R"({"objects": [{"mesh": ")" + testing::data_file("meshes/bunny00.off") +
         R"(", "uv_projection": "spherical", "material": {"texture": )" + texture + "}}]}";
}

TEST(SceneFormatKey, ProceduralTextureStoredAsBc1KeepsItsBlocksPerLevel) {
  testing::TempDir dir;
  const Scene scene =
      load_scene(dir.write("s.json", scene_json(R"({"procedural": "checker", "size": 64, "format": "bc1"})")));
  ASSERT_EQ(scene.textures.size(), 1u);
  const Texture& texture = scene.textures[0];
  EXPECT_EQ(texture.format, TextureFormat::Bc1);
  ASSERT_EQ(texture.blocks.size(), texture.levels.size());
  for (std::size_t level = 0; level < texture.levels.size(); ++level)
    EXPECT_EQ(texture.blocks[level].size(), level_bytes(TextureFormat::Bc1, std::uint32_t(texture.levels[level].width),
                                                        std::uint32_t(texture.levels[level].height)));
}

TEST(SceneFormatKey, OverrideReplacesTheFilesFormat) {
  testing::TempDir dir;
  const std::string path =
      dir.write("s.json", scene_json(R"({"procedural": "gradient", "size": 32, "format": "bc1"})"));
  EXPECT_EQ(load_scene(path, TextureFormat::Bc4).textures[0].format, TextureFormat::Bc4);
  EXPECT_EQ(load_scene(path, TextureFormat::Rgba8).textures[0].blocks.size(), 0u);
}

TEST(SceneFormatKey, BadNameIsAnInputErrorNamingTheJsonPath) {
  testing::TempDir dir;
  const std::string path = dir.write("s.json", scene_json(R"({"procedural": "checker", "format": "dxt9"})"));
  try {
    load_scene(path);
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("objects[0].material.texture.format"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("dxt9"), std::string::npos) << error.what();
  }
}

TEST(TextureFormatOption, RenderStoresTheTexturesAsAskedAndRefusesABadName) {
  testing::TempDir dir;
  const testing::CommandRun ok = testing::run_rastrace(
      {"render", "builtin:bunny", "--size", "64x48", "--texture-format", "bc7", "-o", dir.file("f.png")});
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  const testing::CommandRun bad = testing::run_rastrace(
      {"render", "builtin:bunny", "--size", "64x48", "--texture-format", "bc9", "-o", dir.file("g.png")});
  EXPECT_NE(bad.exit_code, 0);
  EXPECT_NE(bad.err.find("--texture-format"), std::string::npos) << bad.err;
  EXPECT_NE(bad.err.find("bc9"), std::string::npos) << bad.err;
}

TEST(TextureFormatOption, TexsweepAcceptsItToo) {
  const testing::CommandRun bad = testing::run_rastrace({"texsweep", "builtin:bunny", "--texture-format", "nope"});
  EXPECT_NE(bad.exit_code, 0);
  EXPECT_NE(bad.err.find("--texture-format"), std::string::npos) << bad.err;
}

// texsweep renders with --aniso and --aniso-rule too: 4x probes read more texels than the isotropic
// filter on the grid, the table states both, and 17 is refused.
TEST(TextureFormatOption, TexsweepTakesTheAnisotropyAndStatesIt) {
  const auto sweep = [](const std::string& aniso) {
    return testing::run_rastrace({"texsweep", "builtin:grid", "--resolution", "128x96", "--order", "strip", "--raster",
                                  "scanline", "--aniso", aniso, "--aniso-rule", "probes", "--texture-format", "bc1",
                                  "--tcache", "size=4KiB,layout=block4", "--format", "csv"});
  };
  const auto accesses = [](const std::string& csv) {
    const std::size_t row = csv.find("\nstrip,");
    return std::stoull(csv.substr(csv.find(",block4,", row) + 8));
  };
  const testing::CommandRun one = sweep("1"), four = sweep("4");
  ASSERT_EQ(one.exit_code, 0) << one.err;
  ASSERT_EQ(four.exit_code, 0) << four.err;
  EXPECT_NE(four.out.find("# aniso_rule: probes"), std::string::npos) << four.out;
  EXPECT_NE(four.out.find("# texture_format: bc1"), std::string::npos) << four.out;
  EXPECT_GT(accesses(four.out), accesses(one.out) * 5 / 4);
  const testing::CommandRun bad = sweep("17");
  EXPECT_NE(bad.exit_code, 0);
  EXPECT_NE(bad.err.find("--aniso"), std::string::npos) << bad.err;
}

}  // namespace
}  // namespace rastrace

// JSON scenes, plain mesh files as scenes, and the built-in scenes.
#include <cstdlib>
#include <filesystem>
#include <map>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "core/error.h"
#include "scenes/scene_io.h"
#include "scenes/texture_io.h"
#include "tests/support/temp_dir.h"
#include "tests/support/test_data.h"

namespace rastrace {
namespace {

using ::testing::HasSubstr;
using testing::TempDir;

std::string error_of(const std::string& spec) {
  try {
    load_scene(spec);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(JsonScene, ExampleSceneLoadsWithTransformsTexturesAndCamera) {
  // tests/scenes/scene_test.cpp -> the source tree's docs/.
  const std::string path =
      (std::filesystem::path(__FILE__).parent_path().parent_path().parent_path() / "docs" / "example_scene.json")
          .string();
  const Scene scene = load_scene(path);
  ASSERT_EQ(scene.objects.size(), 3u);
  EXPECT_EQ(scene.width, 640);
  EXPECT_EQ(scene.height, 480);
  EXPECT_FLOAT_EQ(scene.background.b, 0.2f);
  EXPECT_EQ(scene.camera.eye, glm::vec3(0.0f, 0.9f, 2.6f));
  EXPECT_FLOAT_EQ(scene.camera.fov_y_degrees, 45.0f);
  EXPECT_EQ(scene.objects[1].mesh.name, "bunny");
  EXPECT_EQ(scene.objects[1].mesh.face_count(), 75408u);
  ASSERT_EQ(scene.textures.size(), 3u);
  EXPECT_EQ(scene.textures[0].levels.size(), 10u);  // 512 -> 1
  EXPECT_EQ(scene.textures[1].levels.size(), 9u);   // 256 -> 1
  for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(scene.objects[i].mesh.materials.at(0).texture, static_cast<int>(i));
  // The matrix is given row by row: its last column is the translation.
  EXPECT_EQ(scene.objects[2].transform[3], glm::vec4(0.6f, -0.2f, 0.2f, 1.0f));
  // translate * rotate * scale: the floor's corner (1, 0, 1) lands at (2, -0.5, 2).
  EXPECT_EQ(glm::vec3(scene.objects[0].transform * glm::vec4(1, 0, 1, 1)), glm::vec3(2.0f, -0.5f, 2.0f));
}

TEST(JsonScene, SyntaxErrorsNameTheLineAndColumn) {
  TempDir dir;
  const std::string path = dir.write("bad.json", "{\n  \"objects\": [\n    { \"mesh\": \"x.off\" },\n  ]\n}\n");
  EXPECT_THAT(error_of(path), HasSubstr("bad.json:4: column 3: invalid JSON"));
}

TEST(JsonScene, WrongShapesNameTheJsonPath) {
  TempDir dir;
  const auto scene = [&](const std::string& body) { return error_of(dir.write("s.json", body)); };
  EXPECT_THAT(
      scene(
          R"({"objects": [{"mesh": {"procedural": "grid"}}], "camera": {"eye": [0,0,1], "target": [0,0,0], "fov_y": "wide"}})"),
      HasSubstr("s.json: camera.fov_y: expected a number, found string"));
  EXPECT_THAT(scene(R"({"objects": []})"), HasSubstr("objects: expected a non-empty array"));
  EXPECT_THAT(scene(R"([1, 2])"), HasSubstr("scene: expected an object, found array"));
  EXPECT_THAT(scene(R"({"objects": [{"mesh": {"procedural": "grid"}, "trasnform": {}}]})"),
              HasSubstr("objects[0].trasnform: expected no such key"));
  EXPECT_THAT(scene(R"({"objects": [{"mesh": {"procedural": "torus"}}]})"), HasSubstr("objects[0].mesh.procedural"));
  EXPECT_THAT(scene(R"({"objects": [{"mesh": "nowhere/missing.off"}]})"),
              HasSubstr("objects[0].mesh: expected an existing file"));
  EXPECT_THAT(scene(R"({"objects": [{"mesh": {"procedural": "icosphere"}, "material": {"texture": "gone.png"}}]})"),
              HasSubstr("objects[0].material.texture: expected an existing file"));
  EXPECT_THAT(
      scene(R"({"objects": [{"mesh": "meshes/fandisk.off", "material": {"texture": {"procedural": "checker"}}}]})"),
      HasSubstr("has none: add \"uv_projection\""));
  EXPECT_THAT(scene(R"({"objects": [{"mesh": {"procedural": "grid"}}], "viewport": {"width": 0, "height": 10}})"),
              HasSubstr("viewport.width: expected an integer from 1 to 16384, found 0"));
  EXPECT_THAT(scene(R"({"objects": [{"mesh": {"procedural": "grid"}}], "background": [2, 0, 0]})"),
              HasSubstr("background[0]: expected a colour component in 0..1"));
}

// Each procedural size is bounded, but not their sum over a scene: the generated meshes and
// textures are counted against the one allocation limit (RASTRACE_MEMORY_LIMIT, 64 MiB here)
// before anything is generated: 32 bytes a vertex (position, normal, UV), 16 a triangle (indices,
// material), 4/3 * 4 a texel (RGBA8 and mips). A 900 x 900 grid needs 901^2 * 32 + 2 * 900^2 * 16
// = 51,897,632 bytes: one fits, two do not.
TEST(JsonScene, ProceduralMeshesAndTexturesBeyondTheMemoryLimitAreErrorsNamingTheObject) {
  TempDir dir;
  ::setenv("RASTRACE_MEMORY_LIMIT", "67108864", 1);
  const auto scene = [&](const std::string& body) { return error_of(dir.write("big.json", body)); };
  const std::string grid_900 = R"({"mesh": {"procedural": "grid", "width": 900, "height": 900}})";
  EXPECT_EQ(scene(R"({"objects": [)" + grid_900 + "]}"), "(no error)");
  EXPECT_THAT(scene(R"({"objects": [)" + grid_900 + "," + grid_900 + "]}"),
              HasSubstr("big.json: objects[1].mesh: the scene's procedural meshes: needs 103795264 bytes"));
  EXPECT_THAT(scene(R"({"objects": [{"mesh": {"procedural": "plane", "segments": 1100}}]})"),
              HasSubstr("objects[0].mesh: the scene's procedural meshes: needs 77510432 bytes"));
  EXPECT_EQ(scene(R"({"objects": [{"mesh": {"procedural": "icosphere", "subdivisions": 8}}]})"), "(no error)");
  const std::string textured = R"({"mesh": {"procedural": "plane"}, "material": {"texture": {"procedural": "checker", "size": 4096}}})";
  EXPECT_THAT(scene(R"({"objects": [)" + textured + "]}"),
              HasSubstr("procedural textures: needs 89478485 bytes"));
  ::unsetenv("RASTRACE_MEMORY_LIMIT");
}

// A scene of a few kilobytes may list one mesh file hundreds of times: the file is read once, and
// every object's copy counts into the scene's mesh bytes against the allocation limit (64 MiB here),
// so the copies end in an error naming the first object past it rather than in an allocation failure.
TEST(JsonScene, OneMeshFileListedManyTimesIsReadOnceAndItsCopiesAreBounded) {
  TempDir dir;
  std::filesystem::copy_file(testing::data_file("meshes/triceratops.off"), dir.file("t.off"));
  const auto listing = [&](int n) {
    std::string body = R"({"objects": [)";
    for (int i = 0; i < n; ++i) body += std::string(i ? ", " : "") + R"({"mesh": "t.off"})";
    return dir.write("many.json", body + "]}");
  };
  ::setenv("RASTRACE_MEMORY_LIMIT", "67108864", 1);
  const Scene scene = load_scene(listing(200));
  ASSERT_EQ(scene.objects.size(), 200u);
  for (const SceneObject& object : scene.objects) EXPECT_EQ(object.mesh.face_count(), 5660u);
  EXPECT_THAT(error_of(listing(1000)), HasSubstr("many.json: objects[370].mesh: the scene's meshes: needs 67219264 bytes"));
  ::unsetenv("RASTRACE_MEMORY_LIMIT");
}

TEST(JsonScene, RelativePathsResolveBesideTheSceneThenInTheDataFolder) {
  TempDir dir;
  std::filesystem::copy_file(testing::data_file("meshes/triceratops.off"), dir.file("local.off"));
  const Scene scene =
      load_scene(dir.write("s.json", R"({"objects": [{"mesh": "local.off"}, {"mesh": "meshes/fandisk.off"}]})"));
  EXPECT_EQ(scene.objects[0].mesh.face_count(), 5660u);
  EXPECT_EQ(scene.objects[1].mesh.face_count(), 12946u);
}

TEST(MeshFileScene, DefaultCameraSeesTheWholeBoundingBox) {
  const Scene scene = load_scene(testing::data_file("meshes/triceratops.off"));
  ASSERT_EQ(scene.objects.size(), 1u);
  const Camera& c = scene.camera;
  const glm::mat4 view = glm::lookAt(c.eye, c.target, c.up);
  const glm::mat4 projection = glm::perspective(glm::radians(c.fov_y_degrees), 1.0f, c.near_plane, c.far_plane);
  for (const glm::vec3& p : scene.objects[0].mesh.positions) {
    const glm::vec4 clip = projection * view * glm::vec4(p, 1.0f);
    ASSERT_GT(clip.w, 0.0f);
    EXPECT_LE(std::abs(clip.x), clip.w);
    EXPECT_LE(std::abs(clip.y), clip.w);
    EXPECT_LE(std::abs(clip.z), clip.w);
  }
}

TEST(MeshFileScene, GlbEmbeddedTextureDecodesToTheSameTexelsAsTheExternalCopy) {
  const Scene scene = load_scene(testing::data_file("assimp/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb"));
  ASSERT_EQ(scene.textures.size(), 1u);
  EXPECT_THAT(scene.textures[0].name, HasSubstr("BoxTextured.glb#"));
  const Image external = load_image(testing::data_file("assimp/glTF2/BoxTextured-glTF/CesiumLogoFlat.png"));
  const Image& embedded = scene.textures[0].levels[0];
  EXPECT_EQ(embedded.width, external.width);
  EXPECT_EQ(embedded.height, external.height);
  EXPECT_EQ(embedded.rgba, external.rgba);
}

TEST(BuiltinScene, GridIsCheckeredAndSeenFromAboveAtAGrazingAngle) {
  const Scene scene = load_scene("builtin:grid");
  ASSERT_EQ(scene.objects.size(), 1u);
  const SceneObject& grid = scene.objects[0];
  EXPECT_EQ(grid.mesh.face_count(), 2048u);
  ASSERT_EQ(scene.textures.size(), 1u);
  EXPECT_EQ(scene.textures[0].levels.size(), 10u);
  EXPECT_EQ(grid.mesh.materials[0].texture, 0);
  // Every triangle, once transformed, faces the camera counter-clockwise... as the article's
  // layout winds clockwise seen from +z, the transform turns its -z side up.
  const glm::mat4& m = grid.transform;
  for (std::size_t i = 0; i < grid.mesh.indices.size(); i += 3) {
    const glm::vec3 a(m * glm::vec4(grid.mesh.positions[grid.mesh.indices[i]], 1)),
        b(m * glm::vec4(grid.mesh.positions[grid.mesh.indices[i + 1]], 1)),
        c(m * glm::vec4(grid.mesh.positions[grid.mesh.indices[i + 2]], 1));
    ASSERT_GT(glm::cross(b - a, c - a).y, 0.0f);
    ASSERT_EQ(a.y, 0.0f);
  }
  const glm::vec3 view = glm::normalize(scene.camera.target - scene.camera.eye);
  const float elevation = glm::degrees(std::asin(-view.y));
  EXPECT_NEAR(elevation, 25.0f, 0.01f);
}

TEST(BuiltinScene, BunnyHasEachOfTheFourColoursOnASizeableRegion) {
  const Scene scene = load_scene("builtin:bunny");
  ASSERT_EQ(scene.objects.size(), 1u);
  const Mesh& bunny = scene.objects[0].mesh;
  EXPECT_EQ(bunny.vertex_count(), 37706u);
  ASSERT_EQ(scene.textures.size(), 1u);
  const Image& base = scene.textures[0].levels[0];
  std::map<std::array<std::uint8_t, 3>, std::size_t> faces_per_colour;
  for (std::size_t f = 0; f < bunny.face_count(); ++f) {
    glm::vec2 uv(0.0f);
    for (int k = 0; k < 3; ++k) uv += bunny.uvs[bunny.indices[f * 3 + k]] / 3.0f;
    const int x = std::min(base.width - 1, static_cast<int>(uv.x * static_cast<float>(base.width)));
    const int y = std::min(base.height - 1, static_cast<int>(uv.y * static_cast<float>(base.height)));
    const std::uint8_t* t = base.texel(x, y);
    ++faces_per_colour[{t[0], t[1], t[2]}];
  }
  ASSERT_EQ(faces_per_colour.size(), 4u);
  for (const auto& [colour, count] : faces_per_colour) EXPECT_GT(count, bunny.face_count() / 10);
}

TEST(BuiltinScene, SpiderHasItsOwnFiveTextures) {
  const Scene scene = load_scene("builtin:spider");
  ASSERT_EQ(scene.objects.size(), 1u);
  EXPECT_EQ(scene.objects[0].mesh.materials.size(), 5u);
  ASSERT_EQ(scene.textures.size(), 5u);
  for (const Material& m : scene.objects[0].mesh.materials) EXPECT_GE(m.texture, 0);
  for (const Texture& t : scene.textures) {
    EXPECT_EQ(t.levels.back().width, 1);
    EXPECT_EQ(t.levels.back().height, 1);
  }
}

TEST(BuiltinScene, UnknownNamesAndAMissingDataFolderAreInputErrors) {
  EXPECT_THAT(error_of("builtin:teapot"), HasSubstr("builtin:teapot: no such built-in scene"));
  TempDir dir;
  ::setenv("RASTRACE_DATA", dir.path().c_str(), 1);
  EXPECT_EQ(data_directory(), dir.path().string());
  const std::string message = error_of("builtin:bunny");
  ::unsetenv("RASTRACE_DATA");
  EXPECT_THAT(message, HasSubstr(dir.path().string()));
  EXPECT_THAT(message, HasSubstr("RASTRACE_DATA"));
}

}  // namespace
}  // namespace rastrace

// Camera paths (scenes/camera_path.h): the camera of a frame interpolated between keyframes, and
// "camera_path" in JSON scenes with errors that name the JSON path.
#include <filesystem>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "core/error.h"
#include "scenes/camera_path.h"
#include "scenes/scene_io.h"
#include "tests/support/temp_dir.h"

namespace rastrace {
namespace {

using ::testing::HasSubstr;

CameraPath two_keyframes() {
  CameraPath path;
  path.keyframes.push_back({10, {0, 0, 4}, {0, 0, 0}, {0, 1, 0}, 40.0f});
  path.keyframes.push_back({20, {4, 2, 0}, {0, 1, 0}, {1, 0, 0}, 60.0f});
  return path;
}

Camera base_camera() {
  Camera c;
  c.near_plane = 0.5f;
  c.far_plane = 50.0f;
  return c;
}

TEST(CameraPath, KeyframesAreReproducedExactlyWithTheBaseCamerasPlanes) {
  const CameraPath path = two_keyframes();
  for (const CameraKeyframe& k : path.keyframes) {
    const Camera c = camera_at(base_camera(), path, k.frame);
    EXPECT_EQ(c.eye, k.eye);
    EXPECT_EQ(c.target, k.target);
    EXPECT_EQ(c.up, k.up);
    EXPECT_EQ(c.fov_y_degrees, k.fov_y_degrees);
    EXPECT_EQ(c.near_plane, 0.5f);
    EXPECT_EQ(c.far_plane, 50.0f);
  }
}

TEST(CameraPath, MidpointInterpolatesLinearlyAndNormalizesUp) {
  const Camera c = camera_at(base_camera(), two_keyframes(), 15);
  EXPECT_EQ(c.eye, glm::vec3(2.0f, 1.0f, 2.0f));
  EXPECT_EQ(c.target, glm::vec3(0.0f, 0.5f, 0.0f));
  EXPECT_FLOAT_EQ(c.up.x, 1.0f / std::sqrt(2.0f));
  EXPECT_FLOAT_EQ(c.up.y, 1.0f / std::sqrt(2.0f));
  EXPECT_EQ(c.up.z, 0.0f);
  EXPECT_EQ(c.fov_y_degrees, 50.0f);
  // A quarter of the way: frame 12 of 10..20 is t = 0.2.
  const Camera q = camera_at(base_camera(), two_keyframes(), 12);
  EXPECT_FLOAT_EQ(q.eye.x, 0.8f);
  EXPECT_FLOAT_EQ(q.eye.z, 3.2f);
  EXPECT_FLOAT_EQ(q.fov_y_degrees, 44.0f);
}

TEST(CameraPath, FramesOutsideTheKeyframesClampToTheFirstAndLast) {
  const CameraPath path = two_keyframes();
  EXPECT_EQ(camera_at(base_camera(), path, 0).eye, path.keyframes[0].eye);
  EXPECT_EQ(camera_at(base_camera(), path, 9).fov_y_degrees, 40.0f);
  EXPECT_EQ(camera_at(base_camera(), path, 21).eye, path.keyframes[1].eye);
  EXPECT_EQ(camera_at(base_camera(), path, 4000000000u).target, path.keyframes[1].target);
}

TEST(CameraPath, NoKeyframesIsTheStaticCameraAndOneKeyframeHoldsEverywhere) {
  CameraPath path;
  Camera base = base_camera();
  base.eye = {1, 2, 3};
  EXPECT_EQ(camera_at(base, path, 7).eye, base.eye);
  path.keyframes.push_back({5, {9, 9, 9}, {0, 0, 0}, {0, 1, 0}, 30.0f});
  EXPECT_EQ(camera_at(base, path, 0).eye, glm::vec3(9, 9, 9));
  EXPECT_EQ(camera_at(base, path, 100).fov_y_degrees, 30.0f);
}

TEST(CameraPath, OppositeUpsKeepTheEarlierUpWhereTheyCancel) {
  CameraPath path;
  path.keyframes.push_back({0, {0, 0, 4}, {0, 0, 0}, {0, 1, 0}, 45.0f});
  path.keyframes.push_back({2, {0, 0, 4}, {0, 0, 0}, {0, -1, 0}, 45.0f});
  EXPECT_EQ(camera_at(base_camera(), path, 1).up, glm::vec3(0, 1, 0));
}

TEST(CameraPath, ErrorsNameTheKeyframeAndField) {
  CameraPath path = two_keyframes();
  EXPECT_EQ(camera_path_error(path), "");
  path.keyframes[1].frame = 10;
  EXPECT_EQ(camera_path_error(path), "keyframes[1].frame: expected a frame after the previous keyframe's 10, found 10");
  path = two_keyframes();
  path.keyframes[0].target = path.keyframes[0].eye;
  EXPECT_THAT(camera_path_error(path), HasSubstr("keyframes[0].target: expected a point different"));
  path = two_keyframes();
  path.keyframes[1].fov_y_degrees = 180.0f;
  EXPECT_THAT(camera_path_error(path), HasSubstr("keyframes[1].fov_y: expected degrees between 0 and 180"));
}

std::string scene_with_path(const std::string& path) {
  return R"({"objects": [{"mesh": {"procedural": "grid", "width": 2, "height": 2}}], "camera_path": )" + path + "}";
}

std::string error_of(const testing::TempDir& dir, const std::string& path) {
  try {
    load_scene(dir.write("path.json", scene_with_path(path)));
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(JsonCameraPath, KeyframesTakeUpAndFovFromTheStaticCameraWhenOmitted) {
  const testing::TempDir dir;
  const std::string file = dir.write("path.json", R"({"objects": [{"mesh": {"procedural": "grid"}}],
    "camera": {"eye": [0, 0, 5], "target": [0, 0, 0], "up": [0, 2, 0], "fov_y": 30},
    "camera_path": {"keyframes": [{"frame": 0, "eye": [0, 0, 5], "target": [0, 0, 0]},
                                  {"frame": 8, "eye": [5, 0, 0], "target": [0, 0, 0], "up": [0, 0, 3], "fov_y": 60}]}})");
  const Scene scene = load_scene(file);
  ASSERT_EQ(scene.camera_path.keyframes.size(), 2u);
  EXPECT_EQ(scene.camera_path.keyframes[0].up, glm::vec3(0, 1, 0));  // the camera's, normalized
  EXPECT_EQ(scene.camera_path.keyframes[0].fov_y_degrees, 30.0f);
  EXPECT_EQ(scene.camera_path.keyframes[1].up, glm::vec3(0, 0, 1));
  const Camera mid = camera_at(scene.camera, scene.camera_path, 4);
  EXPECT_EQ(mid.eye, glm::vec3(2.5f, 0.0f, 2.5f));
  EXPECT_EQ(mid.fov_y_degrees, 45.0f);
}

TEST(JsonCameraPath, BadPathsAreErrorsNamingTheJsonPath) {
  const testing::TempDir dir;
  EXPECT_THAT(error_of(dir, "[]"), HasSubstr("camera_path: expected an object, found array"));
  EXPECT_THAT(error_of(dir, R"({"keyframes": []})"), HasSubstr("camera_path.keyframes: expected a non-empty array"));
  EXPECT_THAT(error_of(dir, R"({"frames": []})"), HasSubstr("camera_path.frames: expected no such key"));
  EXPECT_THAT(error_of(dir, R"({"keyframes": [{"frame": 0, "eye": [0, 0, 1]}]})"),
              HasSubstr("camera_path.keyframes[0]: expected a key \"target\""));
  EXPECT_THAT(error_of(dir, R"({"keyframes": [{"frame": -1, "eye": [0, 0, 1], "target": [0, 0, 0]}]})"),
              HasSubstr("camera_path.keyframes[0].frame: expected an integer from 0"));
  EXPECT_THAT(error_of(dir, R"({"keyframes": [{"frame": 0, "eye": [0, 0, 1], "target": [0, 0, 0]},
                                              {"frame": 3, "eye": [0, 1, 1], "target": [0, 0, 0]},
                                              {"frame": 2, "eye": [0, 2, 1], "target": [0, 0, 0]}]})"),
              HasSubstr("camera_path.keyframes[2].frame: expected a frame after the previous keyframe's 3, found 2"));
  EXPECT_THAT(error_of(dir, R"({"keyframes": [{"frame": 0, "eye": [0, 0, 1], "target": [0, 0, 0], "up": [0, 0, 0]}]})"),
              HasSubstr("camera_path.keyframes[0].up: expected a non-zero direction"));
  EXPECT_THAT(error_of(dir, R"({"keyframes": [{"frame": 0, "eye": [0, 0, 1], "target": [0, 0, 0], "up": [0, 0, 2]}]})"),
              HasSubstr("camera_path.keyframes[0].up: expected a direction not parallel"));
  EXPECT_THAT(error_of(dir, R"({"keyframes": [{"frame": 0, "eye": [0, 0, 1], "target": [0, 0, 0], "fov_y": 0}]})"),
              HasSubstr("camera_path.keyframes[0].fov_y: expected degrees between 0 and 180"));
  EXPECT_THAT(error_of(dir, R"({"keyframes": [{"frame": 0, "eye": [0, 0, "1"], "target": [0, 0, 0]}]})"),
              HasSubstr("camera_path.keyframes[0].eye[2]: expected a number, found string"));
}

TEST(JsonCameraPath, TheOrbitExampleCirclesItsTargetInThirtyFrames) {
  const std::string path =
      (std::filesystem::path(RASTRACE_TEST_FILES_DIR).parent_path() / "docs" / "orbit_scene.json").string();
  const Scene scene = load_scene(path);
  ASSERT_EQ(scene.camera_path.keyframes.size(), 7u);
  EXPECT_EQ(scene.camera_path.keyframes.back().frame, 30u);
  for (std::uint32_t f = 0; f <= 30; f += 5) {
    const Camera c = camera_at(scene.camera, scene.camera_path, f);
    EXPECT_NEAR(glm::length(glm::vec2(c.eye.x, c.eye.z)), 2.6f, 1e-3f) << "frame " << f;
    EXPECT_EQ(c.target, glm::vec3(0.0f, 0.1f, 0.0f));
  }
  const Scene grid = load_scene(
      (std::filesystem::path(RASTRACE_TEST_FILES_DIR).parent_path() / "docs" / "grid_orbit_scene.json").string());
  ASSERT_EQ(grid.camera_path.keyframes.size(), 9u);
  EXPECT_EQ(camera_at(grid.camera, grid.camera_path, 30).eye, camera_at(grid.camera, grid.camera_path, 0).eye);
}

}  // namespace
}  // namespace rastrace

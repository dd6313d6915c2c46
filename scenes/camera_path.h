// A camera moving over frames (render --frames N): keyframes at increasing frame numbers, the
// camera of frame f interpolated linearly between the keyframes around it (eye, target, up
// normalized after interpolation, vertical field of view) and clamped before the first keyframe
// and after the last. Scene files give it as "camera_path" (docs/scene-format.md); near and far
// planes stay those of the scene's static camera.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace rastrace {

struct Camera {
  glm::vec3 eye{0.0f, 0.0f, 3.0f};
  glm::vec3 target{0.0f, 0.0f, 0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float fov_y_degrees = 45.0f;
  float near_plane = 0.1f;
  float far_plane = 100.0f;
};

struct CameraKeyframe {
  std::uint32_t frame = 0;
  glm::vec3 eye{0.0f, 0.0f, 3.0f};
  glm::vec3 target{0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};  // unit length
  float fov_y_degrees = 45.0f;
};

// No keyframes: the scene's static camera in every frame.
struct CameraPath {
  std::vector<CameraKeyframe> keyframes;  // strictly increasing `frame`
  bool empty() const { return keyframes.empty(); }
};

// The camera of `frame`: `base` itself when the path is empty, else base's near and far planes
// with the path's interpolated eye, target, up and fov_y. An interpolated up that vanishes
// (opposite ups halfway) keeps the earlier keyframe's up.
Camera camera_at(const Camera& base, const CameraPath& path, std::uint32_t frame);

// What is wrong with the path, as "keyframes[2].frame: expected ..." (empty when it is sound):
// frames strictly increasing, target different from eye, up of unit length and not parallel to
// the view direction, fov_y in (0, 180) degrees.
std::string camera_path_error(const CameraPath& path);

}  // namespace rastrace

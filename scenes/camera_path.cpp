#include "scenes/camera_path.h"

#include <cmath>

#include <glm/geometric.hpp>

namespace rastrace {

namespace {
glm::vec3 lerp(const glm::vec3& a, const glm::vec3& b, float t) { return a + (b - a) * t; }

Camera with_keyframe(Camera camera, const CameraKeyframe& k) {
  camera.eye = k.eye;
  camera.target = k.target;
  camera.up = k.up;
  camera.fov_y_degrees = k.fov_y_degrees;
  return camera;
}
}  // namespace

Camera camera_at(const Camera& base, const CameraPath& path, std::uint32_t frame) {
  const std::vector<CameraKeyframe>& keys = path.keyframes;
  if (keys.empty()) return base;
  if (frame <= keys.front().frame) return with_keyframe(base, keys.front());
  if (frame >= keys.back().frame) return with_keyframe(base, keys.back());
  std::size_t next = 1;
  while (keys[next].frame <= frame) ++next;  // keys[next - 1].frame <= frame < keys[next].frame
  const CameraKeyframe& a = keys[next - 1];
  const CameraKeyframe& b = keys[next];
  // In double: frame numbers up to 2^32 lose nothing, and t is exact at the keyframes.
  const auto t = static_cast<float>(double(frame - a.frame) / double(b.frame - a.frame));
  Camera camera = base;
  camera.eye = lerp(a.eye, b.eye, t);
  camera.target = lerp(a.target, b.target, t);
  const glm::vec3 up = lerp(a.up, b.up, t);
  camera.up = glm::length(up) > 1e-6f ? glm::normalize(up) : a.up;
  camera.fov_y_degrees = a.fov_y_degrees + (b.fov_y_degrees - a.fov_y_degrees) * t;
  return camera;
}

std::string camera_path_error(const CameraPath& path) {
  for (std::size_t i = 0; i < path.keyframes.size(); ++i) {
    const CameraKeyframe& k = path.keyframes[i];
    const std::string at = "keyframes[" + std::to_string(i) + "].";
    if (i > 0 && k.frame <= path.keyframes[i - 1].frame)
      return at + "frame: expected a frame after the previous keyframe's " +
             std::to_string(path.keyframes[i - 1].frame) + ", found " + std::to_string(k.frame);
    if (!(k.fov_y_degrees > 0.0f && k.fov_y_degrees < 180.0f))
      return at + "fov_y: expected degrees between 0 and 180 (exclusive)";
    if (glm::length(k.target - k.eye) == 0.0f) return at + "target: expected a point different from the eye";
    if (std::fabs(glm::length(k.up) - 1.0f) > 1e-4f) return at + "up: expected a non-zero direction";
    if (glm::length(glm::cross(k.target - k.eye, k.up)) == 0.0f)
      return at + "up: expected a direction not parallel to the view direction";
  }
  return {};
}

}  // namespace rastrace

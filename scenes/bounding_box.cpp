#include "scenes/bounding_box.h"

#include <limits>

#include <glm/common.hpp>

namespace rastrace {

namespace {

// Grows a box from +inf/-inf corners. glm::min(lo, p) keeps lo when a coordinate of p is NaN (a
// comparison with NaN is false), so a NaN read from a file does not poison the box; an axis that
// received nothing but NaN ends at 0, as an empty set does.
class BoxBuilder {
 public:
  void add(const glm::vec3& p) {
    lo_ = glm::min(lo_, p);
    hi_ = glm::max(hi_, p);
  }
  BoundingBox box() const {
    BoundingBox box{lo_, hi_};
    for (int axis = 0; axis < 3; ++axis)
      if (!(box.lo[axis] <= box.hi[axis])) box.lo[axis] = box.hi[axis] = 0.0f;
    return box;
  }

 private:
  glm::vec3 lo_{std::numeric_limits<float>::infinity()};
  glm::vec3 hi_{-std::numeric_limits<float>::infinity()};
};

}  // namespace

BoundingBox bounding_box(std::span<const glm::vec3> positions) {
  BoxBuilder builder;
  for (const glm::vec3& p : positions) builder.add(p);
  return builder.box();
}

BoundingBox bounding_box(std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices) {
  BoxBuilder builder;
  for (const std::uint32_t v : indices) builder.add(positions[v]);
  return builder.box();
}

BoundingBox bounding_box(std::span<const glm::vec3> positions, const glm::mat4& transform) {
  BoxBuilder builder;
  for (const glm::vec3& p : positions) builder.add(glm::vec3(transform * glm::vec4(p, 1.0f)));
  return builder.box();
}

BoundingBox bounding_box(const Scene& scene) {
  BoxBuilder builder;
  for (const SceneObject& object : scene.objects)
    for (const glm::vec3& p : object.mesh.positions) builder.add(glm::vec3(object.transform * glm::vec4(p, 1.0f)));
  return builder.box();
}

}  // namespace rastrace

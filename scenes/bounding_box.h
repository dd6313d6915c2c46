// The axis-aligned bounding box of a set of positions: what framing a camera, normalizing
// centroids for a space-filling curve or projecting UVs start from.
#pragma once

#include <cstdint>
#include <span>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "scenes/scene.h"

namespace rastrace {

struct BoundingBox {
  // Both corners are the origin for an empty set of positions. NaN coordinates are ignored.
  glm::vec3 lo{0.0f};
  glm::vec3 hi{0.0f};

  glm::vec3 extent() const { return hi - lo; }
  glm::vec3 centre() const { return 0.5f * (lo + hi); }
};

// The box of all the positions.
BoundingBox bounding_box(std::span<const glm::vec3> positions);
// The box of the positions the indices name (a mesh's referenced vertices: unreferenced ones do
// not stretch it). Every index must be < positions.size().
BoundingBox bounding_box(std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices);
// The box of the positions after `transform` (model to world).
BoundingBox bounding_box(std::span<const glm::vec3> positions, const glm::mat4& transform);
// The world-space box of every object of the scene.
BoundingBox bounding_box(const Scene& scene);

}  // namespace rastrace

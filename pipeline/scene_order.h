// A scene's objects in a triangle ordering, as draw calls the pipeline takes
// (RenderOptions::object_draws): `rastrace render --order`, `compare` and the texture
// experiment draw exactly the same streams, so a live render and the replay of its trace agree.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "pipeline/pipeline.h"
#include "reorder/ordering.h"
#include "scenes/scene.h"

namespace rastrace {

// One draw per object in the requested triangle order; `indices` and `materials` keep the spans
// of `draws` alive.
struct OrderedDraws {
  std::vector<std::vector<std::uint32_t>> indices;
  std::vector<std::vector<std::uint32_t>> materials;
  std::vector<DrawCall> draws;
};
// Empty when the order is "original" (the file's own triangle lists). Each object is drawn from
// its ordering's own stream (list, strip, ...), every triangle with its face's material. Throws
// InputError for an unknown ordering.
OrderedDraws order_scene(const Scene& scene, const std::string& order, const ReorderParams& params);

}  // namespace rastrace

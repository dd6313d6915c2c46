// A scene at one VIPM level of detail, ready for the full textured pipeline (`rastrace render
// --vipm METHOD --lod N`): every object is replaced by its progressive mesh's vertex buffer
// (vanilla's vertex order, or sliding window's relaxed one) and drawn with exactly the draws the
// representation hands a GPU at that LoD (mixed-mode: two per object), degenerate triangles
// included, so the frame's texel trace can be swept like any other.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "lod/vipm_representation.h"
#include "pipeline/pipeline.h"
#include "scenes/scene.h"

namespace rastrace {

struct VipmSceneSpec {
  std::string method = "vanilla";   // a vipm_method_names() name
  std::uint32_t lod = 0;            // collapses done; clamped to each object's last LoD
  double tolerance = 0.1;           // sliding window's relaxation, of the mean collapse error
  std::uint32_t min_triangles = 0;  // the builder's; 0: its default
};

// What one drawn part received.
struct VipmPartLod {
  std::string name;  // object (and material, for objects split by material)
  std::uint32_t lod = 0;
  std::uint32_t last_lod = 0;
  std::uint32_t full_triangles = 0;
  std::uint32_t draws = 0;
};

struct VipmScene {
  Scene scene;  // one object per part: the part's VIPM vertex buffer, with the source's transform
  std::vector<std::unique_ptr<VipmRepresentation>> representations;  // own the draws' indices
  std::vector<DrawCall> draws;
  std::vector<std::uint32_t> draw_objects;  // draws[i] draws scene.objects[draw_objects[i]]
  std::vector<VipmPartLod> parts;
};

// An object with several face materials is split into one part per material (in order of first
// use), as an engine keeps one progressive mesh per draw's material. Throws InputError for an
// unknown method (naming `--vipm`), or a part the progressive-mesh builder refuses (naming the
// object and the part).
VipmScene build_vipm_scene(const Scene& scene, const VipmSceneSpec& spec);

// `--lod N`: a count of collapses, 0 .. 2^32 - 1 (InputError otherwise).
std::uint32_t parse_vipm_lod(const std::string& text);
// "bunny00.off 30000/36950 (1 draw)" per part (LoD done / last LoD), "; " between.
std::string describe_vipm_lods(std::span<const VipmPartLod> parts);

}  // namespace rastrace

#include "lod/vipm_measure_methods.h"

#include <stdexcept>

#include "lod/mixed_mode.h"
#include "lod/skip_strips.h"
#include "lod/sliding_window.h"

namespace rastrace {

namespace {

LevelParams level_params(PrimitiveType primitive, const VipmMethodsParams& params) {
  LevelParams level;
  level.primitive = primitive;
  level.algorithm = primitive == PrimitiveType::TriangleStrip ? params.strip_algorithm : params.list_algorithm;
  level.reorder = params.reorder;
  level.new_level_fraction = params.new_level_fraction;
  return level;
}

}  // namespace

std::unique_ptr<VipmRepresentation> build_vipm_representation(const std::string& method, const ProgressiveMesh& pm,
                                                              const Mesh& vertices, const VipmMethodsParams& params) {
  const LevelParams strips = level_params(PrimitiveType::TriangleStrip, params);
  const LevelParams lists = level_params(PrimitiveType::TriangleList, params);
  if (method == "vanilla") return build_vanilla(pm, params.build);
  if (method == "skip-strips-strip") return build_skip_strips(pm, vertices, strips, params.build);
  if (method == "skip-strips-list") return build_skip_strips(pm, vertices, lists, params.build);
  if (method == "mixed-strip") return build_mixed_mode(pm, vertices, strips, params.build);
  if (method == "mixed-list") return build_mixed_mode(pm, vertices, lists, params.build);
  if (method == "sliding-window") {
    SlidingWindowParams window;
    window.algorithm = params.list_algorithm;
    window.reorder = params.reorder;
    return build_sliding_window(pm, vertices, window, params.build);
  }
  throw std::logic_error("no VIPM representation named " + method);
}

VipmMethods build_vipm_methods(const ProgressiveMesh& pm, const Mesh& vertices, const VipmMethodsParams& params) {
  VipmMethods out;
  for (const char* method : {"vanilla", "skip-strips-strip", "skip-strips-list", "mixed-strip", "mixed-list"})
    out.representations.push_back(build_vipm_representation(method, pm, vertices, params));
  out.sliding_window_strict_levels = static_cast<std::uint32_t>(sliding_window_level_starts(pm).size());
  out.sliding_window_levels_tolerance_0 = relax_for_sliding_window(pm, 0.0).levels;
  out.sliding_window_order = relax_for_sliding_window(pm, params.tolerance);
  Mesh relaxed_vertices;
  relaxed_vertices.name = vertices.name;
  for (std::uint32_t v : out.sliding_window_order.input_vertex)
    relaxed_vertices.positions.push_back(vertices.positions[v]);
  out.representations.push_back(
      build_vipm_representation("sliding-window", out.sliding_window_order.pm, relaxed_vertices, params));
  return out;
}

}  // namespace rastrace

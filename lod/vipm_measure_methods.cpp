#include "lod/vipm_measure_methods.h"

#include "lod/mixed_mode.h"
#include "lod/skip_strips.h"
#include "lod/sliding_window.h"

namespace rastrace {

VipmMethods build_vipm_methods(const ProgressiveMesh& pm, const Mesh& vertices, const VipmMethodsParams& params) {
  VipmMethods out;
  LevelParams strips;
  strips.primitive = PrimitiveType::TriangleStrip;
  strips.algorithm = params.strip_algorithm;
  strips.reorder = params.reorder;
  strips.new_level_fraction = params.new_level_fraction;
  LevelParams lists = strips;
  lists.primitive = PrimitiveType::TriangleList;
  lists.algorithm = params.list_algorithm;
  out.representations.push_back(build_vanilla(pm, params.build));
  out.representations.push_back(build_skip_strips(pm, vertices, strips, params.build));
  out.representations.push_back(build_skip_strips(pm, vertices, lists, params.build));
  out.representations.push_back(build_mixed_mode(pm, vertices, strips, params.build));
  out.representations.push_back(build_mixed_mode(pm, vertices, lists, params.build));
  out.sliding_window_strict_levels = static_cast<std::uint32_t>(sliding_window_level_starts(pm).size());
  out.sliding_window_levels_tolerance_0 = relax_for_sliding_window(pm, 0.0).levels;
  out.sliding_window_order = relax_for_sliding_window(pm, params.tolerance);
  Mesh relaxed_vertices;
  relaxed_vertices.name = vertices.name;
  for (std::uint32_t v : out.sliding_window_order.input_vertex)
    relaxed_vertices.positions.push_back(vertices.positions[v]);
  SlidingWindowParams window;
  window.algorithm = params.list_algorithm;
  window.reorder = params.reorder;
  out.representations.push_back(
      build_sliding_window(out.sliding_window_order.pm, relaxed_vertices, window, params.build));
  return out;
}

}  // namespace rastrace

#include <algorithm>
#include <array>
#include <map>
#include <numeric>

#include "core/error.h"
#include "reorder/kcache.h"
#include "reorder/nvstrip.h"
#include "reorder/ordering.h"
#include "reorder/texgroup.h"

namespace rastrace {

const std::vector<ReorderAlgorithm>& reorder_algorithms() {
  static const std::vector<ReorderAlgorithm> algorithms = {
      {"original", "file order", reorder_original},
      {"random", "uniformly random face order (seeded)", reorder_random},
      {"scanline", "rows of triangles in order (Castano 2009 baseline)", reorder_scanline},
      {"forsyth", "Forsyth 2006, linear-speed vertex cache optimisation", reorder_forsyth},
      {"tipsy", "Sander, Nehab, Barczak 2007, Tipsify fanning", reorder_tipsy},
      {"tipsy-overdraw", "Sander, Nehab, Barczak 2007, Tipsy clusters sorted by occlusion potential",
       reorder_tipsy_overdraw},
      {"front-to-back", "tipsy-overdraw's clusters sorted nearest first along --view", reorder_front_to_back},
      {"back-to-front", "tipsy-overdraw's clusters sorted farthest first along --view", reorder_back_to_front},
      {"kcache", "Lin and Yu 2006, K-Cache-Reorder", reorder_kcache},
      {"morton", "Morton order of triangle centroids", reorder_morton},
      {"hilbert", "Hilbert order of triangle centroids (Skilling 2004)", reorder_hilbert},
      {"grid", "Castano 2009, optimal grid rendering (regular grids only)", reorder_grid},
      {"strip", "cache-unaware sequential strips with swaps, fewest vertices sent (Evans et al. 1996)", reorder_strip},
      {"nvstrip", "NvTriStrip (NVIDIA), experiments of parallel strips, pieces of K - 6 faces ordered for the cache",
       reorder_nvstrip},
      {"greedy", "Hoppe 1999, greedy strip-growing with lookahead cache simulation", reorder_greedy},
      {"local", "Hoppe 1999, local optimization (reflect/insert perturbations) of the greedy order", reorder_local},
      {"texgroup", "Yang, Mitra, Huang: faces grouped by texture region, each group by a base algorithm",
       reorder_texgroup},
      {"batch", "compact patches of 32 triangles for batch-based reuse (after Kerbl et al. 2018, NVIDIA model)",
       reorder_batch},
  };
  return algorithms;
}

const ReorderAlgorithm& find_reorder_algorithm(const std::string& name) {
  for (const ReorderAlgorithm& algorithm : reorder_algorithms())
    if (algorithm.name == name) return algorithm;
  std::string known;
  for (const ReorderAlgorithm& algorithm : reorder_algorithms()) known += (known.empty() ? "" : ", ") + algorithm.name;
  throw InputError("unknown ordering algorithm '" + name + "': expected one of " + known);
}

bool reorder_algorithm_applies(const ReorderAlgorithm& algorithm, const Mesh& mesh) {
  return algorithm.name != "grid" || mesh.grid.has_value();
}

std::vector<std::uint32_t> indices_in_face_order(const Mesh& mesh, const std::vector<std::uint32_t>& face_order) {
  std::vector<std::uint32_t> indices;
  indices.reserve(face_order.size() * 3);
  for (const std::uint32_t face : face_order)
    indices.insert(indices.end(), mesh.indices.begin() + face * 3, mesh.indices.begin() + face * 3 + 3);
  return indices;
}

Ordering list_ordering(const Mesh& mesh, std::vector<std::uint32_t> face_order) {
  Ordering ordering;
  ordering.indices = indices_in_face_order(mesh, face_order);
  ordering.face_order = std::move(face_order);
  return ordering;
}

std::vector<std::uint32_t> primitive_materials(const Mesh& mesh, const Ordering& ordering) {
  // Faces by their vertices, rotated so the smallest id comes first (the winding is kept).
  const auto key = [](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    std::array<std::uint32_t, 3> t{a, b, c};
    while (t[0] > t[1] || t[0] > t[2]) std::rotate(t.begin(), t.begin() + 1, t.end());
    return t;
  };
  std::map<std::array<std::uint32_t, 3>, std::uint32_t> material_of_face;
  for (std::size_t f = 0; f < mesh.face_count(); ++f)
    material_of_face.emplace(key(mesh.indices[3 * f], mesh.indices[3 * f + 1], mesh.indices[3 * f + 2]),
                             mesh.material_of(f));
  std::vector<std::uint32_t> materials;
  std::uint32_t previous = 0;
  for_each_triangle(
      ordering.indices, ordering.type, ordering.restart_index, [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        if (a != b && b != c && a != c) {
          const auto found = material_of_face.find(key(a, b, c));
          if (found == material_of_face.end())
            throw InputError(mesh.name + ": the ordering draws triangle (" + std::to_string(a) + ", " +
                             std::to_string(b) + ", " + std::to_string(c) + "), which is not a face of the mesh");
          previous = found->second;
        }
        materials.push_back(previous);
      });
  return materials;
}

}  // namespace rastrace

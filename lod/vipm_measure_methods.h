// Every VIPM representation of one progressive mesh, as the measurements compare them: vanilla,
// multilevel skip strips and mixed-mode (each as strips and as lists), and sliding window on
// Forsyth's relaxed order of the same collapses.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "lod/progressive_mesh.h"
#include "lod/sliding_window_relax.h"
#include "lod/vanilla.h"
#include "lod/vipm_representation.h"
#include "reorder/ordering.h"
#include "scenes/mesh.h"

namespace rastrace {

struct VipmMethodsParams {
  VipmBuildParams build;
  std::string strip_algorithm = "greedy";  // skip strips and mixed-mode as strips (Hoppe 1999: cache-aware)
  std::string list_algorithm = "tipsy";    // skip strips and mixed-mode as lists, sliding window's middle
  ReorderParams reorder;
  double new_level_fraction = 0.5;  // multilevel: degenerates (binned triangles) per level triangle
  double tolerance = 0.1;           // sliding window: of the mean collapse error
};

struct VipmMethods {
  std::vector<std::unique_ptr<VipmRepresentation>> representations;
  RelaxedOrder sliding_window_order;
  std::uint32_t sliding_window_strict_levels = 0;       // levels in the builder's own order
  std::uint32_t sliding_window_levels_tolerance_0 = 0;  // relaxed with tolerance 0 (equal or lower errors only)
};

// `vertices`: the vertex buffer in pm's numbering (reordered_mesh's result).
VipmMethods build_vipm_methods(const ProgressiveMesh& pm, const Mesh& vertices, const VipmMethodsParams& params = {});

// One representation by its method() name (vipm_representation.h), on pm as given: sliding window
// is built on pm's own order, so relax it first for Forsyth's variant. Throws std::logic_error
// for an unknown name.
std::unique_ptr<VipmRepresentation> build_vipm_representation(const std::string& method, const ProgressiveMesh& pm,
                                                              const Mesh& vertices,
                                                              const VipmMethodsParams& params = {});

}  // namespace rastrace

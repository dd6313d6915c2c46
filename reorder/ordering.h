// The one interface every reordering algorithm implements: a mesh and parameters in; a face
// order and an index stream (triangle list or strip) out. One algorithm per source file.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "cache_sim/vertex_cache.h"
#include "scenes/mesh.h"
#include "traces/events.h"

namespace rastrace {

struct ReorderParams {
  unsigned cache_size = 16;  // the post-transform cache the algorithm optimizes for
  VertexCachePolicy policy = VertexCachePolicy::Fifo;
  std::uint64_t seed = 1;
  double time_budget_seconds = 60.0;  // for iterative algorithms (local optimization)
  // local: perturbation searches (one per face position visited); 0 = until no improvement is
  // found. The primary, reproducible control; time_budget_seconds is only a safety cap.
  std::uint64_t iteration_budget = 0;
  std::string texgroup_base = "strip";    // texgroup: the algorithm ordering each group
  std::string texgroup_regions = "auto";  // texgroup: auto, quadrant, chart or texture
};

struct Ordering {
  // A permutation of the mesh's faces: face_order[i] is the i-th face drawn.
  std::vector<std::uint32_t> face_order;
  // What is sent to the GPU. A list is the faces in face_order with their original winding,
  // possibly with extra degenerate triangles (Castano's prefetch row); a strip may use
  // duplicated indices (swaps, degenerates) and restart_index.
  PrimitiveType type = PrimitiveType::TriangleList;
  std::vector<std::uint32_t> indices;
  RestartIndex restart_index = kNoRestart;
};

using ReorderFunction = Ordering (*)(const Mesh& mesh, const ReorderParams& params);

struct ReorderAlgorithm {
  std::string name;         // as typed on the command line: "tipsy"
  std::string description;  // one line, with the paper
  ReorderFunction run;
};

// Every algorithm, in the order tables list them.
const std::vector<ReorderAlgorithm>& reorder_algorithms();
// Throws InputError naming the known algorithms when `name` is not one.
const ReorderAlgorithm& find_reorder_algorithm(const std::string& name);

// The triangle list of the faces in the given order (original winding).
std::vector<std::uint32_t> indices_in_face_order(const Mesh& mesh, const std::vector<std::uint32_t>& face_order);
// An Ordering that draws the faces as a triangle list in the given order.
Ordering list_ordering(const Mesh& mesh, std::vector<std::uint32_t> face_order);

// The material of every triangle the ordering's stream assembles, degenerates included (the
// pipeline's DrawCall::primitive_materials): each drawn triangle takes the material of the mesh
// face with its vertices, a degenerate one the material before it. So a strip that runs across
// materials still draws every face with its own. Throws InputError if a triangle is not a face.
std::vector<std::uint32_t> primitive_materials(const Mesh& mesh, const Ordering& ordering);

// One line per algorithm: defined in its own file.
Ordering reorder_original(const Mesh& mesh, const ReorderParams& params);
Ordering reorder_random(const Mesh& mesh, const ReorderParams& params);
Ordering reorder_scanline(const Mesh& mesh, const ReorderParams& params);
Ordering reorder_forsyth(const Mesh& mesh, const ReorderParams& params);
Ordering reorder_tipsy(const Mesh& mesh, const ReorderParams& params);
Ordering reorder_morton(const Mesh& mesh, const ReorderParams& params);
Ordering reorder_hilbert(const Mesh& mesh, const ReorderParams& params);
Ordering reorder_grid(const Mesh& mesh, const ReorderParams& params);
Ordering reorder_strip(const Mesh& mesh, const ReorderParams& params);
Ordering reorder_greedy(const Mesh& mesh, const ReorderParams& params);
Ordering reorder_local(const Mesh& mesh, const ReorderParams& params);

// False when the algorithm cannot order this mesh: "grid" needs a make_grid grid (mesh.grid).
// Tables skip such pairs; running one anyway throws InputError.
bool reorder_algorithm_applies(const ReorderAlgorithm& algorithm, const Mesh& mesh);

}  // namespace rastrace

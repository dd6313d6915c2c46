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
  // tipsy-overdraw, front-to-back, back-to-front: Sander et al.'s lambda as a markup on the Tipsy
  // order's ACMR (a cluster is cut once its own ACMR, from a flushed cache, is below lambda times it).
  double overdraw_lambda = 1.05;
  // front-to-back, back-to-front: the direction the camera looks along (need not be unit length).
  glm::vec3 view_direction{0.0f, 0.0f, -1.0f};
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

// The algorithms, one source file each (the file names the paper and the details). Ranges are
// ACMR at FIFO 16, each ordering made for that cache, on CGAL's fandisk, triceratops and bunny00
// (12,946, 5,660 and 75,408 faces); ACMR is at least about 0.5 and a random order gives 3.0.
// Every algorithm is deterministic for a given ReorderParams (seed included). All return a
// triangle list unless said otherwise.

// The file's own order: the baseline every table starts from. ACMR 1.0-2.3 on the three meshes,
// whatever the exporter happened to do.
Ordering reorder_original(const Mesh& mesh, const ReorderParams& params);

// A uniformly random permutation (params.seed): the worst case a cache-unaware exporter could
// produce. ACMR 2.98-3.00 at FIFO 16 (every triangle misses almost all three vertices).
Ordering reorder_random(const Mesh& mesh, const ReorderParams& params);

// Rows of triangles swept one after another, the naive exporter's or height-field generator's
// order (the baseline of Castano, "Optimal grid rendering", 2009): on a make_grid grid the quads
// row by row, on any other mesh the same sweep over triangle centroids along the bounding box's
// longest axis. ACMR 1.3-1.5 on the three meshes; 1.062 on a 16x16 grid at every FIFO size 12-20.
// Cache size and policy are ignored.
Ordering reorder_scanline(const Mesh& mesh, const ReorderParams& params);

// Forsyth, "Linear-speed vertex cache optimisation", 2006: the highest-scoring triangle around
// the vertices of a 32-entry LRU model is emitted next. The model does not depend on the target
// cache (cache size and policy are ignored): one order for every GPU. ACMR 0.68-0.71. A vertex
// with more live triangles than the model has entries offers only the first 32 as candidates, so
// an edge or vertex shared by thousands of faces stays linear (no real mesh reaches 32).
Ordering reorder_forsyth(const Mesh& mesh, const ReorderParams& params);

// Tipsy: Sander, Nehab, Barczak, "Fast triangle reordering for vertex locality and reduced
// overdraw", SIGGRAPH 2007 (the vertex-locality pass). Fans around the vertex that will still be
// in a FIFO of params.cache_size entries after its fan; linear time, time stamps instead of a
// simulated cache. ACMR 0.65-0.67; the policy is ignored (the rule is defined for FIFO).
Ordering reorder_tipsy(const Mesh& mesh, const ReorderParams& params);

// Tipsy's overdraw pass (Sander, Nehab, Barczak 2007, sections 4 and 5): Tipsy's order cut into
// clusters at its dead ends (hard boundaries) and wherever a cluster's own ACMR from a flushed
// cache of params.cache_size drops below params.overdraw_lambda times the Tipsy order's ACMR (soft
// boundaries; the threshold is lowered, by bisection, until the clustered order's misses stay
// within lambda times Tipsy's), the clusters then sorted by decreasing occlusion potential
// (C(P) - C(M)) . N(P): outward-facing clusters far from the centroid first. View-independent.
// ACMR 0.68-0.70 at lambda 1.05 (Tipsy: 0.65-0.67); overdraw of the axis views
// (overdraw/view_independent.h) bunny00 1.051 -> 1.019, triceratops 1.077 -> 1.049.
Ordering reorder_tipsy_overdraw(const Mesh& mesh, const ReorderParams& params);

// The same clusters as tipsy-overdraw sorted for one view, the simple orders a user would try:
// by the depth of each cluster's centroid along params.view_direction, nearest first
// (front-to-back) or farthest first (back-to-front, the worst case for an early depth test). Best
// and worst for that view, not for others.
Ordering reorder_front_to_back(const Mesh& mesh, const ReorderParams& params);
Ordering reorder_back_to_front(const Mesh& mesh, const ReorderParams& params);

// K-Cache-Reorder (Lin and Yu 2006) is declared, with its documentation, in reorder/kcache.h.

// Faces sorted by the Morton (Z-order) or Hilbert (Skilling, "Programming the Hilbert curve",
// 2004) index of their centroid over the mesh's bounding box: cache-oblivious, blind to
// connectivity; Castano 2009 uses both as baselines. ACMR 0.86-0.92 for either. Cache size and
// policy are ignored.
Ordering reorder_morton(const Mesh& mesh, const ReorderParams& params);
Ordering reorder_hilbert(const Mesh& mesh, const ReorderParams& params);

// Castano, "Optimal grid rendering", 2009: columns of at most cache_size - 2 quads, each column's
// first vertex row prefetched with degenerate triangles when it does not fit. Only for make_grid
// grids (see reorder_algorithm_applies; InputError otherwise). 16x16 grid: ACMR 0.564 (every
// vertex once) at FIFO 20, 0.598 at 16 and 12.
Ordering reorder_grid(const Mesh& mesh, const ReorderParams& params);

// A cache-unaware stripifier minimizing the vertices sent, after Evans, Skiena, Varshney,
// "Optimizing triangle strips for fast rendering", IEEE Visualization 1996, and NvTriStrip. A
// TriangleStrip with restarts (strip.h). 1.12-1.21 vertices sent per triangle (triceratops: 6,820
// for 5,660 triangles, where Yang, Mitra, Huang, "Improving rendering by texture map-based
// triangle strips", print 6,911 for Evans et al.'s strips), indices per triangle b 1.15-1.27;
// ACMR 1.00-1.02, since nothing keeps a strip's vertices for the next strip. The parameters are
// unused.
Ordering reorder_strip(const Mesh& mesh, const ReorderParams& params);

// Hoppe, "Optimization of mesh locality for transparent vertex caching", SIGGRAPH 1999,
// section 5: strips grown with lookahead simulations of the params.cache_size cache (FIFO or
// LRU) deciding when to restart (greedy.h). A TriangleStrip with restarts. ACMR 0.63-0.69,
// b 1.38-1.54.
Ordering reorder_greedy(const Mesh& mesh, const ReorderParams& params);

// Hoppe 1999, section 6: the greedy order improved by local perturbations (reflections and
// insertions) of Hoppe's cost, 32 bytes per miss plus 6 per strip (local_opt.h). A TriangleStrip with
// restarts. params.iteration_budget bounds the work reproducibly, params.time_budget_seconds as
// a safety cap. ACMR 0.598-0.643, 4-7% below greedy; FIFO only (for LRU the greedy order).
Ordering reorder_local(const Mesh& mesh, const ReorderParams& params);

// For the batch-based reuse of current GPUs (Kerbl, Kenzel, Ivanchenko, Schmalstieg, Steinberger,
// "Revisiting the Vertex Cache", HPG 2018): batches grown greedily under their NVIDIA model
// (cache_sim/kerbl_batch.h, preset kerbl-nv), each next triangle the one adding the fewest shader
// invocations to the open batch, so each batch of 32 triangles is a compact patch. Cache size and
// policy are ignored. FIFO 16 is not its measure: see docs/PERFORMANCE.md for it against the
// FIFO-tuned orders under every preset.
Ordering reorder_batch(const Mesh& mesh, const ReorderParams& params);

// False when the algorithm cannot order this mesh: "grid" needs a make_grid grid (mesh.grid).
// Tables skip such pairs; running one anyway throws InputError.
bool reorder_algorithm_applies(const ReorderAlgorithm& algorithm, const Mesh& mesh);

}  // namespace rastrace

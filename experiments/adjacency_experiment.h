// The adjacency-primitive evaluation behind `rastrace adjacency`: triangle-with-adjacency
// primitives (Sander, Nehab, Chlamtac, Hoppe 2008). Builds the cover, its lower bound and the
// restricted assignment, orders the primitives, and makes one table row per ordering: faces, dual
// edges, |C| (and % of faces), B, C/B, primitives and indices per face, misses and CM/V in a FIFO
// post-transform cache, and three gains (baseline misses / the row's misses): `gain` over
// `baseline` (kcache on the cover faces alone), `gain_mesh` over `baseline-mesh` (kcache on all
// the mesh's faces, each primitive drawn at its first face: the paper's naive use of a triangle
// method) and `gain_naive` over the naive scheme (one primitive per face, faces in kcache's
// order), whose row can be added for comparison. With edges, each ordering is drawn through the pipeline with the edge
// stage (pipeline/edge_stage.h), from a camera that frames the mesh, and its counts are added.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "core/table.h"
#include "pipeline/edge_stage.h"
#include "pipeline/pipeline.h"
#include "raster/framebuffer.h"
#include "reorder/adjacency/order.h"
#include "scenes/mesh.h"

namespace rastrace {

struct MeshView {
  glm::mat4 view{1.0f}, projection{1.0f};
};

// Looks at the mesh's bounding-box centre from `direction`, far enough to see all of it, with a
// 45-degree vertical field of view (as the OSMesa cross-check of the edge stage does).
MeshView frame_mesh(const Mesh& mesh, glm::vec3 direction, float aspect);

struct EdgeDraw {
  PipelineStats pipeline;
  EdgeStageStats edges;
  // With stage.record: every processed edge and face (EdgeStage::edges, EdgeStage::faces).
  std::vector<ProcessedEdge> processed;
  std::vector<std::array<std::uint32_t, 3>> faces;
};

// Draws the adjacency primitives (GL_TRIANGLES_ADJACENCY indices) through the pipeline with the
// edge stage attached, into `lines` when it is not null. The viewport is the line image's size,
// or viewport x viewport pixels without one (the counts do not depend on it).
EdgeDraw draw_edge_stage(const Mesh& mesh, std::span<const std::uint32_t> indices, const MeshView& camera,
                         const EdgeStageOptions& stage, unsigned cache_entries, Framebuffer* lines, int viewport = 64);

struct AdjacencyExperiment {
  std::string mesh_spec;  // how the mesh was named, for the table's parameters
  unsigned cache = 24;    // FIFO post-transform cache entries
  std::vector<AdjacencyOrder> orders;
  bool naive = false;  // add the naive scheme's row
  std::uint64_t seed = 1;
  std::int64_t iterations = -1;  // local-search iterations of the cover; -1: 20 per face
  bool edges = false;            // draw each ordering through the edge stage
  int size = 512;                // the edge stage's square viewport
  bool with_time = true;         // run times differ between runs: leave them out for identical tables
};

struct AdjacencyResult {
  Table table;
  std::string first_order;  // the first row's ordering and its index buffer
  std::vector<std::uint32_t> first_indices;
};

// `lines` (size x size, or null): the first edge-stage row draws its silhouette, sharp and
// boundary lines into it. Throws InputError for a mesh without faces or a cache of 0 entries.
AdjacencyResult run_adjacency_experiment(const Mesh& mesh, const AdjacencyExperiment& experiment, Framebuffer* lines);

}  // namespace rastrace

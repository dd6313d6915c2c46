#include "experiments/adjacency_experiment.h"

#include <algorithm>
#include <chrono>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "cache_sim/vertex_cache.h"
#include "core/error.h"
#include "reorder/adjacency/bound.h"
#include "reorder/adjacency/build.h"
#include "reorder/ordering.h"
#include "scenes/bounding_box.h"

namespace rastrace {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

MeshView frame_mesh(const Mesh& mesh, glm::vec3 direction, float aspect) {
  const BoundingBox box = bounding_box(mesh.positions);
  const glm::vec3 centre = box.centre();
  const float radius = std::max(0.5f * glm::length(box.extent()), 1e-6f);
  const glm::vec3 eye = centre + glm::normalize(direction) * radius * 2.6f;
  MeshView camera;
  camera.view = glm::lookAt(eye, centre, glm::vec3(0, 1, 0));
  camera.projection = glm::perspective(glm::radians(45.0f), aspect, radius * 0.5f, radius * 6.0f);
  return camera;
}

EdgeDraw draw_edge_stage(const Mesh& mesh, std::span<const std::uint32_t> indices, const MeshView& camera,
                         const EdgeStageOptions& stage_options, unsigned cache_entries, Framebuffer* lines,
                         int viewport) {
  Framebuffer scratch(lines ? lines->width() : viewport, lines ? lines->height() : viewport);
  PipelineOptions options;
  options.cache_entries = cache_entries;
  Pipeline pipeline(scratch, options, nullptr);
  pipeline.set_camera(camera.view, camera.projection);
  EdgeStage stage(mesh, stage_options, lines);
  pipeline.set_primitive_hook(&stage);
  DrawCall call;
  call.indices = indices;
  call.type = PrimitiveType::TriangleListAdjacency;
  pipeline.draw(mesh, glm::mat4(1.0f), call, {});
  pipeline.finish();
  return {pipeline.stats(), stage.stats(), stage.edges(), stage.faces()};
}

AdjacencyResult run_adjacency_experiment(const Mesh& mesh, const AdjacencyExperiment& experiment, Framebuffer* lines) {
  if (experiment.cache == 0) throw InputError("--cache 0: a vertex cache needs at least 1 entry");
  if (mesh.face_count() == 0) throw InputError(experiment.mesh_spec + ": the mesh has no faces");

  CoverParams params;
  params.seed = experiment.seed;
  params.max_iterations = experiment.iterations;
  const AdjacencyBuild build = build_adjacency_primitives(mesh, params);
  const CoverBound bound = adjacency_cover_lower_bound(mesh, build.dual);
  const std::uint32_t F = build.dual.face_count;
  const double vertices = double(mesh.vertex_count());

  auto misses_of = [&](const AdjacencyPrimitives& primitives) {
    return simulate_vertex_stream(primitives.indices, PrimitiveType::TriangleListAdjacency, VertexCachePolicy::Fifo,
                                  experiment.cache)
        .misses;
  };
  // The gains are always against all three baselines, even when they are not printed.
  auto start = std::chrono::steady_clock::now();
  const AdjacencyPrimitives baseline = permute_primitives(
      build.primitives, order_adjacency(AdjacencyOrder::Baseline, mesh, build.primitives, experiment.cache));
  const double baseline_seconds = seconds_since(start);
  const double baseline_misses = double(misses_of(baseline));
  start = std::chrono::steady_clock::now();
  const AdjacencyPrimitives baseline_mesh = permute_primitives(
      build.primitives, order_adjacency(AdjacencyOrder::BaselineMesh, mesh, build.primitives, experiment.cache));
  const double baseline_mesh_seconds = seconds_since(start);
  const double baseline_mesh_misses = double(misses_of(baseline_mesh));
  // The naive scheme: a primitive per face, faces ordered by kcache.
  start = std::chrono::steady_clock::now();
  ReorderParams reorder_params;
  reorder_params.cache_size = experiment.cache;
  const Ordering naive_faces = find_reorder_algorithm("kcache").run(mesh, reorder_params);
  const AdjacencyPrimitives naive =
      permute_primitives(encode_one_primitive_per_face(mesh, build.dual), naive_faces.face_order);
  const double naive_seconds = seconds_since(start);
  const double naive_misses = double(misses_of(naive));

  AdjacencyResult result;
  Table& table = result.table;
  table.title = "Adjacency primitives (Sander et al. 2008): " + mesh.name;
  table.parameters = {{"mesh", experiment.mesh_spec},
                      {"mesh_vertices", mesh.vertex_count()},
                      {"cache", experiment.cache},
                      {"policy", "fifo"},
                      {"seed", static_cast<std::int64_t>(experiment.seed)},
                      {"cover_iterations", static_cast<std::int64_t>(build.cover.iterations)},
                      {"gain_over", "baseline (kcache on the cover faces alone)"},
                      {"gain_mesh_over", "baseline-mesh (kcache on all mesh faces, each primitive at its first face)"},
                      {"gain_naive_over", "naive (one primitive per face, faces in kcache's order)"}};
  table.columns = {{"order", "order", 0},
                   {"faces", "faces", 0},
                   {"dual_edges", "dual edges", 0},
                   {"cover", "C", 0},
                   {"cover_percent", "% faces", 1},
                   {"lower_bound", "B", 1},
                   {"c_over_b", "C/B", 3},
                   {"primitives", "primitives", 0},
                   {"indices_per_face", "indices/face", 3},
                   {"misses", "misses", 0},
                   {"cm_per_v", "CM/V", 3},
                   {"gain", "gain", 3},
                   {"gain_mesh", "gain mesh", 3},
                   {"gain_naive", "gain naive", 3}};
  const bool edges = experiment.edges;
  const MeshView camera = frame_mesh(mesh, glm::vec3(0.3f, 0.2f, 1.0f), 1.0f);
  EdgeStageOptions stage;
  stage.draw_sharp = true;
  if (edges) {
    table.parameters.push_back({"view", "bounding box from (0.3, 0.2, 1), 45 degrees"});
    table.parameters.push_back({"sharp_degrees", 60.0});
    table.columns.push_back({"shader_invocations", "VS invocations", 0});
    table.columns.push_back({"faces_processed", "faces processed", 0});
    table.columns.push_back({"edges_processed", "edges processed", 0});
    table.columns.push_back({"silhouette_edges", "silhouettes", 0});
    table.columns.push_back({"sharp_edges", "sharp", 0});
  }
  if (experiment.with_time) {
    table.columns.push_back({"cover_seconds", "cover s", 3});
    table.columns.push_back({"assignment_seconds", "assignment s", 3});
    table.columns.push_back({"order_seconds", "order s", 4});
  }
  const double cover_size = build.cover.size;
  bool first_row = true;
  auto add_row = [&](const std::string& name, const AdjacencyPrimitives& primitives, double misses, double seconds) {
    std::vector<TableCell> row = {name,
                                  F,
                                  build.dual.dual_edge_count,
                                  build.cover.size,
                                  100.0 * cover_size / F,
                                  bound.bound,
                                  bound.bound > 0 ? cover_size / bound.bound : 0.0,
                                  primitives.size(),
                                  6.0 * double(primitives.size()) / F,
                                  static_cast<std::uint64_t>(misses),
                                  misses / vertices,
                                  misses > 0 ? baseline_misses / misses : 0.0,
                                  misses > 0 ? baseline_mesh_misses / misses : 0.0,
                                  misses > 0 ? naive_misses / misses : 0.0};
    if (edges) {
      if (name == "naive") {
        // One primitive per face has no assigned faces and sees every interior edge twice: the
        // edge stage's reading does not apply.
        row.insert(row.end(), 5, TableCell{});
      } else {
        const EdgeDraw run = draw_edge_stage(mesh, primitives.indices, camera, stage, experiment.cache,
                                             first_row ? lines : nullptr, experiment.size);
        row.insert(row.end(), {run.pipeline.vertices_shaded, run.edges.faces(), run.edges.edges,
                               run.edges.silhouette_edges, run.edges.sharp_edges});
        first_row = false;
      }
    }
    if (experiment.with_time) {
      row.emplace_back(build.cover.seconds);
      row.emplace_back(build.assignment.seconds);
      row.emplace_back(seconds);
    }
    table.add_row(std::move(row));
  };

  for (const AdjacencyOrder order : experiment.orders) {
    if (order == AdjacencyOrder::Baseline || order == AdjacencyOrder::BaselineMesh) {
      const bool on_covers = order == AdjacencyOrder::Baseline;
      const AdjacencyPrimitives& ordered = on_covers ? baseline : baseline_mesh;
      add_row(to_string(order), ordered, on_covers ? baseline_misses : baseline_mesh_misses,
              on_covers ? baseline_seconds : baseline_mesh_seconds);
      if (result.first_indices.empty()) {
        result.first_indices = ordered.indices;
        result.first_order = to_string(order);
      }
      continue;
    }
    start = std::chrono::steady_clock::now();
    const std::vector<std::uint32_t> permutation = order_adjacency(order, mesh, build.primitives, experiment.cache);
    const double seconds = seconds_since(start);
    const AdjacencyPrimitives ordered = permute_primitives(build.primitives, permutation);
    add_row(to_string(order), ordered, double(misses_of(ordered)), seconds);
    if (result.first_indices.empty()) {
      result.first_indices = ordered.indices;
      result.first_order = to_string(order);
    }
  }
  if (experiment.naive) add_row("naive", naive, naive_misses, naive_seconds);
  return result;
}

}  // namespace rastrace

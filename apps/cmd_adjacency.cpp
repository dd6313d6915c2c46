// `rastrace adjacency MESH [--cache 24] [--order careful|fast|baseline|baseline-mesh|all] [--seed N]
//  [--iterations N] [--format md|csv|latex|json] [-o FILE] [--no-time]`: triangle-with-adjacency
// primitives (Sander, Nehab, Chlamtac, Hoppe 2008). Builds the cover, its lower bound and the
// restricted assignment, orders the primitives, and prints one row per ordering: faces, dual
// edges, |C| (and % of faces), B, C/B, primitives and indices per face, misses and CM/V in a FIFO
// post-transform cache, and two gains (baseline misses / the row's misses): `gain` over
// `baseline` (kcache on the cover faces alone, issue 7's definition) and `gain_mesh` over
// `baseline-mesh` (kcache on all the mesh's faces, each primitive drawn at its first face: the
// paper's naive use of a triangle method). `--order all` adds the naive scheme (one primitive
// per face, ordered by kcache) for comparison.
// -o writes the index buffer of the first ordering: raw little-endian uint32 for a .bin file,
// otherwise text, one 6-index primitive per line. --edges draws each ordering through the
// pipeline with the edge stage (pipeline/edge_stage.h) and adds its counts; --lines writes the
// first ordering's line image.
#include <algorithm>
#include <chrono>
#include <cstring>
#include <iostream>
#include <limits>
#include <memory>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "apps/commands.h"
#include "apps/mesh_spec.h"
#include "cache_sim/vertex_cache.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/table.h"
#include "pipeline/edge_stage.h"
#include "pipeline/pipeline.h"
#include "raster/framebuffer.h"
#include "reorder/adjacency/bound.h"
#include "reorder/adjacency/build.h"
#include "reorder/adjacency/order.h"
#include "reorder/ordering.h"

namespace rastrace {
namespace {

struct AdjacencyOptions {
  std::string mesh;
  unsigned cache = 24;
  std::string order = "all";
  std::uint64_t seed = 1;
  std::int64_t iterations = -1;
  std::string format = "md";
  std::string output;
  std::string lines;  // silhouette image of the first ordering
  bool edges = false;
  int size = 512;
  bool no_time = false;
};

// The mesh framed from the front-right-top, as the OSMesa cross-check does.
void frame_mesh(const Mesh& mesh, glm::mat4& view, glm::mat4& projection) {
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  for (const glm::vec3& p : mesh.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const glm::vec3 centre = 0.5f * (lo + hi);
  const float radius = std::max(0.5f * glm::length(hi - lo), 1e-6f);
  const glm::vec3 eye = centre + glm::normalize(glm::vec3(0.3f, 0.2f, 1.0f)) * radius * 2.6f;
  view = glm::lookAt(eye, centre, glm::vec3(0, 1, 0));
  projection = glm::perspective(glm::radians(45.0f), 1.0f, radius * 0.5f, radius * 6.0f);
}

// Draws the primitives through the pipeline with the edge stage attached.
struct EdgeRun {
  PipelineStats pipeline;
  EdgeStageStats stage;
};
EdgeRun run_edge_stage(const Mesh& mesh, const AdjacencyPrimitives& primitives, unsigned cache, int size,
                       Framebuffer* lines) {
  glm::mat4 view, projection;
  frame_mesh(mesh, view, projection);
  Framebuffer scratch(size, size);
  PipelineOptions options;
  options.cache_entries = cache;
  Pipeline pipeline(scratch, options, nullptr);
  pipeline.set_camera(view, projection);
  EdgeStageOptions stage_options;
  stage_options.draw_sharp = true;
  EdgeStage stage(mesh, stage_options, lines);
  pipeline.set_primitive_hook(&stage);
  DrawCall call;
  call.indices = primitives.indices;
  call.type = PrimitiveType::TriangleListAdjacency;
  pipeline.draw(mesh, glm::mat4(1.0f), call, {});
  pipeline.finish();
  return {pipeline.stats(), stage.stats()};
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void write_index_buffer(const std::string& path, const std::vector<std::uint32_t>& indices, const std::string& header) {
  const bool binary = path.size() >= 4 && path.compare(path.size() - 4, 4, ".bin") == 0;
  write_file_atomically(
      path,
      [&](std::ostream& out) {
        if (binary) {
          for (const std::uint32_t index : indices) {
            const unsigned char bytes[4] = {static_cast<unsigned char>(index), static_cast<unsigned char>(index >> 8),
                                            static_cast<unsigned char>(index >> 16),
                                            static_cast<unsigned char>(index >> 24)};
            out.write(reinterpret_cast<const char*>(bytes), 4);
          }
          return;
        }
        out << "# " << header << "\n";
        for (std::size_t i = 0; i < indices.size(); i += 6)
          out << indices[i] << ' ' << indices[i + 1] << ' ' << indices[i + 2] << ' ' << indices[i + 3] << ' '
              << indices[i + 4] << ' ' << indices[i + 5] << '\n';
      },
      binary);
}

void run_adjacency(const AdjacencyOptions& options) {
  const TableFormat format = parse_table_format(options.format);
  if (options.cache == 0) throw InputError("--cache 0: a vertex cache needs at least 1 entry");
  if (options.size < 16 || options.size > 8192)
    throw InputError("--size " + std::to_string(options.size) + ": expected 16..8192");
  std::vector<AdjacencyOrder> orders;
  if (options.order == "all")
    orders = {AdjacencyOrder::Careful, AdjacencyOrder::Fast, AdjacencyOrder::Baseline, AdjacencyOrder::BaselineMesh};
  else if (options.order == "careful" || options.order == "fast" || options.order == "baseline" ||
           options.order == "baseline-mesh")
    orders = {parse_adjacency_order(options.order)};
  else
    throw InputError("--order '" + options.order + "': expected careful, fast, baseline, baseline-mesh or all");
  const Mesh mesh = load_mesh_spec(options.mesh);
  if (mesh.face_count() == 0) throw InputError(options.mesh + ": the mesh has no faces");

  CoverParams params;
  params.seed = options.seed;
  params.max_iterations = options.iterations;
  const AdjacencyBuild build = build_adjacency_primitives(mesh, params);
  const CoverBound bound = adjacency_cover_lower_bound(mesh, build.dual);
  const std::uint32_t F = build.dual.face_count;
  const double vertices = double(mesh.vertex_count());

  auto misses_of = [&](const AdjacencyPrimitives& primitives) {
    return simulate_vertex_stream(primitives.indices, PrimitiveType::TriangleListAdjacency, VertexCachePolicy::Fifo,
                                  options.cache)
        .misses;
  };
  // The gains are always against both baselines, even when they are not printed.
  auto start = std::chrono::steady_clock::now();
  const AdjacencyPrimitives baseline = permute_primitives(
      build.primitives, order_adjacency(AdjacencyOrder::Baseline, mesh, build.primitives, options.cache));
  const double baseline_seconds = seconds_since(start);
  const double baseline_misses = double(misses_of(baseline));
  start = std::chrono::steady_clock::now();
  const AdjacencyPrimitives baseline_mesh = permute_primitives(
      build.primitives, order_adjacency(AdjacencyOrder::BaselineMesh, mesh, build.primitives, options.cache));
  const double baseline_mesh_seconds = seconds_since(start);
  const double baseline_mesh_misses = double(misses_of(baseline_mesh));

  Table table;
  table.title = "Adjacency primitives (Sander et al. 2008): " + mesh.name;
  table.parameters = {{"mesh", options.mesh},
                      {"mesh_vertices", mesh.vertex_count()},
                      {"cache", options.cache},
                      {"policy", "fifo"},
                      {"seed", static_cast<std::int64_t>(options.seed)},
                      {"cover_iterations", static_cast<std::int64_t>(build.cover.iterations)},
                      {"gain_over", "baseline (kcache on the cover faces alone)"},
                      {"gain_mesh_over", "baseline-mesh (kcache on all mesh faces, each primitive at its first face)"}};
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
                   {"gain_mesh", "gain mesh", 3}};
  const bool edges = options.edges || !options.lines.empty();
  if (edges) {
    table.parameters.push_back({"view", "bounding box from (0.3, 0.2, 1), 45 degrees"});
    table.parameters.push_back({"sharp_degrees", 60.0});
    table.columns.push_back({"shader_invocations", "VS invocations", 0});
    table.columns.push_back({"faces_processed", "faces processed", 0});
    table.columns.push_back({"edges_processed", "edges processed", 0});
    table.columns.push_back({"silhouette_edges", "silhouettes", 0});
    table.columns.push_back({"sharp_edges", "sharp", 0});
  }
  std::unique_ptr<Framebuffer> line_image;
  if (!options.lines.empty()) {
    line_image = std::make_unique<Framebuffer>(options.size, options.size);
    line_image->clear(glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
  }
  if (!options.no_time) {
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
                                  misses > 0 ? baseline_mesh_misses / misses : 0.0};
    if (edges) {
      if (name == "naive") {
        // One primitive per face has no assigned faces and sees every interior edge twice: the
        // edge stage's reading does not apply.
        row.insert(row.end(), 5, TableCell{});
      } else {
        const EdgeRun run =
            run_edge_stage(mesh, primitives, options.cache, options.size, first_row ? line_image.get() : nullptr);
        row.insert(row.end(), {run.pipeline.vertices_shaded, run.stage.faces(), run.stage.edges,
                               run.stage.silhouette_edges, run.stage.sharp_edges});
        first_row = false;
      }
    }
    if (!options.no_time) {
      row.emplace_back(build.cover.seconds);
      row.emplace_back(build.assignment.seconds);
      row.emplace_back(seconds);
    }
    table.add_row(std::move(row));
  };

  std::vector<std::uint32_t> first_indices;
  std::string first_name;
  for (const AdjacencyOrder order : orders) {
    if (order == AdjacencyOrder::Baseline || order == AdjacencyOrder::BaselineMesh) {
      const bool on_covers = order == AdjacencyOrder::Baseline;
      const AdjacencyPrimitives& ordered = on_covers ? baseline : baseline_mesh;
      add_row(to_string(order), ordered, on_covers ? baseline_misses : baseline_mesh_misses,
              on_covers ? baseline_seconds : baseline_mesh_seconds);
      if (first_indices.empty()) {
        first_indices = ordered.indices;
        first_name = to_string(order);
      }
      continue;
    }
    start = std::chrono::steady_clock::now();
    const std::vector<std::uint32_t> permutation = order_adjacency(order, mesh, build.primitives, options.cache);
    const double seconds = seconds_since(start);
    const AdjacencyPrimitives ordered = permute_primitives(build.primitives, permutation);
    add_row(to_string(order), ordered, double(misses_of(ordered)), seconds);
    if (first_indices.empty()) {
      first_indices = ordered.indices;
      first_name = to_string(order);
    }
  }
  if (options.order == "all") {
    // The naive scheme: a primitive per face, faces ordered by kcache.
    start = std::chrono::steady_clock::now();
    ReorderParams reorder_params;
    reorder_params.cache_size = options.cache;
    const Ordering faces = find_reorder_algorithm("kcache").run(mesh, reorder_params);
    const AdjacencyPrimitives naive =
        permute_primitives(encode_one_primitive_per_face(mesh, build.dual), faces.face_order);
    add_row("naive", naive, double(misses_of(naive)), seconds_since(start));
  }
  std::cout << render_table(table, format);
  if (line_image) line_image->write_colour(options.lines);
  if (!options.output.empty())
    write_index_buffer(options.output, first_indices,
                       "GL_TRIANGLES_ADJACENCY index buffer of " + mesh.name + ", order " + first_name + ", " +
                           std::to_string(first_indices.size() / 6) + " primitives");
}

}  // namespace

void add_adjacency_command(CLI::App& app) {
  CLI::App* command = app.add_subcommand(
      "adjacency", "Triangle-with-adjacency primitives for edge processing (Sander et al. 2008): cover, bound, orders");
  auto options = std::make_shared<AdjacencyOptions>();
  command->add_option("mesh", options->mesh, "Mesh file, builtin:<scene> or grid:WxH")->required();
  command->add_option("--cache", options->cache, "FIFO post-transform cache entries")->capture_default_str();
  command->add_option("--order", options->order, "careful, fast, baseline, baseline-mesh or all")
      ->capture_default_str();
  command->add_option("--seed", options->seed, "Seed of the cover's local search")->capture_default_str();
  command->add_option("--iterations", options->iterations,
                      "Local-search iterations for the cover (default: 20 per face)");
  command->add_option("--format", options->format, "md, csv, latex or json")->capture_default_str();
  command->add_option("-o,--output", options->output,
                      "Write the index buffer of the first ordering (.bin: uint32 little-endian; else text)");
  command->add_flag("--edges", options->edges,
                    "Draw each ordering through the pipeline's edge stage: shader invocations, faces and "
                    "edges processed, silhouette and sharp (60 degree) edges");
  command->add_option("--lines", options->lines, "Write the first ordering's silhouette/sharp/boundary lines (PNG)");
  command->add_option("--size", options->size, "Image size for --edges/--lines (square)")->capture_default_str();
  command->add_flag("--no-time", options->no_time, "Leave out the timing columns so outputs compare byte for byte");
  command->footer(
      "Examples:\n"
      "  rastrace adjacency data/meshes/bunny00.off\n"
      "  rastrace adjacency data/meshes/fandisk.off --order fast --cache 12 --format json\n"
      "  rastrace adjacency data/meshes/triceratops.off --order careful -o triceratops.adj.bin\n"
      "  rastrace adjacency data/meshes/bunny00.off --order fast --edges --lines bunny-silhouette.png");
  command->callback([options] { run_adjacency(*options); });
}

}  // namespace rastrace

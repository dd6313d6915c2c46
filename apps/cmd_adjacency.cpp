// `rastrace adjacency MESH [--cache entries=24] [--order careful|fast|baseline|baseline-mesh|all] [--seed N]
//  [--iterations N] [--format md|csv|latex|json] [-o FILE] [--no-time]`: triangle-with-adjacency
// primitives (Sander, Nehab, Chlamtac, Hoppe 2008), one table row per ordering
// (experiments/adjacency_experiment.h). `--order all` adds the naive scheme (one primitive per
// face, ordered by kcache) for comparison.
// -o writes the index buffer of the first ordering: raw little-endian uint32 for a .bin file,
// otherwise text, one 6-index primitive per line. --edges draws each ordering through the
// pipeline with the edge stage (pipeline/edge_stage.h) and adds its counts; --lines writes the
// first ordering's line image.
#include <iostream>
#include <memory>

#include "apps/commands.h"
#include "apps/option_checks.h"
#include "cache_sim/cache_spec.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/table.h"
#include "experiments/adjacency_experiment.h"
#include "scenes/mesh_spec.h"

namespace rastrace {
namespace {

struct AdjacencyOptions {
  std::string mesh;
  std::string cache_spec = "entries=24";
  unsigned cache = 24;  // from cache_spec
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

  AdjacencyExperiment experiment;
  experiment.mesh_spec = options.mesh;
  experiment.cache = options.cache;
  experiment.orders = orders;
  experiment.naive = options.order == "all";
  experiment.seed = options.seed;
  experiment.iterations = options.iterations;
  experiment.edges = options.edges || !options.lines.empty();
  experiment.size = options.size;
  experiment.with_time = !options.no_time;
  std::unique_ptr<Framebuffer> line_image;
  if (!options.lines.empty()) {
    line_image = std::make_unique<Framebuffer>(options.size, options.size);
    line_image->clear(glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
  }
  const AdjacencyResult result = run_adjacency_experiment(mesh, experiment, line_image.get());
  std::cout << render_table(result.table, format);
  if (line_image) line_image->write_colour(options.lines);
  if (!options.output.empty())
    write_index_buffer(options.output, result.first_indices,
                       "GL_TRIANGLES_ADJACENCY index buffer of " + mesh.name + ", order " + result.first_order + ", " +
                           std::to_string(result.first_indices.size() / 6) + " primitives");
}

}  // namespace

void add_adjacency_command(CLI::App& app) {
  CLI::App* command = app.add_subcommand(
      "adjacency", "Triangle-with-adjacency primitives for edge processing (Sander et al. 2008): cover, bound, orders");
  auto options = std::make_shared<AdjacencyOptions>();
  command->add_option("mesh", options->mesh, "Mesh file, builtin:<scene> or grid:WxH")->required();
  command->add_option("--cache", options->cache_spec, "FIFO post-transform cache (cache spec, README): entries=N")
      ->capture_default_str();
  command->add_option("--order", options->order, "careful, fast, baseline, baseline-mesh or all")
      ->capture_default_str();
  command->add_option("--seed", options->seed, "Seed of the cover's local search")->check(whole_number(0, 9223372036854775807))->capture_default_str();
  command->add_option("--iterations", options->iterations,
                      "Local-search iterations for the cover (default: 20 per face)")->check(whole_number(0, 100000000));
  command->add_option("--format", options->format, "md, csv, latex or json")->capture_default_str();
  command->add_option("-o,--output", options->output,
                      "Write the index buffer of the first ordering (.bin: uint32 little-endian; else text)");
  command->add_flag("--edges", options->edges,
                    "Draw each ordering through the pipeline's edge stage: shader invocations, faces and "
                    "edges processed, silhouette and sharp (60 degree) edges");
  command->add_option("--lines", options->lines, "Write the first ordering's silhouette/sharp/boundary lines (PNG)");
  command->add_option("--size", options->size, "Image size for --edges/--lines (square)")->check(whole_number(1, 16384))->capture_default_str();
  command->add_flag("--no-time", options->no_time, "Leave out the timing columns so outputs compare byte for byte");
  command->footer(
      "Examples:\n"
      "  rastrace adjacency data/meshes/bunny00.off\n"
      "  rastrace adjacency data/meshes/fandisk.off --order fast --cache entries=12 --format json\n"
      "  rastrace adjacency data/meshes/triceratops.off --order careful -o triceratops.adj.bin\n"
      "  rastrace adjacency data/meshes/bunny00.off --order fast --edges --lines bunny-silhouette.png");
  command->callback([options] {
    const VertexCacheSpec cache = parse_vertex_cache(options->cache_spec, "--cache");
    if (cache.batched())
      throw InputError("--cache '" + options->cache_spec + "': the adjacency orders and CM/V are defined for a FIFO " +
                       "shared by the draw, not for warp or batch models: write entries=N,policy=fifo (compare " +
                       "orders under batch models with rastrace vcache --model all)");
    if (cache.policy != VertexCachePolicy::Fifo)
      throw InputError("--cache '" + options->cache_spec + "': the adjacency orders and CM/V are defined for FIFO: " +
                       "write entries=" + std::to_string(cache.entries) + ",policy=fifo");
    options->cache = cache.entries;
    run_adjacency(*options);
  });
}

}  // namespace rastrace

// `rastrace vcache MESH --algo all|a,b,c --cache entries=8/12/16/20/24/32,policy=fifo/lru [--target K]
//  --format md|csv|latex|json [--no-time] [--accounting misses|evictions] [--vertex-bytes 32] [--fetch meshopt|SPEC]
//  [--miss-image FILE]`: the post-transform vertex cache and the vertex-buffer fetch under every ordering.
// One row per algorithm, policy and cache size: ACMR, ATVR, misses, indices per triangle, Hoppe's
// bandwidth (ACMR * 32 + indices per triangle * 2 bytes per triangle, restart indices counted) and
// the ordering's run time. --miss-image writes the mesh with each face coloured by its misses.
// With reuse models (--model all, or model=/warp=/primgroup= in --cache) one row per algorithm and
// model with warps and lane use, then (text formats) ACMR pivoted by model; --plot draws it.
// An algorithm orders for the simulated cache unless --target fixes the size it orders for.
#include <algorithm>
#include <iostream>
#include <memory>

#include "apps/commands.h"
#include "apps/option_checks.h"
#include "cache_sim/cache_spec.h"
#include "cache_sim/vertex_fetch.h"
#include "core/error.h"
#include "experiments/vcache_table.h"
#include "scenes/mesh_spec.h"

namespace rastrace {

namespace {

struct VcacheOptions {
  std::string mesh;
  std::string algorithms = "all";
  std::string cache = "entries=8/12/16/20/24/32,policy=fifo";
  std::string old_policy;  // --policy, replaced by the cache spec's policy key
  unsigned target = 0;     // 0: the simulated size
  std::uint64_t seed = 1;
  double time_budget = 60.0;
  std::string format = "md";
  bool no_time = false;
  std::string accounting = "misses";
  std::uint32_t vertex_bytes = 32;
  std::string fetch = "meshopt";
  std::string miss_image;
  std::string model;  // reuse-model presets: the same as --cache model=...
  std::string plot;
};

void run_vcache(const VcacheOptions& options) {
  const TableFormat format = parse_table_format(options.format);
  VcacheTableSpec spec;
  spec.algorithms = options.algorithms;
  if (!options.old_policy.empty()) {
    std::string policies = options.old_policy;
    std::replace(policies.begin(), policies.end(), ',', '/');
    throw InputError("--policy '" + options.old_policy + "': write the policy in the cache spec, e.g. --cache " +
                     "entries=12/16,policy=" + policies);
  }
  std::string cache_text = options.cache;
  if (!options.model.empty()) {
    std::string models = options.model;
    std::replace(models.begin(), models.end(), ',', '/');
    cache_text = "model=" + models;
  }
  const CacheSpec cache = parse_cache_spec(cache_text, options.model.empty() ? "--cache" : "--model");
  if (cache.kind != CacheKind::Vertex)
    throw InputError("--cache '" + options.cache + "': vcache simulates post-transform vertex caches: expected " +
                     "entries=...,policy=..., e.g. entries=12/16,policy=fifo/lru");
  spec.caches = cache.entries;
  spec.policies = cache.vertex_policies;
  const std::vector<VertexCacheSpec> models = vertex_caches(cache);
  if (std::any_of(models.begin(), models.end(), [](const VertexCacheSpec& m) { return m.batched() || !m.preset.empty(); }))
    spec.models = models;
  if (!options.plot.empty() && spec.models.empty())
    throw InputError("--plot draws ACMR per reuse model: give --model (e.g. --model all) or --cache model=...");
  spec.target = options.target;
  spec.seed = options.seed;
  spec.time_budget = options.time_budget;
  spec.with_time = !options.no_time;
  if (options.accounting != "misses" && options.accounting != "evictions")
    throw InputError("--accounting '" + options.accounting + "': expected misses or evictions");
  spec.eviction_charged = options.accounting == "evictions";
  if (options.vertex_bytes == 0) throw InputError("--vertex-bytes 0: expected at least 1 byte per vertex");
  spec.vertex_bytes = options.vertex_bytes;
  spec.fetch_cache = parse_fetch_cache(options.fetch, "--fetch");
  spec.miss_image = options.miss_image;
  const Mesh mesh = load_mesh_spec(options.mesh);
  const Table table = vcache_table(mesh, options.mesh, spec);
  if (!spec.models.empty() && format != TableFormat::Json) {
    const std::vector<Table> tables = {table, vcache_model_pivot(table)};
    std::cout << render_tables(tables, format);
  } else {
    std::cout << render_table(table, format);
  }
  if (!options.plot.empty()) write_vcache_model_plot(options.plot, table);
}

}  // namespace

void add_vcache_command(CLI::App& app) {
  CLI::App* command = app.add_subcommand("vcache", "Post-transform vertex cache misses under each triangle ordering");
  auto options = std::make_shared<VcacheOptions>();
  command->add_option("mesh", options->mesh, "Mesh file, builtin:<scene> or grid:WxH")->required();
  command->add_option("--algo", options->algorithms, "all, or a comma-separated list of orderings")
      ->capture_default_str();
  command
      ->add_option("--cache", options->cache,
                   "Simulated post-transform caches (cache spec, README): entries=N/M/...,policy=fifo/lru")
      ->capture_default_str();
  command
      ->add_option("--model", options->model,
                   "Vertex reuse presets instead of --cache: all, or a comma-separated list of nv-pascal, nv-maxwell, "
                   "amd-gcn, intel, kerbl-nv, kerbl-nv-gl, kerbl-amd, kerbl-intel (one row per ordering and model)");
  command->add_option("--plot", options->plot, "With models: bars of ACMR per ordering and model (PNG or SVG)");
  command->add_option("--policy", options->old_policy)->group("");  // the old spelling: an error naming the new
  command->add_option("--target", options->target,
                      "Cache size the orderings optimize for (default: the simulated size)")->check(whole_number(1, 65536));
  command->add_option("--seed", options->seed, "Seed of the randomized orderings")->check(whole_number(0, 9223372036854775807))->capture_default_str();
  command->add_option("--time-budget", options->time_budget, "Seconds for iterative orderings (local)")->check(finite_number(0, 1e6))
      ->capture_default_str();
  command->add_option("--format", options->format, "md, csv, latex or json")->capture_default_str();
  command
      ->add_option("--accounting", options->accounting,
                   "misses (true FIFO/LRU misses) or evictions (transforms as NVIDIA Mesh Tools charged "
                   "them, as in Castano's grid tables; FIFO only)")
      ->capture_default_str();
  command->add_option("--vertex-bytes", options->vertex_bytes, "Bytes per vertex: vertex fetch and bandwidth")->check(whole_number(0, 4294967295))
      ->capture_default_str();
  command
      ->add_option("--fetch", options->fetch,
                   "The vertex-buffer cache of the fetch columns: meshopt (meshopt_analyzeVertexFetch's direct-mapped "
                   "128 KiB, 64-byte lines) or a byte-cache spec, e.g. size=16KiB,line=64B,assoc=4")
      ->capture_default_str();
  command->add_option("--miss-image", options->miss_image,
                      "Also write a PNG of the mesh, each face coloured by how many of its vertices missed (0 green, 1 "
                      "yellow, 2 orange, 3 red); needs one algorithm and one cache");
  command->add_flag("--no-time", options->no_time, "Leave out the run-time column so outputs compare byte for byte");
  command->footer(
      "Examples:\n"
      "  rastrace vcache grid:16x16 --algo scanline,grid,tipsy --cache entries=12/16/20\n"
      "  rastrace vcache data/meshes/fandisk.off --algo all --cache entries=16,policy=fifo/lru --format csv --no-time\n"
      "  rastrace vcache grid:16x16 --algo grid --target 8 --cache entries=8/16\n"
      "  rastrace vcache grid:16x16 --algo scanline,grid --cache entries=12/16/20 --accounting evictions\n"
      "  rastrace vcache data/meshes/bunny00.off --algo original,tipsy --vertex-bytes 48 --fetch size=32KiB,line=64B,assoc=4\n"
      "  rastrace vcache data/meshes/fandisk.off --algo kcache --cache entries=16 --miss-image fandisk-misses.png\n"
      "  rastrace vcache data/meshes/bunny00.off --algo tipsy,forsyth,batch --model all --no-time --plot models.png\n"
      "  rastrace vcache data/meshes/fandisk.off --cache entries=32,warp=32,primgroup=32 --format json");
  command->callback([options] { run_vcache(*options); });
}

}  // namespace rastrace

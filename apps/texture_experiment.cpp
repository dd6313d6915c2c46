#include "apps/texture_experiment.h"

#include <filesystem>

#include "core/error.h"
#include "core/units.h"
#include "reorder/ordering.h"
#include "traces/trace_writer.h"

namespace rastrace {

namespace {

// One draw per object: the ordering's faces as a triangle list, with their materials.
struct OrderedScene {
  std::vector<std::vector<std::uint32_t>> indices;
  std::vector<std::vector<std::uint32_t>> materials;
  std::vector<DrawCall> draws;
  VertexStreamStats vertex;
};

void accumulate(VertexStreamStats& total, const VertexStreamStats& part) {
  total.lookups += part.lookups;
  total.misses += part.misses;
  total.triangles += part.triangles;
  total.degenerate += part.degenerate;
  total.vertices += part.vertices;
  total.indices_sent += part.indices_sent;
}

OrderedScene order_for_experiment(const Scene& scene, const TextureExperiment& experiment, const std::string& order) {
  const ReorderAlgorithm& algorithm = find_reorder_algorithm(order);
  ReorderParams params;
  params.cache_size = experiment.vertex_cache.entries;
  params.policy = experiment.vertex_cache.policy;
  params.texgroup_base = experiment.texgroup_base;
  params.texgroup_regions = experiment.texgroup_regions;

  OrderedScene out;
  const std::size_t objects = scene.objects.size();
  out.indices.resize(objects);
  out.materials.resize(objects);
  out.draws.resize(objects);
  for (std::size_t o = 0; o < objects; ++o) {
    const Mesh& mesh = scene.objects[o].mesh;
    const Ordering ordering = algorithm.run(mesh, params);
    accumulate(out.vertex, simulate_vertex_stream(ordering.indices, ordering.type, experiment.vertex_cache.policy,
                                                  experiment.vertex_cache.entries, ordering.restart_index));
    out.indices[o] = indices_in_face_order(mesh, ordering.face_order);
    if (!mesh.face_material.empty())
      for (const std::uint32_t face : ordering.face_order) out.materials[o].push_back(mesh.face_material[face]);
    out.draws[o].indices = out.indices[o];
    out.draws[o].primitive_materials = out.materials[o];
  }
  return out;
}

}  // namespace

std::vector<TextureRun> run_texture_experiment(const TextureExperiment& experiment) {
  if (experiment.orders.empty() || experiment.rasters.empty())
    throw InputError("texture experiment: expected at least one ordering and one raster order");
  SceneRenderFlags flags = experiment.render;
  const Scene scene = load_render_scene(flags);
  const TextureLevels levels = texture_levels(scene);
  if (levels.empty()) throw InputError(flags.scene + ": the scene has no texture, so there is no texture cache to measure");
  std::filesystem::create_directories(experiment.trace_dir);
  if (!experiment.image_dir.empty()) std::filesystem::create_directories(experiment.image_dir);

  std::vector<TextureRun> runs;
  for (const std::string& order : experiment.orders) {
    const OrderedScene ordered = order_for_experiment(scene, experiment, order);
    for (const std::string& raster : experiment.rasters) {
      flags.raster = raster;
      flags.order = order;
      RenderOptions options = render_options_from(flags);
      options.pipeline.cache_policy = experiment.vertex_cache.policy;
      options.pipeline.cache_entries = experiment.vertex_cache.entries;
      options.object_draws = ordered.draws;

      TextureRun run;
      run.order = order;
      run.raster = raster;
      run.vertex = ordered.vertex;
      run.trace_path = (std::filesystem::path(experiment.trace_dir) / (order + "-" + raster + ".rtrace")).string();
      TraceMetadata metadata;
      metadata.scene = flags.scene;
      metadata.ordering = order;
      metadata.width = static_cast<std::uint32_t>(scene.width);
      metadata.height = static_cast<std::uint32_t>(scene.height);
      metadata.filter = flags.filter;
      metadata.textures = levels;
      metadata.extra = {{"raster", raster}, {"wrap", flags.wrap}};
      if (order == "texgroup")
        metadata.extra.insert({{"texgroup_base", experiment.texgroup_base}, {"texgroup_regions", experiment.texgroup_regions}});
      TraceWriter writer(run.trace_path, metadata);
      const RenderResult result = render_scene(scene, options, &writer);  // finishes the writer
      run.fragments = result.raster.fragments;
      run.texel_accesses = result.raster.texel_reads;
      if (!experiment.image_dir.empty()) {
        run.image_path = (std::filesystem::path(experiment.image_dir) / (order + "-" + raster + ".png")).string();
        result.framebuffer.write_colour(run.image_path);
      }
      run.sweep = run_sweep(run.trace_path, experiment.sweep);
      runs.push_back(std::move(run));
    }
  }
  return runs;
}

Table texture_experiment_table(const TextureExperiment& experiment, const std::vector<TextureRun>& runs) {
  Table table;
  table.title = experiment.title;
  table.parameters = {
      {"scene", experiment.render.scene},
      {"filter", experiment.render.filter},
      {"wrap", experiment.render.wrap},
      {"cull", experiment.render.cull},
      {"vertex_cache", std::string(to_string(experiment.vertex_cache.policy)) + ":" +
                           std::to_string(experiment.vertex_cache.entries)},
      {"texgroup_base", experiment.texgroup_base},
      {"texgroup_regions", experiment.texgroup_regions},
      {"texel_bytes", experiment.sweep.layouts.empty() ? 4u : experiment.sweep.layouts.front().texel_bytes},
  };
  if (!experiment.render.size.empty()) table.parameters.emplace_back("size", experiment.render.size);
  table.columns = {{"order", "order", 0},          {"raster", "raster", 0},   {"size_bytes", "size", 0},
                   {"line_bytes", "line", 0},      {"assoc", "assoc", 0},     {"policy", "policy", 0},
                   {"layout", "layout", 0},        {"accesses", "accesses", 0}, {"misses", "misses", 0},
                   {"miss_rate", "miss rate", 4},  {"bytes_per_fragment", "bytes/fragment", 2},
                   {"vertex_acmr", "vertex ACMR", 3}};
  for (const TextureRun& run : runs) {
    for (const SweepRow& row : run.sweep.rows) {
      const double per_fragment =
          run.fragments ? double(row.stats.bytes_fetched) / double(run.fragments) : 0.0;
      table.add_row({run.order, run.raster, row.cache.size_bytes, row.cache.line_bytes, row.cache.assoc,
                     to_string(row.cache.policy), row.layout, row.stats.accesses, row.stats.misses,
                     row.stats.miss_rate(), per_fragment, run.vertex.acmr()});
    }
  }
  return table;
}

}  // namespace rastrace

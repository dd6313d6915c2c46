#include "experiments/report.h"

#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>

#include "core/error.h"
#include "core/units.h"
#include "experiments/cache_report.h"
#include "experiments/texture_experiment.h"
#include "experiments/vcache_table.h"
#include "scenes/mesh_spec.h"

namespace rastrace {

namespace {

// Misses of texgroup against strip per cache size, for one raster, layout and policy.
Table grouping_table(const std::vector<TextureRun>& runs, const std::string& raster, const std::string& layout,
                     ReplacementPolicy policy) {
  Table table;
  table.title = "Texture-grouped against strips (" + raster + ", " + layout + ", " + to_string(policy) + ")";
  table.columns = {{"size_bytes", "cache size", 0},           {"strip_misses", "strip misses", 0},
                   {"texgroup_misses", "texgroup misses", 0}, {"reduction", "reduction %", 1},
                   {"strip_acmr", "strip vertex ACMR", 3},    {"texgroup_acmr", "texgroup vertex ACMR", 3}};
  const TextureRun* strip = nullptr;
  const TextureRun* grouped = nullptr;
  for (const TextureRun& run : runs) {
    if (run.raster != raster) continue;
    if (run.order == "strip") strip = &run;
    if (run.order == "texgroup") grouped = &run;
  }
  if (!strip || !grouped) return table;
  for (const SweepRow& a : strip->sweep.rows) {
    if (a.layout != layout || a.cache.policy != policy) continue;
    for (const SweepRow& b : grouped->sweep.rows) {
      if (b.layout != a.layout || b.cache.policy != policy || b.cache.size_bytes != a.cache.size_bytes ||
          b.cache.line_bytes != a.cache.line_bytes || b.cache.assoc != a.cache.assoc)
        continue;
      const double reduction =
          a.stats.misses ? 100.0 * (double(a.stats.misses) - double(b.stats.misses)) / double(a.stats.misses) : 0.0;
      table.add_row({a.cache.size_bytes, a.stats.misses, b.stats.misses, reduction, strip->vertex.acmr(),
                     grouped->vertex.acmr()});
    }
  }
  return table;
}

}  // namespace

void write_report(const ReportSpec& spec) {
  namespace fs = std::filesystem;
  const fs::path dir = spec.output_dir;
  fs::create_directories(dir / "plots");
  std::ostringstream md;
  md << "# rastrace report: " << spec.scene << "\n\n"
     << "How the order in which triangles are drawn changes the traffic between the GPU and its memory:\n"
     << "the post-transform vertex cache under each ordering, then the texture cache under the orderings\n"
     << "of Yang, Mitra and Huang (strips against texture-grouped strips) and Sander et al.'s Tipsy.\n\n"
     << "Reproduce with:\n\n```sh\nrastrace report " << spec.scene << " -o " << spec.output_dir << "\n```\n\n";

  // 1. The vertex cache under each ordering.
  std::cerr << "report: vertex cache orderings\n";
  const Mesh mesh = load_mesh_spec(spec.scene);
  VcacheTableSpec vcache;
  vcache.algorithms = spec.vcache_orders;
  vcache.caches = {12, 16, 24, 32};
  vcache.with_time = false;
  md << render_table(vcache_table(mesh, spec.scene, vcache), TableFormat::Markdown) << "\n";

  // 1b. The same kind of orders on current GPUs: every reuse preset (cache_sim/vertex_reuse.h).
  std::cerr << "report: vertex reuse models\n";
  VcacheTableSpec models = vcache;
  models.algorithms = spec.model_orders;
  for (const VertexReusePreset& preset : vertex_reuse_presets()) models.models.push_back(preset.spec);
  const Table model_table = vcache_table(mesh, spec.scene, models);
  write_output((dir / "vertex-reuse-models.csv").string(), render_table(model_table, TableFormat::Csv));
  write_vcache_model_plot((dir / "plots" / "vertex-reuse-models.png").string(), model_table);
  md << "Which orders keep their advantage on batch hardware: every order (made for FIFO 16) under the\n"
     << "FIFO-with-warp profiles of meshoptimizer and the batch models of Kerbl et al. 2018. Invocations,\n"
     << "warps and lane use per model are in `vertex-reuse-models.csv`.\n\n"
     << render_table(vcache_model_pivot(model_table), TableFormat::Markdown) << "\n"
     << "![vertex reuse models](plots/vertex-reuse-models.png)\n\n";

  // 2. The texture cache under the chosen orderings, scanline and tiled traversal.
  std::cerr << "report: rendering and sweeping texture caches\n";
  TextureExperiment experiment;
  experiment.title = "Texture cache: " + spec.scene;
  experiment.render.scene = spec.scene;
  experiment.render.cull = "back";
  experiment.orders = split_list(spec.orders, "--order");
  experiment.rasters = {"scanline", "tiled8"};
  experiment.vertex_cache = vertex_cache_spec(VertexCachePolicy::Fifo, 16);
  experiment.sweep = spec.sweep;
  experiment.trace_dir = (dir / "traces").string();
  experiment.image_dir = (dir / "images").string();
  const std::vector<TextureRun> runs = run_texture_experiment(experiment);

  md << "## Frames\n\n";
  for (const TextureRun& run : runs)
    if (run.raster == "scanline") md << "![" << run.order << "](" << fs::relative(run.image_path, dir).string() << ") ";
  md << "\n\nOne frame per ordering (scanline traversal); the images are identical, the memory traffic is not.\n\n";

  // 3. The whole frame: the four streams per ordering, side by side and stacked.
  md << "## The whole frame: vertex, texture, depth and colour traffic\n\n"
     << "Bytes between the GPU and its memory per frame and per pixel of the frame, each render through one\n"
     << "live cache bank (the caches are stated in full below); depth and colour caches write back dirty\n"
     << "lines, and the colour buffer is written, never read.\n\n";
  write_frame_traffic_plot((dir / "plots" / "frame-traffic.png").string(), "Frame traffic per ordering: " + spec.scene,
                           frame_traffic_rows(runs));
  md << "![frame traffic](plots/frame-traffic.png)\n\n"
     << render_table(frame_experiment_table(experiment, runs), TableFormat::Markdown) << "\n";

  // Plots: miss rate against size, a line per ordering and policy, per traversal and layout.
  for (const std::string& raster : experiment.rasters) {
    for (const LayoutSpec& layout : experiment.sweep.layouts) {
      PlotSeries series;
      for (const TextureRun& run : runs) {
        if (run.raster != raster) continue;
        for (const SweepRow& row : run.sweep.rows)
          if (row.layout == layout_name(layout))
            series[run.order + " " + to_string(row.cache.policy)].emplace_back(row.cache.size_bytes,
                                                                               row.stats.miss_rate());
      }
      const std::string name = "texture-" + raster + "-" + layout_name(layout) + ".png";
      write_size_plot((dir / "plots" / name).string(),
                      "texture miss rate: " + spec.scene + ", " + raster + ", " + layout_name(layout),
                      "texture miss rate", std::move(series));
      if (raster == "scanline") md << "![" << name << "](plots/" << name << ")\n";
    }
  }
  md << "\n";
  for (const LayoutSpec& layout : experiment.sweep.layouts)
    md << render_table(grouping_table(runs, "scanline", layout_name(layout), ReplacementPolicy::Lru),
                       TableFormat::Markdown)
       << "\n";
  md << render_table(texture_experiment_table(experiment, runs), TableFormat::Markdown) << "\n"
     << "Traces of every run are in `traces/`; `rastrace sweep traces/<order>-<raster>.rtrace` replays them "
        "under any other cache.\n";

  write_output((dir / "report.md").string(), md.str());
  std::cout << "wrote " << (dir / "report.md").string() << "\n";
}

}  // namespace rastrace

// `rastrace texsweep [SCENE] [--experiment fig6|fig7|fig9|fig11] [--order strip,texgroup]
//  [--raster scanline,tiled8] [--tcache size=1KiB..64KiB,policy=fifo/lru/opt,layout=...]`:
// renders the scene once per triangle ordering and traversal order, records each texel trace and
// sweeps texture caches over it (texture_experiment.h); a second table gives each run's whole
// frame traffic (vertex, texture, depth, colour). The named experiments are the figures of Yang,
// Mitra and Huang; explicit flags override what an experiment sets.
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <set>

#include "apps/commands.h"
#include "apps/render_flags.h"
#include "apps/sweep_flags.h"
#include "core/error.h"
#include "core/units.h"
#include "experiments/cache_report.h"
#include "experiments/texture_experiment.h"

namespace rastrace {

namespace {

struct ExperimentPreset {
  std::string name;
  std::string title;
  std::string scene;
  std::string orders;
  std::string policies;
};

const std::vector<ExperimentPreset>& experiment_presets() {
  static const std::vector<ExperimentPreset> presets = {
      {"fig6", "Texture miss rate against cache size (Yang et al., Figure 6)", "builtin:bunny", "strip,greedy,tipsy",
       "lru"},
      {"fig7", "FIFO against LRU, OPT the lower bound (Yang et al., Figure 7)", "builtin:bunny", "strip",
       "fifo,lru,opt"},
      {"fig9", "Texture-grouped against strips, one component with the four-colour texture (Yang et al., Figure 9)",
       "builtin:bunny", "strip,texgroup", "lru"},
      {"fig11", "Texture-grouped against strips, a model of separate components (Yang et al., Figure 11)",
       "builtin:spider", "strip,texgroup", "lru"},
  };
  return presets;
}

const ExperimentPreset& find_preset(const std::string& name) {
  for (const ExperimentPreset& preset : experiment_presets())
    if (preset.name == name) return preset;
  throw InputError("unknown experiment '" + name + "': expected fig6, fig7, fig9 or fig11");
}

struct TexsweepCommand {
  std::string scene;
  std::string experiment;
  std::string orders = "strip,texgroup";
  std::string rasters = "scanline,tiled8";
  std::string base = "strip";
  std::string regions = "auto";
  std::string vcache = "entries=16,policy=fifo";
  std::string resolution;
  std::string filter = "trilinear";
  std::string wrap = "repeat";
  std::string cull = "back";
  std::string texture_format;  // empty: each texture's own
  unsigned aniso = 1;
  std::string aniso_rule = "ellipse";
  SweepFlags sweep{
      .tcache = "size=1KiB..64KiB,line=64B,assoc=full,policy=fifo/lru/opt,layout=linear/block4/block8/morton",
      .retired = {}};
  std::string format = "md";
  std::string output;
  std::string plot_dir;
  std::string trace_dir;
  std::string image_dir;
};

// One plot per raster, layout, line size and associativity: a line per ordering and policy.
void write_plots(const std::string& dir, const std::string& stem, const std::string& title,
                 const std::vector<TextureRun>& runs) {
  std::filesystem::create_directories(dir);
  std::map<std::string, PlotSeries> plots;
  for (const TextureRun& run : runs) {
    for (const SweepRow& row : run.sweep.rows) {
      const std::string key = run.raster + "-" + row.layout + "-" + format_byte_size(row.cache.line_bytes) + "-" +
                              (row.cache.assoc == 0 ? std::string("full") : std::to_string(row.cache.assoc) + "way");
      plots[key][run.order + " " + to_string(row.cache.policy)].emplace_back(row.cache.size_bytes,
                                                                             row.stats.miss_rate());
    }
  }
  for (auto& [key, series] : plots)
    write_size_plot((std::filesystem::path(dir) / (stem + "-" + key + ".png")).string(), title + " [" + key + "]",
                    "texture miss rate", std::move(series));
}

void run_texsweep(const TexsweepCommand& command, const CLI::App& app) {
  TextureExperiment experiment;
  TexsweepCommand c = command;
  std::string stem = "texsweep";
  experiment.title = "Texture cache sweep";
  if (!c.experiment.empty()) {
    const ExperimentPreset& preset = find_preset(c.experiment);
    stem = preset.name;
    experiment.title = preset.title;
    if (c.scene.empty()) c.scene = preset.scene;
    if (app.count("--order") == 0) c.orders = preset.orders;
    if (app.count("--tcache") == 0) {  // the figure's policies in the default sweep
      std::string policies = preset.policies;
      std::replace(policies.begin(), policies.end(), ',', '/');
      const std::size_t at = c.sweep.tcache.find("policy=");
      c.sweep.tcache.replace(at, c.sweep.tcache.find(',', at) - at, "policy=" + policies);
    }
  }
  if (c.scene.empty()) throw InputError("texsweep: expected a SCENE or an --experiment");
  const TableFormat format = parse_table_format(c.format);
  experiment.render.scene = c.scene;
  experiment.render.size = c.resolution;
  experiment.render.filter = c.filter;
  experiment.render.wrap = c.wrap;
  experiment.render.cull = c.cull;
  experiment.render.texture_format = c.texture_format;
  experiment.render.aniso = c.aniso;
  experiment.render.aniso_rule = c.aniso_rule;
  experiment.orders = split_list(c.orders, "--order");
  experiment.rasters = split_list(c.rasters, "--raster");
  experiment.texgroup_base = c.base;
  experiment.texgroup_regions = c.regions;
  experiment.vertex_cache = parse_vcache_spec(c.vcache);
  experiment.sweep = sweep_spec_from(c.sweep);
  experiment.image_dir = c.image_dir;

  experiment.trace_dir = c.trace_dir;  // empty: temporary, removed afterwards

  const std::vector<TextureRun> runs = run_texture_experiment(experiment);
  if (!c.plot_dir.empty()) {
    write_plots(c.plot_dir, stem, experiment.title, runs);
    write_frame_traffic_plot((std::filesystem::path(c.plot_dir) / (stem + "-frame.png")).string(),
                             "Frame traffic per ordering: " + c.scene, frame_traffic_rows(runs));
  }
  const Table tables[] = {texture_experiment_table(experiment, runs), frame_experiment_table(experiment, runs)};
  write_output(c.output, render_tables(tables, format));
}

}  // namespace

void add_texsweep_command(CLI::App& app) {
  CLI::App* command = app.add_subcommand(
      "texsweep", "Render each triangle ordering, record its texel trace, sweep texture caches (Yang et al.)");
  auto c = std::make_shared<TexsweepCommand>();
  command->add_option("scene", c->scene,
                      "Scene: builtin:bunny|spider|grid, a JSON scene or a mesh file "
                      "(default: the experiment's)");
  command->add_option("--experiment", c->experiment,
                      "A figure of Yang et al.: fig6 (miss rate against size), fig7 (FIFO against LRU), "
                      "fig9 (texgroup against strips, bunny), fig11 (texgroup against strips, spider)");
  command->add_option("--order", c->orders, "Triangle orderings to compare (rastrace reorder --help lists them)")
      ->capture_default_str();
  command->add_option("--raster", c->rasters, "Traversal orders inside triangles: scanline, tiled8")
      ->capture_default_str();
  command->add_option("--base", c->base, "texgroup: the algorithm ordering each group (strip, greedy, tipsy, ...)")
      ->capture_default_str();
  command->add_option("--regions", c->regions, "texgroup: auto, quadrant, chart or texture")->capture_default_str();
  command->add_option("--vcache", c->vcache, "Post-transform cache the orderings target and ACMR is measured on")
      ->capture_default_str();
  command->add_option("--resolution", c->resolution, "Image size WxH (default: the scene's)");
  command
      ->add_option("--filter", c->filter, "nearest, linear, nearest_mipmap_nearest, linear_mipmap_nearest, trilinear")
      ->capture_default_str();
  command->add_option("--wrap", c->wrap, "repeat or clamp_to_edge")->capture_default_str();
  command->add_option("--cull", c->cull, "Face culling: none, back or front")->capture_default_str();
  command->add_option("--texture-format", c->texture_format,
                      "Store every texture as rgba8, bc1, bc3, bc4, bc5, bc7, astc4x4 or astc8x8 (decoded at load)");
  add_anisotropy_flags(*command, c->aniso, c->aniso_rule);
  add_sweep_flags(*command, c->sweep);
  command->add_option("--format", c->format, "Table format: md, csv, latex or json")->capture_default_str();
  command->add_option("-o,--output", c->output, "Write the table to this file (atomically) instead of stdout");
  command->add_option("--plot", c->plot_dir, "Draw miss rate against cache size into this folder (PNG, gnuplot)");
  command->add_option("--traces", c->trace_dir,
                      "Keep the texel traces in this folder (rastrace replay/sweep read them)");
  command->add_option("--images", c->image_dir, "Write each run's frame into this folder");
  command->footer(
      "Examples:\n"
      "  rastrace texsweep --experiment fig9 --plot out/plots\n"
      "  rastrace texsweep builtin:spider --order strip,texgroup,tipsy --tcache "
      "size=1KiB..64KiB,assoc=full,policy=lru,layout=block4 "
      "--format csv\n"
      "  rastrace texsweep builtin:bunny --tcache size=1KiB..16KiB,line=32B/64B,assoc=2/4/full --raster scanline");
  command->callback([c, command] { run_texsweep(*c, *command); });
}

}  // namespace rastrace

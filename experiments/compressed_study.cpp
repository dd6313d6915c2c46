#include "experiments/compressed_study.h"

#include <map>

#include "cache_sim/texture_layout.h"
#include "core/error.h"
#include "core/units.h"
#include "experiments/cache_report.h"
#include "experiments/texture_experiment.h"

namespace rastrace {

namespace {

SweepSpec study_sweep(const CompressedStudy& study) {
  SweepSpec sweep;
  sweep.sizes = study.sizes;
  sweep.lines = {study.line_bytes};
  sweep.assocs = {study.assoc};
  sweep.policies = {ReplacementPolicy::Lru};
  sweep.three_c = false;
  sweep.layouts.clear();
  for (const std::string& format : study.formats) {
    LayoutSpec layout = parse_layout(study.layout);
    layout.format = parse_texture_format(format, "compressed study format");
    sweep.layouts.push_back(layout);
  }
  return sweep;
}

}  // namespace

std::vector<CompressedStudyRow> run_compressed_study(const CompressedStudy& study) {
  std::vector<CompressedStudyRow> rows;
  for (const std::string& scene : study.scenes)
    for (const unsigned aniso : study.anisotropy) {
      TextureExperiment experiment;
      experiment.render.scene = scene;
      experiment.render.size = study.frame_size;
      experiment.render.aniso = aniso;
      experiment.render.aniso_rule = study.aniso_rule;
      experiment.orders = study.orders;
      experiment.rasters = {study.raster};
      experiment.vertex_cache = VertexCacheSpec{VertexCachePolicy::Fifo, 16};
      experiment.sweep = study_sweep(study);
      for (const TextureRun& run : run_texture_experiment(experiment))
        for (const SweepRow& row : run.sweep.rows) {
          const LayoutSpec& layout = experiment.sweep.layouts.at(row.layout_index);
          CompressedStudyRow out;
          out.scene = scene;
          out.order = run.order;
          out.anisotropy = aniso;
          out.format = to_string(*layout.format);
          out.size_bytes = row.cache.size_bytes;
          out.fragments = run.fragments;
          out.accesses = row.stats.accesses;
          out.misses = row.stats.misses;
          out.miss_ratio = row.stats.miss_rate();
          out.bytes_per_fragment = run.fragments ? double(row.stats.bytes_fetched) / double(run.fragments) : 0.0;
          rows.push_back(std::move(out));
        }
    }
  return rows;
}

Table compressed_study_table(const CompressedStudy& study, const std::vector<CompressedStudyRow>& rows) {
  Table table;
  table.title = "Texture traffic by storage format and anisotropy";
  table.kind = "compressed_texture_study";
  table.parameters = {{"frame", study.frame_size},
                      {"raster", study.raster},
                      {"filter", "trilinear"},
                      {"aniso_rule", study.aniso_rule},
                      {"layout", study.layout},
                      {"line_bytes", study.line_bytes},
                      {"assoc", study.assoc},
                      {"policy", "lru"},
                      {"vertex_cache", "fifo:16"}};
  table.columns = {{"scene", "scene", 0},
                   {"order", "order", 0},
                   {"aniso", "aniso", 0},
                   {"format", "format", 0},
                   {"size_bytes", "size", 0},
                   {"fragments", "fragments", 0},
                   {"accesses", "texel reads", 0},
                   {"misses", "misses", 0},
                   {"miss_ratio", "miss ratio", 4},
                   {"bytes_per_fragment", "bytes/fragment", 2}};
  for (const CompressedStudyRow& r : rows)
    table.add_row({r.scene, r.order, std::int64_t{r.anisotropy}, r.format, r.size_bytes, r.fragments, r.accesses,
                   r.misses, r.miss_ratio, r.bytes_per_fragment});
  return table;
}

std::uint64_t working_set_knee(const std::vector<CompressedStudyRow>& rows, const std::string& scene,
                               const std::string& order, unsigned anisotropy, const std::string& format) {
  std::map<std::uint64_t, double> ratio;  // by size, ascending
  for (const CompressedStudyRow& r : rows)
    if (r.scene == scene && r.order == order && r.anisotropy == anisotropy && r.format == format)
      ratio[r.size_bytes] = r.miss_ratio;
  if (ratio.empty()) return 0;
  const double floor = ratio.rbegin()->second;
  for (const auto& [size, value] : ratio)
    if (value <= 1.1 * floor) return size;
  return ratio.rbegin()->first;
}

void write_compressed_study_plot(const std::string& path, const std::vector<CompressedStudyRow>& rows,
                                 const std::string& scene, const std::string& order) {
  PlotSeries series;
  for (const CompressedStudyRow& r : rows)
    if (r.scene == scene && r.order == order)
      series[r.format + " aniso " + std::to_string(r.anisotropy)].emplace_back(r.size_bytes, r.bytes_per_fragment);
  if (series.empty()) throw InputError("--plot: the study has no rows for " + scene + " drawn in " + order + " order");
  write_size_plot(path, "Texture bytes per fragment: " + scene + ", " + order + " order (LRU, 4-way, 64 B lines)",
                  "bytes fetched per fragment", std::move(series));
}

}  // namespace rastrace

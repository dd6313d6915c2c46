#include "experiments/frame_traffic.h"

#include <cstdio>

#include "experiments/cache_report.h"

namespace rastrace {

TextureCacheSpec FrameCaches::default_texture_cache() {
  TextureCacheSpec spec;
  spec.cache = CacheConfig{16 * 1024, 64, 4, ReplacementPolicy::Lru, 1};
  spec.layout = parse_layout("block4");
  return spec;
}

CacheBankConfig frame_bank_config(const FrameCaches& caches) {
  CacheBankConfig config;
  config.vertex = {caches.vertex};
  config.texture = {caches.texture};
  config.framebuffer = {caches.depth, caches.colour};
  config.three_c = false;
  return config;
}

FrameTraffic measure_frame_traffic(const FrameCaches& caches, const LiveBankSink& bank, const RenderResult& result) {
  FrameTraffic t;
  const Framebuffer& fb = result.framebuffer;
  t.pixels = static_cast<std::uint64_t>(fb.width()) * static_cast<std::uint64_t>(fb.height());
  t.covered_pixels = fb.covered_pixels();
  t.fragments = result.raster.fragments;
  t.fragments_shaded = result.raster.fragments_shaded;
  t.depth_writes = result.raster.fragments_passed;
  t.rejected_early = result.raster.fragments_rejected_early;
  const VertexStreamStats& v = bank.vertex_stats().at(0);
  t.vertex_bytes = v.misses * caches.vertex_bytes + v.indices_sent * caches.index_bytes;
  t.texture_bytes = bank.texture_stats().at(0).bytes_fetched;
  const WriteBackStats& depth = bank.framebuffer_stats().at(0);
  const WriteBackStats& colour = bank.framebuffer_stats().at(1);
  t.depth_read_bytes = depth.bytes_read;
  t.depth_write_bytes = depth.bytes_written;
  t.colour_write_bytes = colour.bytes_written + colour.bytes_read;  // colour is never read: bytes_read is 0
  return t;
}

std::vector<std::pair<std::string, TableCell>> frame_cache_parameters(const FrameCaches& caches) {
  return {{"vcache", format_cache_spec(caches.vertex)},
          {"vertex_model", std::to_string(caches.vertex_bytes) + " B per shaded vertex + " +
                               std::to_string(caches.index_bytes) + " B per index sent"},
          {"tcache", format_cache_spec(caches.texture.cache) + ",layout=" + layout_name(caches.texture.layout)},
          {"zcache", format_framebuffer_cache_spec(caches.depth)},
          {"ccache", format_framebuffer_cache_spec(caches.colour)},
          {"per_pixel", "bytes / (width x height)"}};
}

std::vector<TableColumn> frame_traffic_columns() {
  return {{"vertex_bytes", "vertex B", 0},
          {"texture_bytes", "texture B", 0},
          {"depth_read_bytes", "depth read B", 0},
          {"depth_write_bytes", "depth write B", 0},
          {"colour_write_bytes", "colour write B", 0},
          {"total_bytes", "total B", 0},
          {"vertex_bytes_per_pixel", "vertex B/px", 2},
          {"texture_bytes_per_pixel", "texture B/px", 2},
          {"depth_bytes_per_pixel", "depth B/px", 2},
          {"colour_bytes_per_pixel", "colour B/px", 2},
          {"total_bytes_per_pixel", "total B/px", 2},
          {"covered_pixels", "covered pixels", 0},
          {"overdraw", "overdraw", 3},
          {"depth_writes_per_pixel", "depth writes/px", 3},
          {"rejected_early", "rejected early", 0}};
}

std::vector<TableCell> frame_traffic_cells(const FrameTraffic& t) {
  std::vector<TableCell> cells;
  for (const std::uint64_t bytes : {t.vertex_bytes, t.texture_bytes, t.depth_read_bytes, t.depth_write_bytes,
                                    t.colour_write_bytes, t.total_bytes()})
    cells.emplace_back(bytes);
  for (const std::uint64_t bytes : {t.vertex_bytes, t.texture_bytes, t.depth_read_bytes + t.depth_write_bytes,
                                    t.colour_write_bytes, t.total_bytes()})
    cells.emplace_back(t.per_pixel(bytes));
  cells.emplace_back(t.covered_pixels);
  cells.emplace_back(t.overdraw());
  cells.emplace_back(t.depth_writes_per_pixel());
  cells.emplace_back(t.rejected_early);
  return cells;
}

Table frame_traffic_table(const std::string& title, std::vector<std::pair<std::string, TableCell>> parameters,
                          const std::vector<FrameTrafficRow>& rows) {
  Table table;
  table.title = title;
  table.parameters = std::move(parameters);
  table.columns = {{"order", "order", 0}, {"raster", "raster", 0}};
  for (TableColumn& column : frame_traffic_columns()) table.columns.push_back(std::move(column));
  for (const FrameTrafficRow& row : rows) {
    std::vector<TableCell> cells = {row.order, row.raster};
    for (TableCell& cell : frame_traffic_cells(row.traffic)) cells.push_back(std::move(cell));
    table.add_row(std::move(cells));
  }
  return table;
}

void write_frame_traffic_plot(const std::string& path, const std::string& title,
                              const std::vector<FrameTrafficRow>& rows) {
  std::string script = gnuplot_terminal(path, 1000, 650);
  std::string quoted_title = title;
  for (char& c : quoted_title)
    if (c == '\'' || c == '\n' || c == '"') c = ' ';
  script += "set title '" + quoted_title + "'\nset ylabel 'bytes per pixel'\nset grid ytics\n" +
            "set style data histograms\nset style histogram rowstacked\nset style fill solid 0.8 border -1\n" +
            "set boxwidth 0.7\nset key outside right\nset yrange [0:*]\nset xtics rotate by -30\n$traffic << EOD\n";
  for (const FrameTrafficRow& row : rows) {
    const FrameTraffic& t = row.traffic;
    std::string label = row.order + (row.raster.empty() ? "" : "/" + row.raster);
    for (char& c : label)
      if (c == ' ' || c == '"') c = '_';
    char line[256];
    std::snprintf(line, sizeof(line), "\"%s\" %.9g %.9g %.9g %.9g %.9g\n", label.c_str(), t.per_pixel(t.vertex_bytes),
                  t.per_pixel(t.texture_bytes), t.per_pixel(t.depth_read_bytes), t.per_pixel(t.depth_write_bytes),
                  t.per_pixel(t.colour_write_bytes));
    script += line;
  }
  script += "EOD\n";
  const std::string plot =
      "plot $traffic using 2:xtic(1) title 'vertex', '' using 3 title 'texture', '' using 4 title 'depth read', "
      "'' using 5 title 'depth write', '' using 6 title 'colour write'";
  run_gnuplot(path, script, plot);
}

}  // namespace rastrace

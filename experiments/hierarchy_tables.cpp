#include "experiments/hierarchy_tables.h"

#include "cache_sim/cache_spec.h"
#include "core/error.h"
#include "core/units.h"

namespace rastrace {

std::string format_level_spec(const CacheLevelSpec& level) {
  std::string spec = format_cache_spec(level.cache);
  if (level.sector_bytes != 0 && level.sector_bytes != level.cache.line_bytes) {
    const std::size_t at = spec.find(",assoc=");
    spec.insert(at, ",sector=" + format_byte_size(level.sector_bytes));
  }
  return spec;
}

HierarchySpec parse_hierarchy(const HierarchyRequest& request) {
  HierarchySpec out;
  if (request.levels.empty()) throw InputError("--level: expected at least one cache level");
  for (std::size_t k = 0; k < request.levels.size(); ++k) {
    const std::string& text = request.levels[k];
    const std::string where = "--level '" + text + "' (L" + std::to_string(k + 1) + ")";
    const CacheSpec spec = parse_cache_spec(text, "--level");
    if (spec.kind != CacheKind::Byte || spec.buffer)
      throw InputError(where + ": expected a byte cache, e.g. size=16KiB,line=128B,sector=32B,assoc=4");
    if (spec.combinations() != 1)
      throw InputError(where + ": expected one cache, not " + std::to_string(spec.combinations()) + " alternatives");
    if (spec.source && *spec.source == SweepSource::VertexBuffer)
      throw InputError(where + ": hierarchies take texel or address traces, not source=vertex");
    const ByteCacheChoice choice = byte_caches(spec).front();
    if (k == 0) {
      out.layout = choice.layout;
    } else if (text.find("layout=") != std::string::npos || text.find("texel=") != std::string::npos ||
               text.find("align=") != std::string::npos || text.find("format=") != std::string::npos) {
      throw InputError(where + ": layout=, texel=, align= and format= belong to the L1 spec (they map texels to "
                               "bytes once, for every level)");
    }
    try {
      validate(choice.cache);
    } catch (const InputError& e) {
      throw InputError(where + ": " + e.what());
    }
    out.hierarchy.levels.push_back({choice.cache, choice.sector_bytes});
  }
  out.hierarchy.units = request.units;
  out.hierarchy.tile = request.tile;
  out.hierarchy.inclusion = parse_inclusion(request.inclusion);
  out.hierarchy.element_bytes = out.layout.texel_bytes;
  out.hierarchy.decoded_l1 = request.decoded_l1;
  // The levels' own checks (sector sizes, opt), named by level.
  CacheHierarchy check(out.hierarchy);
  return out;
}

Table hierarchy_table(TableParameters parameters, const HierarchySpec& spec, const CacheHierarchy& hierarchy) {
  Table t;
  t.title = "Cache hierarchy";
  t.parameters = std::move(parameters);
  const HierarchyConfig& h = spec.hierarchy;
  t.parameters.emplace_back("hierarchy", describe(h));
  t.parameters.emplace_back("l1_units", h.units);
  t.parameters.emplace_back("tile_pixels", h.tile);
  t.parameters.emplace_back("inclusion", to_string(h.inclusion));
  t.parameters.emplace_back("layout", layout_name(spec.layout));
  t.parameters.emplace_back("texel_bytes", spec.layout.texel_bytes);
  t.parameters.emplace_back("decoded_l1", h.decoded_l1 ? "yes" : "no");
  const std::vector<LevelStats> stats = hierarchy.stats();
  const double reduction = stats.back().bytes_fetched
                               ? double(stats.front().bytes_requested) / double(stats.back().bytes_fetched)
                               : 0.0;
  t.parameters.emplace_back("bandwidth_reduction", reduction);
  t.columns = {{"level", "level", 0},
               {"cache", "cache", 0},
               {"accesses", "accesses", 0},
               {"misses", "misses", 0},
               {"line_misses", "line misses", 0},
               {"request_miss_ratio", "request miss ratio", 5},
               {"bytes_requested", "bytes requested", 0},
               {"bytes_fetched", "bytes from next level", 0},
               {"byte_miss_ratio", "byte miss ratio", 5},
               {"invalidations", "back-invalidations", 0}};
  for (std::size_t k = 0; k < stats.size(); ++k) {
    const LevelStats& s = stats[k];
    std::string level = "L" + std::to_string(k + 1);
    if (k == 0 && h.units > 1) level += " (" + std::to_string(h.units) + " units)";
    t.add_row({level, format_level_spec(h.levels[k]), s.accesses, s.misses, s.line_misses, s.request_miss_ratio(),
               s.bytes_requested, s.bytes_fetched, s.byte_miss_ratio(), s.invalidations});
  }
  return t;
}

Table sectored_cache_table(TableParameters parameters, const std::vector<HierarchySpec>& specs,
                           const HierarchySink& sink, std::size_t first) {
  Table t;
  t.title = "Sectored caches";
  t.parameters = std::move(parameters);
  t.columns = {{"cache", "cache", 0},         {"layout", "layout", 0},
               {"accesses", "accesses", 0},   {"misses", "misses (sector)", 0},
               {"line_misses", "line misses", 0}, {"miss_rate", "miss rate", 5},
               {"bytes_fetched", "bytes fetched", 0}};
  for (std::size_t i = first; i < specs.size(); ++i) {
    const LevelStats s = sink.hierarchy(i).stats().front();
    t.add_row({format_level_spec(specs[i].hierarchy.levels.front()), layout_name(specs[i].layout), s.accesses,
               s.misses, s.line_misses, s.request_miss_ratio(), s.bytes_fetched});
  }
  return t;
}

}  // namespace rastrace

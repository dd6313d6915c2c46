// `rastrace replay TRACE --cache SPEC...`: replays a trace (rastrace container, CSV export or
// Dinero din) through the given caches in one pass, with the LiveBankSink that live rendering uses.
#include <iostream>
#include <memory>

#include "apps/commands.h"
#include "cache_sim/cache_spec.h"
#include "core/error.h"
#include "experiments/cache_report.h"
#include "experiments/per_frame_caches.h"
#include "experiments/replay_tables.h"
#include "experiments/texture_miss_map.h"

namespace rastrace {

void add_replay_command(CLI::App& app) {
  CLI::App* command = app.add_subcommand("replay", "Replay a trace through one or more caches");
  auto trace = std::make_shared<std::string>();
  auto specs = std::make_shared<std::vector<std::string>>();
  auto format = std::make_shared<std::string>("md");
  auto output = std::make_shared<std::string>();
  auto keep_vertex_cache = std::make_shared<bool>(false);
  command->add_option("trace", *trace, "Trace file: rastrace trace (.rtrace), .csv export or Dinero .din")->required();
  command
      ->add_option("--cache", *specs,
                   "Caches to simulate (repeatable; cache spec, README; alternatives a/b expand to every "
                   "combination). Byte cache: size=16KiB,line=64B,assoc=4|full,policy=fifo|lru|random|opt,"
                   "layout=linear|block2..block16|morton[,texel=4B][,align=4KiB][,source=texel|vertex|address]"
                   "[,stride=32B][,seed=1]. Depth or colour cache: source=depth|colour with size=... or model=attila"
                   "[,pixel=4B]. Post-transform vertex cache: entries=16,policy=fifo|lru. Sectored: "
                   "line=128B,sector=32B");
  auto hierarchy = std::make_shared<HierarchyRequest>();
  command->add_option("--level", hierarchy->levels,
                      "A cache hierarchy, one --level per level, L1 first (each one byte cache spec, sector= "
                      "allowed; the L1 spec's layout= maps texels to bytes)");
  command->add_option("--units", hierarchy->units, "Hierarchy: L1 copies (texture units) sharing the lower levels")
      ->check(CLI::Range(1, 1024));
  command->add_option("--tile", hierarchy->tile, "Hierarchy: side in pixels of the screen tiles dealt out to units")
      ->check(CLI::Range(1, 4096));
  command->add_option("--inclusion", hierarchy->inclusion, "Hierarchy: inclusive or non-inclusive")
      ->check(CLI::IsMember({"inclusive", "non-inclusive"}));
  command->add_flag("--decoded-l1", hierarchy->decoded_l1,
                    "Hierarchy: the L1 holds decoded texels and the levels below compressed blocks (textures the "
                    "trace or the L1's format= stores block-compressed)");
  command->add_option("--format", *format, "Table format: md, csv, latex or json");
  command->add_option("-o,--output", *output, "Write the table to this file (atomically) instead of stdout");
  auto miss_map = std::make_shared<std::string>();
  command->add_option("--miss-map", *miss_map,
                      "Draw per pixel the texture misses of the first texture --cache (0, 1, 2, 3+; legend and cache "
                      "in FILE.txt beside it)");
  auto per_frame = std::make_shared<bool>(false);
  command->add_flag("--per-frame", *per_frame,
                    "One row per frame (of a trace of render --frames N), texture cache and level; the caches keep "
                    "their contents between frames");
  command->add_flag("--keep-vertex-cache", *keep_vertex_cache,
                    "Keep the post-transform cache across draws (default: empty at each draw)");
  command->footer(
      "Examples:\n"
      "  rastrace replay frame.rtrace --cache size=16KiB,line=64B,assoc=4,policy=lru,layout=block4\n"
      "  rastrace replay frame.rtrace --cache entries=16,policy=fifo --cache size=8KiB,assoc=full,policy=opt\n"
      "  rastrace replay old.din --cache size=32KiB,line=32B,assoc=2 --format json\n"
      "  rastrace replay frame.rtrace --level size=16KiB,line=128B,sector=32B,assoc=4,layout=block4 \\\n"
      "      --level size=1MiB,line=128B,assoc=16 --units 4 --tile 16 --inclusion inclusive\n"
      "  rastrace replay frame.rtrace --cache size=16KiB,line=64B,assoc=4,layout=morton,format=rgba8/bc1/bc7\n"
      "  rastrace replay frame.rtrace --level size=4KiB,line=64B,assoc=4,layout=morton,format=bc1 \\\n"
      "      --level size=16KiB,line=64B,assoc=8 --decoded-l1\n"
      "  rastrace replay frame.rtrace --cache size=32KiB,line=128B,assoc=2,layout=block4 --miss-map misses.png\n"
      "  rastrace replay orbit.rtrace --per-frame --level size=16KiB,line=64B,assoc=4,layout=block4 \\\n"
      "      --level size=1MiB,line=64B,assoc=16");
  command->callback([=] {
    if (specs->empty() && hierarchy->levels.empty())
      throw InputError("replay: expected --cache SPEC or --level SPEC (a hierarchy)");
    if (hierarchy->decoded_l1 && hierarchy->levels.empty())
      throw InputError("--decoded-l1: expected a hierarchy to apply it to (--level L1 --level L2)");
    const TableFormat table_format = parse_table_format(*format);
    if (*per_frame) {
      if (!miss_map->empty()) throw InputError("--per-frame with --miss-map: draw the miss map in a separate replay");
      write_output(*output, render_table(per_frame_replay_table(*trace, *specs, *hierarchy), table_format));
      return;
    }
    const std::vector<Table> tables = replay_tables(*trace, *specs, *keep_vertex_cache, "--cache", true, *hierarchy);
    write_output(*output, render_tables(tables, table_format));
    if (!miss_map->empty()) {
      // The first texture cache the specs name (the table above has its totals).
      for (const std::string& text : *specs) {
        const CacheSpec spec = parse_cache_spec(text, "--cache");
        if (spec.kind != CacheKind::Byte || spec.buffer || spec.source.value_or(SweepSource::Texel) != SweepSource::Texel)
          continue;
        const ByteCacheChoice choice = byte_caches(spec).front();
        if (choice.sector_bytes != 0 || choice.cache.policy == ReplacementPolicy::Opt) continue;
        const TextureMissMap map = texture_miss_map(*trace, choice.cache, choice.layout);
        std::cerr << write_texture_miss_map(
            map, format_cache_spec(choice.cache) + ",layout=" + layout_name(choice.layout), *miss_map);
        return;
      }
      throw InputError("--miss-map: expected a texture --cache (fifo, lru or random, unsectored) to charge misses to");
    }
  });
}

}  // namespace rastrace

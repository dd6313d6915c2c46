// `rastrace replay TRACE --cache SPEC...`: replays a trace (rastrace container, CSV export or
// Dinero din) through the given caches in one pass, with the LiveBankSink that live rendering uses.
#include <iostream>
#include <memory>
#include <optional>

#include "apps/commands.h"
#include "core/error.h"
#include "core/progress.h"
#include "core/units.h"
#include "experiments/cache_report.h"

namespace rastrace {

namespace {

struct CacheSpec {
  bool post_transform = false;
  VertexCacheSpec vertex;
  CacheConfig cache;
  LayoutSpec layout;
  std::optional<SweepSource> source;
  std::uint32_t stride = 32;
};

// "size=16KiB,line=64B,assoc=4,policy=lru,layout=block4" or "entries=16,policy=fifo".
CacheSpec parse_cache_spec(const std::string& text) {
  CacheSpec spec;
  std::string policy = "lru", layout = "linear";
  for (const std::string& item : split_list(text, "--cache")) {
    const std::size_t eq = item.find('=');
    if (eq == std::string::npos)
      throw InputError("--cache '" + text + "': item '" + item +
                       "': expected key=value (size, line, assoc, policy, layout, "
                       "texel, align, stride, source, seed, entries)");
    const std::string key = item.substr(0, eq), value = item.substr(eq + 1);
    if (key == "entries") {
      spec.post_transform = true;
      const std::uint64_t k = parse_count(value, "--cache entries");
      if (k == 0 || k > 1u << 20) throw InputError("--cache entries=" + value + ": expected 1..1048576");
      spec.vertex.entries = static_cast<unsigned>(k);
    } else if (key == "size") {
      spec.cache.size_bytes = parse_byte_size(value, "--cache size");
    } else if (key == "line") {
      spec.cache.line_bytes = static_cast<std::uint32_t>(parse_byte_size(value, "--cache line"));
    } else if (key == "assoc") {
      spec.cache.assoc = value == "full" ? 0 : static_cast<std::uint32_t>(parse_count(value, "--cache assoc"));
      if (value != "full" && spec.cache.assoc == 0)
        throw InputError("--cache assoc=0: expected a number of ways or 'full'");
    } else if (key == "policy") {
      policy = value;
    } else if (key == "layout") {
      layout = value;
    } else if (key == "texel") {
      spec.layout.texel_bytes = static_cast<std::uint32_t>(parse_byte_size(value, "--cache texel"));
    } else if (key == "align") {
      spec.layout.alignment = parse_byte_size(value, "--cache align");
    } else if (key == "stride") {
      spec.stride = static_cast<std::uint32_t>(parse_byte_size(value, "--cache stride"));
    } else if (key == "source") {
      spec.source = parse_sweep_source(value);
    } else if (key == "seed") {
      spec.cache.seed = parse_count(value, "--cache seed");
    } else {
      throw InputError("--cache '" + text + "': unknown key '" + key +
                       "': expected size, line, assoc, policy, layout, texel, align, stride, source, seed or entries");
    }
  }
  if (spec.post_transform) {
    spec.vertex.policy = parse_vertex_cache_policy(policy);
  } else {
    spec.cache.policy = parse_replacement_policy(policy);
    const LayoutSpec named = parse_layout(layout);
    spec.layout.kind = named.kind;
    spec.layout.block = named.block;
    validate(spec.cache);
  }
  return spec;
}

}  // namespace

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
                   "Cache to simulate (repeatable). Byte cache: size=16KiB,line=64B,assoc=4|full,"
                   "policy=fifo|lru|random|opt,layout=linear|block2..block16|morton[,texel=4B][,align=4KiB]"
                   "[,source=texel|vertex|address][,stride=32B][,seed=1]. Post-transform vertex cache: "
                   "entries=16,policy=fifo|lru")
      ->required();
  command->add_option("--format", *format, "Table format: md, csv, latex or json");
  command->add_option("-o,--output", *output, "Write the table to this file (atomically) instead of stdout");
  command->add_flag("--keep-vertex-cache", *keep_vertex_cache,
                    "Keep the post-transform cache across draws (default: empty at each draw)");
  command->footer(
      "Examples:\n"
      "  rastrace replay frame.rtrace --cache size=16KiB,line=64B,assoc=4,policy=lru,layout=block4\n"
      "  rastrace replay frame.rtrace --cache entries=16,policy=fifo --cache size=8KiB,assoc=full,policy=opt\n"
      "  rastrace replay old.din --cache size=32KiB,line=32B,assoc=2 --format json");
  command->callback([=] {
    const TableFormat table_format = parse_table_format(*format);
    const TraceSummary summary = summarize_trace(*trace);
    const SweepSource fallback = default_source(summary);
    CacheBankConfig bank;
    bank.flush_vertex_cache_per_draw = !*keep_vertex_cache;
    std::vector<SweepRow> texture_rows, vertex_buffer_rows, address_rows;
    for (const std::string& text : *specs) {
      const CacheSpec spec = parse_cache_spec(text);
      if (spec.post_transform) {
        bank.vertex.push_back(spec.vertex);
        continue;
      }
      switch (spec.source.value_or(fallback)) {
        case SweepSource::Texel:
          bank.texture.push_back({spec.cache, spec.layout});
          texture_rows.push_back({spec.cache, layout_name(spec.layout), {}});
          break;
        case SweepSource::VertexBuffer:
          bank.vertex_buffer.push_back({spec.cache, spec.stride});
          vertex_buffer_rows.push_back({spec.cache, "stride" + std::to_string(spec.stride), {}});
          break;
        case SweepSource::Address:
          bank.address.push_back(spec.cache);
          address_rows.push_back({spec.cache, "-", {}});
          break;
      }
    }
    LiveBankSink sink(bank, summary.metadata.textures);
    std::optional<Progress> progress;
    if (summary.has_counts) progress.emplace("replay", summary.vertices + summary.texels + summary.addresses);
    replay_file(*trace, sink, {}, progress ? &*progress : nullptr);
    if (progress) progress->finish();

    std::vector<Table> tables;
    const auto parameters = trace_parameters(*trace, summary);
    if (!bank.vertex.empty()) {
      std::vector<VertexSweepRow> rows;
      for (std::size_t i = 0; i < bank.vertex.size(); ++i) rows.push_back({bank.vertex[i], sink.vertex_stats()[i]});
      auto p = parameters;
      p.emplace_back("vertex_cache_per_draw", *keep_vertex_cache ? "kept" : "flushed");
      tables.push_back(vertex_cache_table("Post-transform vertex caches", p, rows));
    }
    const auto add_byte_table = [&](std::vector<SweepRow>& rows, const std::vector<CacheStats>& stats,
                                    const char* title, const char* source) {
      if (rows.empty()) return;
      for (std::size_t i = 0; i < rows.size(); ++i) rows[i].stats = stats[i];
      auto p = parameters;
      if (std::string(source) == "texel") {
        // Stated once when every cache shares them; otherwise each row's layout names them.
        bool same = true;
        for (const TextureCacheSpec& t : bank.texture)
          same = same && t.layout.texel_bytes == bank.texture.front().layout.texel_bytes &&
                 t.layout.alignment == bank.texture.front().layout.alignment;
        if (same) {
          p.emplace_back("texel_bytes", bank.texture.front().layout.texel_bytes);
          p.emplace_back("level_alignment_bytes", bank.texture.front().layout.alignment);
        } else {
          for (std::size_t i = 0; i < rows.size(); ++i)
            rows[i].layout += " texel=" + format_byte_size(bank.texture[i].layout.texel_bytes) +
                              " align=" + format_byte_size(bank.texture[i].layout.alignment);
        }
      }
      bool same_seed = true;
      for (const SweepRow& r : rows) same_seed = same_seed && r.cache.seed == rows.front().cache.seed;
      if (same_seed)
        p.emplace_back("random_seed", rows.front().cache.seed);
      else
        for (SweepRow& r : rows) r.layout += " seed=" + std::to_string(r.cache.seed);
      tables.push_back(byte_cache_table(title, p, rows, source));
    };
    add_byte_table(texture_rows, sink.texture_stats(), "Texture caches", "texel");
    add_byte_table(vertex_buffer_rows, sink.vertex_buffer_stats(), "Vertex buffer caches", "vertex");
    add_byte_table(address_rows, sink.address_stats(), "Address caches", "address");
    write_output(*output, render_tables(tables, table_format));
  });
}

}  // namespace rastrace

#include "experiments/replay_tables.h"

#include <optional>

#include "cache_sim/cache_spec.h"
#include "cache_sim/live_bank_sink.h"
#include "core/error.h"
#include "core/progress.h"
#include "core/units.h"
#include "experiments/cache_report.h"
#include "traces/replay_file.h"
#include "traces/tee_sink.h"

namespace rastrace {

std::vector<Table> replay_tables(const std::string& trace, const std::vector<std::string>& specs,
                                 bool keep_vertex_cache, const std::string& option, bool progress_bar,
                                 const HierarchyRequest& hierarchy) {
  const TraceSummary summary = summarize_trace(trace);
  // Hierarchies and sectored caches: hierarchy_sink.h (the --level hierarchy first, if any).
  std::vector<HierarchySpec> hierarchies;
  if (!hierarchy.levels.empty()) hierarchies.push_back(parse_hierarchy(hierarchy));
  const std::size_t first_sectored = hierarchies.size();
  const SweepSource fallback = default_source(summary);
  CacheBankConfig bank;
  bank.flush_vertex_cache_per_draw = !keep_vertex_cache;
  std::vector<SweepRow> texture_rows, vertex_buffer_rows, address_rows;
  for (const std::string& text : specs) {
    const CacheSpec spec = parse_cache_spec(text, option);
    for (const VertexCacheSpec& vertex : vertex_caches(spec)) bank.vertex.push_back(vertex);
    for (const FramebufferCacheSpec& framebuffer : framebuffer_caches(spec)) {
      try {
        validate(framebuffer.cache);
      } catch (const InputError& e) {
        throw InputError(option + " '" + text + "': " + e.what());
      }
      bank.framebuffer.push_back(framebuffer);
    }
    if (spec.buffer) continue;
    for (const ByteCacheChoice& choice : byte_caches(spec)) {
      try {
        validate(choice.cache);
      } catch (const InputError& e) {
        throw InputError(option + " '" + text + "': " + e.what());
      }
      if (choice.sector_bytes != 0) {
        if (spec.source.value_or(fallback) == SweepSource::VertexBuffer)
          throw InputError(option + " '" + text + "': sector= applies to texel and address caches, not source=vertex");
        HierarchySpec sectored;
        sectored.hierarchy.levels.push_back({choice.cache, choice.sector_bytes});
        sectored.layout = choice.layout;
        try {
          CacheHierarchy check(sectored.hierarchy);
        } catch (const InputError& e) {
          throw InputError(option + " '" + text + "': " + e.what());
        }
        hierarchies.push_back(sectored);
        continue;
      }
      switch (spec.source.value_or(fallback)) {
        case SweepSource::Texel:
          bank.texture.push_back({choice.cache, choice.layout});
          texture_rows.push_back({choice.cache, layout_name(choice.layout), {}});
          break;
        case SweepSource::VertexBuffer:
          bank.vertex_buffer.push_back({choice.cache, spec.stride});
          vertex_buffer_rows.push_back({choice.cache, "stride" + std::to_string(spec.stride), {}});
          break;
        case SweepSource::Address:
          bank.address.push_back(choice.cache);
          address_rows.push_back({choice.cache, "-", {}});
          break;
      }
    }
  }
  if (!bank.framebuffer.empty() && summary.format == TraceFileFormat::Container && summary.framebuffer == 0)
    throw_in_file(trace, "the trace has no framebuffer records (written before trace version 2, or by a "
                         "renderer without them): expected them for source=depth|colour caches");
  LiveBankSink sink(bank, summary.metadata.textures, FrameSize{summary.metadata.width, summary.metadata.height});
  HierarchySink hierarchy_sink(hierarchies, summary.metadata.textures);
  TeeSink both({&sink, &hierarchy_sink});
  std::optional<Progress> progress;
  if (progress_bar && summary.has_counts)
    progress.emplace("replay", summary.vertices + summary.texels + summary.addresses + summary.framebuffer);
  replay_file(trace, hierarchies.empty() ? static_cast<EventSink&>(sink) : both, {}, progress ? &*progress : nullptr);
  if (progress) progress->finish();

  std::vector<Table> tables;
  const auto parameters = trace_parameters(trace, summary);
  if (!bank.vertex.empty()) {
    std::vector<VertexSweepRow> rows;
    for (std::size_t i = 0; i < bank.vertex.size(); ++i) rows.push_back({bank.vertex[i], sink.vertex_stats()[i]});
    auto p = parameters;
    p.emplace_back("vertex_cache_per_draw", keep_vertex_cache ? "kept" : "flushed");
    tables.push_back(vertex_cache_table("Post-transform vertex caches", p, rows));
    tables.back().kind = "vertex_cache";
  }
  const auto add_byte_table = [&](std::vector<SweepRow>& rows, const std::vector<CacheStats>& stats,
                                  const char* title, const char* source, const char* kind) {
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
    tables.back().kind = kind;
  };
  add_byte_table(texture_rows, sink.texture_stats(), "Texture caches", "texel", "texture_cache");
  add_byte_table(vertex_buffer_rows, sink.vertex_buffer_stats(), "Vertex buffer caches", "vertex", "vertex_buffer_cache");
  add_byte_table(address_rows, sink.address_stats(), "Address caches", "address", "address_cache");
  if (!bank.framebuffer.empty()) {
    tables.push_back(framebuffer_cache_table(parameters, bank.framebuffer, sink.framebuffer_stats()));
    tables.back().kind = "framebuffer_cache";
  }
  if (hierarchies.size() > first_sectored) {
    tables.push_back(sectored_cache_table(parameters, hierarchies, hierarchy_sink, first_sectored));
    tables.back().kind = "sectored_cache";
  }
  if (first_sectored == 1) {
    tables.push_back(hierarchy_table(parameters, hierarchies.front(), hierarchy_sink.hierarchy(0)));
    tables.back().kind = "hierarchy_level";
  }
  return tables;
}

}  // namespace rastrace

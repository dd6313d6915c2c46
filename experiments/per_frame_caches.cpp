#include "experiments/per_frame_caches.h"

#include "cache_sim/cache_spec.h"
#include "core/error.h"
#include "experiments/cache_report.h"
#include "traces/replay_file.h"
#include "traces/tee_sink.h"

namespace rastrace {

void FrameCountsSink::end_frame() {
  FrameEnd end;
  end.frame = frame_;
  for (std::size_t i = 0; i < caches_.size(); ++i) end.totals.push_back(caches_.hierarchy(i).stats());
  ends_.push_back(std::move(end));
}

void FrameCountsSink::begin_frame(std::uint32_t frame) {
  if (finished_) throw std::logic_error("FrameCountsSink: begin_frame after finish");
  if (frame == frame_) return;  // frame 0 announced at the start, or a frame announced twice
  end_frame();
  frame_ = frame;
}

void FrameCountsSink::finish() {
  if (finished_) return;
  end_frame();
  finished_ = true;
}

Table per_frame_table(TableParameters parameters, const std::vector<std::string>& names,
                      const FrameCountsSink& counts) {
  Table t;
  t.title = "Caches per frame";
  t.parameters = std::move(parameters);
  t.parameters.emplace_back("frames", static_cast<std::uint64_t>(counts.frames().size()));
  t.parameters.emplace_back("between_frames", "caches keep their contents");
  t.columns = {{"frame", "frame", 0},         {"cache", "cache", 0},
               {"level", "level", 0},         {"accesses", "accesses", 0},
               {"misses", "misses", 0},       {"line_misses", "line misses", 0},
               {"miss_rate", "miss rate", 4}, {"bytes_fetched", "bytes from next level", 0}};
  const std::vector<FrameCountsSink::FrameEnd>& ends = counts.frames();
  for (std::size_t f = 0; f < ends.size(); ++f)
    for (std::size_t i = 0; i < ends[f].totals.size(); ++i)
      for (std::size_t k = 0; k < ends[f].totals[i].size(); ++k) {
        const LevelStats& now = ends[f].totals[i][k];
        const LevelStats before = f ? ends[f - 1].totals[i][k] : LevelStats{};
        const std::uint64_t accesses = now.accesses - before.accesses;
        const std::uint64_t misses = now.misses - before.misses;
        t.add_row({static_cast<std::uint64_t>(ends[f].frame), names.at(i), "L" + std::to_string(k + 1), accesses,
                   misses, now.line_misses - before.line_misses, accesses ? double(misses) / double(accesses) : 0.0,
                   now.bytes_fetched - before.bytes_fetched});
      }
  return t;
}

Table per_frame_replay_table(const std::string& trace, const std::vector<std::string>& specs,
                             const HierarchyRequest& hierarchy, const std::string& option) {
  const TraceSummary summary = summarize_trace(trace);
  const SweepSource fallback = default_source(summary);
  std::vector<HierarchySpec> caches;
  std::vector<std::string> names;
  for (const std::string& text : specs) {
    const CacheSpec spec = parse_cache_spec(text, option);
    const SweepSource source = spec.source.value_or(fallback);
    if (spec.kind != CacheKind::Byte || spec.buffer || source == SweepSource::VertexBuffer)
      throw InputError(option + " '" + text +
                       "' with --per-frame: expected a texture (or address) byte cache; "
                       "vertex, depth and colour caches have no per-frame table");
    for (const ByteCacheChoice& choice : byte_caches(spec)) {
      HierarchySpec one;
      one.hierarchy.levels.push_back({choice.cache, choice.sector_bytes});
      one.hierarchy.element_bytes = choice.layout.texel_bytes;
      one.layout = choice.layout;
      try {
        validate(choice.cache);
        CacheHierarchy check(one.hierarchy);  // policy=opt and bad sectors, named by the spec
      } catch (const InputError& e) {
        throw InputError(option + " '" + text + "' with --per-frame: " + e.what());
      }
      caches.push_back(one);
      names.push_back(format_level_spec(one.hierarchy.levels.front()) +
                      (source == SweepSource::Texel ? ",layout=" + layout_name(choice.layout) : ""));
    }
  }
  if (!hierarchy.levels.empty()) {
    caches.push_back(parse_hierarchy(hierarchy));
    names.push_back("hierarchy");
  }
  if (caches.empty()) throw InputError("--per-frame: expected --cache SPEC or --level SPEC");
  HierarchySink sink(caches, summary.metadata.textures);
  FrameCountsSink counts(sink);
  TeeSink both({&sink, &counts});
  replay_file(trace, both, {false, true, true, false});
  TableParameters parameters = trace_parameters(trace, summary);
  if (!hierarchy.levels.empty()) parameters.emplace_back("hierarchy", describe(caches.back().hierarchy));
  return per_frame_table(std::move(parameters), names, counts);
}

}  // namespace rastrace

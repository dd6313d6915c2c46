#include "cache_sim/sampled_sweep.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <memory>
#include <optional>

#include "core/error.h"
#include "core/progress.h"
#include "traces/replay_file.h"

namespace rastrace {

namespace {

// The estimators of one (layout, line size) group of rows.
struct SampledGroup {
  std::size_t layout = 0;
  std::uint32_t line_shift = 0;
  std::vector<std::size_t> shards_rows, mini_rows;
  std::unique_ptr<ShardsProfile> shards;
  std::unique_ptr<MiniSimulations> minis;
  std::unique_ptr<SampledBatch> sampled;  // the group's lines sampled once for both estimators
  std::vector<std::uint64_t> lines;
};

// Maps the accesses of the sweep's source to byte addresses, per layout, and feeds each group.
class SampledSink final : public EventSink {
 public:
  SampledSink(const SweepSpec& spec, const std::vector<LayoutSpec>& layouts, const TextureLevels& textures,
              std::vector<SampledGroup>& groups)
      : spec_(spec), groups_(groups), textures_(textures.size()) {
    for (const LayoutSpec& layout : layouts) layouts_.emplace_back(layout, textures);
  }
  void begin_draw(const DrawInfo& draw) override { draw_ = draw.draw; }
  void end_draw() override {}
  void finish() override {}
  void vertex_fetches(std::span<const VertexFetch> fetches) override {
    addresses_.resize(fetches.size());
    const std::uint64_t base = std::uint64_t{draw_} << 40;  // as LiveBankSink places draws' buffers
    for (std::size_t i = 0; i < fetches.size(); ++i)
      addresses_[i] = base + std::uint64_t{fetches[i].vertex} * spec_.stride;
    feed(0);
  }
  void texel_accesses(std::span<const TexelAccess> accesses) override {
    for (std::size_t l = 0; l < layouts_.size(); ++l) {
      const TextureLayout& layout = layouts_[l];
      addresses_.resize(accesses.size());
      for (std::size_t i = 0; i < accesses.size(); ++i) {
        const TexelAccess& t = accesses[i];
        if (!layout.contains(t.texture, t.level, t.x, t.y)) [[unlikely]]
          throw InputError("texel access (texture " + std::to_string(t.texture) + ", level " +
                           std::to_string(t.level) + ", x " + std::to_string(t.x) + ", y " + std::to_string(t.y) +
                           ") lies outside the " + std::to_string(textures_) +
                           " texture(s) whose level sizes the trace metadata lists");
        addresses_[i] = layout.address(t.texture, t.level, t.x, t.y);
      }
      feed(l);
    }
  }
  void address_accesses(std::span<const AddressAccess> accesses) override {
    addresses_.resize(accesses.size());
    for (std::size_t i = 0; i < accesses.size(); ++i) addresses_[i] = accesses[i].address;
    feed(0);
  }

 private:
  void feed(std::size_t layout) {
    for (SampledGroup& g : groups_) {
      if (g.layout != layout) continue;
      g.lines.resize(addresses_.size());
      for (std::size_t i = 0; i < addresses_.size(); ++i) g.lines[i] = addresses_[i] >> g.line_shift;
      g.sampled->sample(g.lines);
      if (g.shards) g.shards->access_sampled(*g.sampled);
      if (g.minis) g.minis->access_sampled(*g.sampled);
    }
  }

  const SweepSpec& spec_;
  std::vector<SampledGroup>& groups_;
  std::size_t textures_;
  std::vector<TextureLayout> layouts_;
  std::vector<std::uint64_t> addresses_;
  std::uint32_t draw_ = 0;
};

}  // namespace

std::vector<std::size_t> run_sampled_rows(const std::string& trace_path, const SweepSpec& spec,
                                          const std::vector<LayoutSpec>& layouts, const TextureLevels& textures,
                                          std::uint64_t records, std::size_t configurations, SweepRows& rows,
                                          bool show_progress) {
  const SampleSpec sample = *spec.sample;
  const SampleGuards& guards = spec.sample_guards;
  std::vector<SampledGroup> groups;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const SweepRow& row = rows[r];
    const bool stack = row.cache.policy == ReplacementPolicy::Lru && row.cache.assoc == 0;
    if (!stack && sample.max_lines)
      throw InputError("--sample " + describe(sample) + ": fixed-size sampling gives fully associative LRU only; " +
                       describe(row.cache) + " needs a fixed rate (miniature simulation)");
    if (row.cache.policy == ReplacementPolicy::Opt)
      throw InputError("sampled sweep: opt has no miniature simulation here; drop opt or --sample");
  }
  std::vector<std::size_t> exact;
  const auto simulate_exactly = [&](std::size_t r) {
    rows[r].sampled_as = "exact";
    rows[r].expected_error = 0;
    exact.push_back(r);
  };
  // A short trace: the exact sweep costs about as much as the sample and states no error.
  if (records > 0 && double(records) * double(configurations) <= double(guards.exact_accesses)) {
    for (std::size_t r = 0; r < rows.size(); ++r) simulate_exactly(r);
    return exact;
  }

  for (std::size_t r = 0; r < rows.size(); ++r) {
    const SweepRow& row = rows[r];
    const std::uint32_t shift = static_cast<std::uint32_t>(std::countr_zero(row.cache.line_bytes));
    auto g = groups.begin();
    while (g != groups.end() && (g->layout != row.layout_index || g->line_shift != shift)) ++g;
    if (g == groups.end()) {
      groups.emplace_back();
      g = groups.end() - 1;
      g->layout = row.layout_index;
      g->line_shift = shift;
    }
    const bool stack = row.cache.policy == ReplacementPolicy::Lru && row.cache.assoc == 0;
    // A fixed rate's small caches are known before the pass; a fixed size's rate only falls, so
    // its rows are checked again at the final rate below.
    if (double(row.cache.lines()) * sample.rate < double(guards.min_sampled_lines) ||
        (row.cache.assoc != 0 && row.cache.assoc < guards.min_sampled_assoc))
      simulate_exactly(r);
    else
      (stack ? g->shards_rows : g->mini_rows).push_back(r);
  }
  for (SampledGroup& g : groups) {
    if (!g.shards_rows.empty()) g.shards = std::make_unique<ShardsProfile>(sample);
    std::vector<CacheConfig> caches;
    for (const std::size_t r : g.mini_rows) caches.push_back(rows[r].cache);
    if (!caches.empty()) g.minis = std::make_unique<MiniSimulations>(caches, sample.rate);
    g.sampled = std::make_unique<SampledBatch>(sample.rate);
  }
  std::erase_if(groups, [](const SampledGroup& g) { return !g.shards && !g.minis; });
  if (groups.empty()) return exact;

  ReplayKinds kinds;
  kinds.vertices = spec.source == SweepSource::VertexBuffer;
  kinds.texels = spec.source == SweepSource::Texel;
  kinds.addresses = spec.source == SweepSource::Address;
  kinds.texel_details = false;  // the sink maps texture, level, x and y to addresses, nothing else
  SampledSink sink(spec, layouts, textures, groups);
  std::optional<Progress> progress;
  const TraceSummary summary = summarize_trace(trace_path);
  if (show_progress && summary.has_counts)
    progress.emplace("sampled sweep (" + std::to_string(rows.size()) + " caches)",
                     summary.vertices * kinds.vertices + summary.texels * kinds.texels +
                         summary.addresses * kinds.addresses);
  replay_file(trace_path, sink, kinds, progress ? &*progress : nullptr);
  if (progress) progress->finish();

  const auto estimate = [](SweepRow& row, std::uint64_t accesses, double miss_ratio, double error) {
    row.stats = {};
    row.stats.accesses = accesses;
    row.stats.misses = static_cast<std::uint64_t>(std::llround(miss_ratio * double(accesses)));
    row.stats.hits = accesses - row.stats.misses;
    row.stats.bytes_fetched = row.stats.misses * row.cache.line_bytes;
    row.expected_error = error;
  };
  for (SampledGroup& g : groups) {
    for (const std::size_t r : g.shards_rows) {
      const std::uint64_t lines = rows[r].cache.lines();
      if (double(lines) * g.shards->rate() < double(guards.min_sampled_lines)) {
        simulate_exactly(r);
        continue;
      }
      estimate(rows[r], g.shards->accesses(), g.shards->miss_ratio(lines), g.shards->expected_error(lines));
      rows[r].sampled_as = "shards";
    }
    for (std::size_t i = 0; i < g.mini_rows.size(); ++i) {
      SweepRow& row = rows[g.mini_rows[i]];
      estimate(row, g.minis->accesses(), g.minis->miss_ratio(i), g.minis->expected_error(i));
      row.sampled_as = "mini " + describe(g.minis->scaled(i));
    }
  }
  std::sort(exact.begin(), exact.end());
  return exact;
}

}  // namespace rastrace

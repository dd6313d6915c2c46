#include "cache_sim/sweep.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <numeric>
#include <optional>
#include <thread>

#include "cache_sim/sampled_sweep.h"
#include "core/enum_names.h"
#include "core/error.h"
#include "core/progress.h"
#include "core/units.h"
#include "traces/replay_file.h"

namespace rastrace {

namespace {

constexpr EnumName<SweepSource> kSources[] = {
    {SweepSource::Texel, "texel"}, {SweepSource::VertexBuffer, "vertex"}, {SweepSource::Address, "address"}};

}  // namespace

const char* to_string(SweepSource source) { return enum_to_string(source, kSources); }

SweepSource parse_sweep_source(const std::string& text) { return parse_enum(text, kSources, "source"); }

SweepShard parse_sweep_shard(const std::string& text) {
  SweepShard shard;
  const std::size_t slash = text.find('/');
  const auto number = [](const std::string& digits, std::uint32_t& out) {
    if (digits.empty() || digits.size() > 5 || digits.find_first_not_of("0123456789") != std::string::npos)
      return false;
    out = static_cast<std::uint32_t>(std::stoul(digits));
    return true;
  };
  if (slash == std::string::npos || !number(text.substr(0, slash), shard.index) ||
      !number(text.substr(slash + 1), shard.count) || shard.index < 1 || shard.count > 65536 ||
      shard.index > shard.count)
    throw InputError("--shard '" + text.substr(0, 40) + (text.size() > 40 ? "...'" : "'") +
                     ": expected K/N with 1 <= K <= N <= 65536, e.g. 3/8");
  return shard;
}

namespace {

struct Job {
  std::vector<std::size_t> rows;  // indices into the result rows
  std::size_t layout = 0;
};

ReplayKinds kinds_for(SweepSource source) {
  ReplayKinds kinds;
  kinds.vertices = source == SweepSource::VertexBuffer;
  kinds.texels = source == SweepSource::Texel;
  kinds.addresses = source == SweepSource::Address;
  kinds.framebuffer = false;
  return kinds;
}

// Simulates rows[i] for i in `indices` (ascending) exactly: one job per (layout, line size) of
// them, which share the address and line streams, big ones split so every core has work.
void simulate_rows(const std::string& trace_path, const SweepSpec& spec, const std::vector<LayoutSpec>& layouts,
                   const TextureLevels& textures, const std::vector<std::size_t>& indices, SweepRows& rows,
                   unsigned threads, bool show_progress, SweepRowSink* row_sink) {
  if (indices.empty()) return;
  std::vector<Job> groups;
  for (const std::size_t r : indices) {
    auto found = std::find_if(groups.begin(), groups.end(), [&](const Job& j) {
      return j.layout == rows[r].layout_index && rows[j.rows.front()].cache.line_bytes == rows[r].cache.line_bytes;
    });
    if (found == groups.end()) {
      groups.push_back({{}, rows[r].layout_index});
      found = groups.end() - 1;
    }
    found->rows.push_back(r);
  }
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  // Split big groups so every core has work; the split costs one more pass over the trace each.
  std::vector<Job> jobs;
  const std::size_t per_job = std::max<std::size_t>(1, (indices.size() + threads - 1) / threads);
  for (const Job& group : groups)
    for (std::size_t i = 0; i < group.rows.size(); i += per_job)
      jobs.push_back({std::vector<std::size_t>(
                          group.rows.begin() + static_cast<std::ptrdiff_t>(i),
                          group.rows.begin() + static_cast<std::ptrdiff_t>(std::min(group.rows.size(), i + per_job))),
                      group.layout});

  std::optional<Progress> progress;
  if (show_progress) progress.emplace("sweep (" + std::to_string(indices.size()) + " caches)", jobs.size());
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  const auto work = [&] {
    while (true) {
      const std::size_t j = next.fetch_add(1);
      if (j >= jobs.size()) return;
      try {
        const Job& job = jobs[j];
        CacheBankConfig bank;
        bank.three_c = spec.three_c;
        for (const std::size_t r : job.rows) {
          switch (spec.source) {
            case SweepSource::Texel:
              bank.texture.push_back({rows[r].cache, layouts[job.layout]});
              break;
            case SweepSource::VertexBuffer:
              bank.vertex_buffer.push_back({rows[r].cache, spec.stride});
              break;
            case SweepSource::Address:
              bank.address.push_back(rows[r].cache);
              break;
          }
        }
        LiveBankSink sink(bank, textures);
        replay_file(trace_path, sink, kinds_for(spec.source));
        const auto& stats = spec.source == SweepSource::Texel          ? sink.texture_stats()
                            : spec.source == SweepSource::VertexBuffer ? sink.vertex_buffer_stats()
                                                                       : sink.address_stats();
        for (std::size_t i = 0; i < job.rows.size(); ++i) rows[job.rows[i]].stats = stats[i];
        if (row_sink) row_sink->done(rows, job.rows);
        if (progress) progress->advance();
      } catch (...) {
        std::lock_guard lock(failure_mutex);
        if (!failure) failure = std::current_exception();
        next = jobs.size();
      }
    }
  };
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < std::min<std::size_t>(threads, jobs.size()); ++t) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
  if (progress) progress->finish();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace

const char* sweep_method(bool estimated, bool simulated) {
  if (!estimated) return "exact";
  return simulated ? "sampled+exact-rows" : "sampled";
}

const char* sweep_method(std::span<const SweepRow> rows) {
  bool estimated = false, simulated = false;
  for (const SweepRow& row : rows) {
    if (row.expected_error < 0) continue;  // not a sampled sweep's row
    (row.sampled_as == "exact" ? simulated : estimated) = true;
  }
  return sweep_method(estimated, simulated);
}

std::string sweep_layout_name(const SweepSpec& spec, std::size_t layout_index) {
  switch (spec.source) {
    case SweepSource::Texel:
      return layout_name(spec.layouts.at(layout_index));
    case SweepSource::VertexBuffer:
      return "stride" + std::to_string(spec.stride);
    case SweepSource::Address:
      break;
  }
  return "-";
}

SweepResult run_sweep(const std::string& trace_path, const SweepSpec& spec, unsigned threads, bool show_progress,
                      SweepRowSink* row_sink) {
  const TraceSummary summary = summarize_trace(trace_path);
  if (spec.source == SweepSource::Texel && summary.has_counts && summary.texels == 0)
    throw_in_file(trace_path,
                  "the trace has no texel accesses: expected a texel trace (or choose --source vertex/address)");
  if (spec.source == SweepSource::Address && summary.has_counts && summary.addresses == 0)
    throw_in_file(trace_path,
                  "the trace has no address records: expected a din import (or choose --source texel/vertex)");
  if (spec.source == SweepSource::VertexBuffer && summary.has_counts && summary.vertices == 0)
    throw_in_file(trace_path, "the trace has no vertex fetches");
  if (spec.source == SweepSource::Texel) {
    for (const LayoutSpec& layout : spec.layouts) TextureLayout check(layout, summary.metadata.textures);
  }

  SweepResult result;
  bool any_valid = false;
  const std::vector<LayoutSpec> layouts =
      spec.source == SweepSource::Texel ? spec.layouts : std::vector<LayoutSpec>{LayoutSpec{}};
  for (std::size_t l = 0; l < layouts.size(); ++l)
    for (const ReplacementPolicy policy : spec.policies)
      for (const std::uint32_t line : spec.lines)
        for (const std::uint32_t assoc : spec.assocs)
          for (const std::uint64_t size : spec.sizes) {
            const std::size_t configuration = result.configurations++;
            const CacheConfig config{size, line, assoc, policy, spec.seed};
            try {
              validate(config);
              any_valid = true;
            } catch (const InputError& e) {
              if (spec.shard.owns(configuration)) result.skipped.push_back(e.what());
              continue;
            }
            if (!spec.shard.owns(configuration)) continue;
            SweepRow row;
            row.configuration = configuration;
            row.cache = config;
            row.layout_index = l;
            row.layout = sweep_layout_name(spec, l);
            result.rows.push_back(row);
          }
  if (!any_valid) throw InputError("sweep: no valid cache configuration among the combinations given");
  if (row_sink) row_sink->begin(result.rows.size());
  if (result.rows.empty()) return result;
  // The source's records (0: the trace does not count them).
  const std::uint64_t records = !summary.has_counts                         ? 0
                                : spec.source == SweepSource::Texel        ? summary.texels
                                : spec.source == SweepSource::VertexBuffer ? summary.vertices
                                                                           : summary.addresses;
  // OPT buffers the whole line stream: refuse a trace too long for it before reading any of it.
  if (records > 0 && std::any_of(result.rows.begin(), result.rows.end(), [](const SweepRow& r) {
        return r.cache.policy == ReplacementPolicy::Opt;
      }))
    check_opt_capacity(records);
  std::vector<std::size_t> simulate(result.rows.size());
  std::iota(simulate.begin(), simulate.end(), std::size_t{0});
  if (spec.sample) {
    simulate = run_sampled_rows(trace_path, spec, layouts, summary.metadata.textures, records, result.configurations,
                                result.rows, show_progress);
    if (row_sink) {
      // The estimated rows are final now; the simulated ones follow as their jobs finish.
      std::vector<std::size_t> estimated;
      for (std::size_t r = 0, s = 0; r < result.rows.size(); ++r)
        if (s < simulate.size() && simulate[s] == r)
          ++s;
        else
          estimated.push_back(r);
      if (!estimated.empty()) row_sink->done(result.rows, estimated);
    }
  }
  simulate_rows(trace_path, spec, layouts, summary.metadata.textures, simulate, result.rows, threads, show_progress,
                row_sink);
  return result;
}

std::vector<VertexSweepRow> run_vertex_sweep(const std::string& trace_path, const std::vector<VertexCacheSpec>& caches,
                                             bool flush_per_draw, const SweepShard& shard) {
  CacheBankConfig bank;
  bank.flush_vertex_cache_per_draw = flush_per_draw;
  std::vector<std::size_t> configurations;
  for (std::size_t configuration = 0; configuration < caches.size(); ++configuration)
    if (shard.owns(configuration)) {
      bank.vertex.push_back(caches[configuration]);
      configurations.push_back(configuration);
    }
  std::vector<VertexSweepRow> rows;
  if (bank.vertex.empty()) return rows;
  LiveBankSink sink(bank, {});
  ReplayKinds kinds;
  kinds.texels = kinds.addresses = false;
  replay_file(trace_path, sink, kinds);
  for (std::size_t i = 0; i < bank.vertex.size(); ++i)
    rows.push_back({bank.vertex[i], sink.vertex_stats()[i], configurations[i]});
  return rows;
}

}  // namespace rastrace

// `rastrace sweep TRACE`: every combination of cache size, line, associativity, policy and layout
// over one trace, in parallel; a table (md/csv/latex/json) and optionally a miss-rate plot; or,
// with --shard K/N, one part of that set for `rastrace merge` (experiments/sweep_parts.h).
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include "apps/commands.h"
#include "apps/option_checks.h"
#include "apps/sweep_flags.h"
#include "cache_sim/cache_spec.h"
#include "core/error.h"
#include "core/file_digest.h"
#include "core/units.h"
#include "experiments/cache_report.h"
#include "experiments/sweep_parts.h"

namespace rastrace {

void add_sweep_command(CLI::App& app) {
  CLI::App* command =
      app.add_subcommand("sweep", "Sweep cache sizes, lines, associativities, policies and layouts over a trace");
  struct Options {
    std::string trace, cache = "size=1KiB..64KiB", format = "md", output, plot, shard, sample;
    RetiredCacheFlags retired;
    unsigned threads = 0;
    bool keep_vertex_cache = false;
  };
  auto o = std::make_shared<Options>();
  command->add_option("trace", o->trace, "Trace file: rastrace trace (.rtrace), .csv export or Dinero .din")
      ->required();
  command
      ->add_option("--cache", o->cache,
                   "Caches to sweep (cache spec, README): alternatives a/b and ranges a..b expand to every "
                   "combination, e.g. size=1KiB..64KiB,assoc=1/2/4/full,policy=fifo/lru,layout=linear/morton, "
                   "or entries=4..64,policy=fifo/lru for post-transform vertex caches")
      ->capture_default_str();
  o->retired.add(
      *command, {"entries", "size", "line", "assoc", "policy", "layout", "texel", "align", "seed", "source", "stride"});
  command->add_option("--threads", o->threads, "Worker threads (0: one per core)")->check(whole_number(0, 1024))->capture_default_str();
  command->add_option("--format", o->format, "Table format: md, csv, latex or json")->capture_default_str();
  command->add_option("-o,--output", o->output, "Write the table to this file (atomically) instead of stdout");
  command->add_option("--plot", o->plot, "Also draw miss rate against cache size: FILE.png or FILE.svg (gnuplot)");
  command->add_flag("--keep-vertex-cache", o->keep_vertex_cache,
                    "With a vertex cache spec (entries=...): keep the cache across draws");
  command->add_option("--shard", o->shard,
                      "K/N: compute only the K-th of N disjoint parts of the configurations and write it as a "
                      "part (JSON) for `rastrace merge`");
  command->add_option("--sample", o->sample,
                      "Estimate from spatially hashed samples of the lines: RATE (0.01 or 1%) or RATE,max=LINES "
                      "(fixed size, fully associative LRU only): SHARDS for fully associative LRU, miniature "
                      "simulations for the rest; adds each row's expected error (99% confidence from 8 part samples). Short "
                      "traces, caches scaled under 32 sampled lines and 1- or 2-way caches are simulated exactly (the "
                      "table's method says which)");
  command->footer(
      "Examples:\n"
      "  rastrace sweep frame.rtrace --cache size=1KiB..64KiB,assoc=1/2/4/full,policy=fifo/lru/opt,"
      "layout=linear/block4/block8/morton --plot missrate.png\n"
      "  rastrace sweep old.din --cache size=4KiB..32KiB,line=32B/64B,assoc=1/2/full --format csv\n"
      "  rastrace sweep frame.rtrace --cache entries=4..64,policy=fifo/lru --format json\n"
      "  rastrace sweep frame.rtrace --cache size=1KiB..1MiB,policy=fifo/lru --shard 2/4 -o part-2.json\n"
      "  rastrace sweep long.rtrace --cache size=1KiB..4MiB,assoc=full/4,policy=lru/fifo --sample 1%");
  command->callback([o] {
    const TableFormat table_format = parse_table_format(o->format);
    std::optional<SweepShard> shard;
    if (!o->shard.empty()) {
      shard = parse_sweep_shard(o->shard);
      if (!o->plot.empty()) throw InputError("--plot with --shard: a part has no plot; draw it from the merge");
    }
    const TraceSummary summary = summarize_trace(o->trace);
    auto parameters = trace_parameters(o->trace, summary);

    o->retired.reject("--cache");

    const CacheSpec cache = parse_cache_spec(o->cache, "--cache");
    Table table;
    SweepPart part;
    if (cache.kind == CacheKind::Vertex) {
      if (!o->sample.empty()) throw InputError("--sample: vertex caches are exact in one pass already; drop --sample");
      const auto rows =
          run_vertex_sweep(o->trace, vertex_caches(cache), !o->keep_vertex_cache, shard.value_or(SweepShard{}));
      parameters.emplace_back("vertex_cache_per_draw", o->keep_vertex_cache ? "kept" : "flushed");
      table = vertex_cache_table("Post-transform vertex cache sweep", parameters, rows);
      part.configurations = cache.combinations();
      for (const VertexSweepRow& row : rows) part.row_configurations.push_back(row.configuration);
    } else {
      SweepSpec spec = sweep_spec(cache, default_source(summary));
      spec.shard = shard.value_or(SweepShard{});
      if (!o->sample.empty()) spec.sample = parse_sample_spec(o->sample, "--sample");
      const SweepResult result = run_sweep(o->trace, spec, o->threads);
      for (const std::string& skipped : result.skipped) std::cerr << "rastrace sweep: skipped " << skipped << "\n";
      add_sweep_parameters(spec, parameters);
      const std::string title = sweep_title(spec);
      table = byte_cache_table(title, parameters, result.rows, to_string(spec.source));
      part.configurations = result.configurations;
      part.skipped = result.skipped;
      for (const SweepRow& row : result.rows) part.row_configurations.push_back(row.configuration);
      if (!o->plot.empty())
        write_miss_rate_plot(o->plot, title + ": " + std::filesystem::path(o->trace).filename().string(), result.rows);
    }
    if (!shard) {
      write_output(o->output, render_table(table, table_format));
      return;
    }
    part.version = RASTRACE_VERSION;
    part.trace_digest = file_digest(o->trace);
    part.configuration = "cache=" + o->cache + (o->keep_vertex_cache ? " keep-vertex-cache" : "") +
                         (o->sample.empty() ? "" : " sample=" + o->sample);
    part.shard = *shard;
    part.table = std::move(table);
    write_output(o->output, sweep_part_json(part));
  });
}

}  // namespace rastrace

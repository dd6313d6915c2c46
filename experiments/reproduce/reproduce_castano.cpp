// Castano, "Optimal Grid Rendering" (2009): the 16x16 grid table at FIFO 20, 16 and 12, the grid
// order made for 8 and run on 16, and the W + 2 minimum cache. His numbers were counted by NVIDIA
// Mesh Tools (cache_sim/eviction_charged.h), so ours are counted the same way; the note gives the
// strict FIFO count where it differs.
#include "cache_sim/eviction_charged.h"
#include "cache_sim/vertex_cache.h"
#include "experiments/reproduce/reproduce.h"
#include "reorder/ordering.h"
#include "scenes/procedural.h"

namespace rastrace {

namespace {

constexpr double kTriangles = 512.0;  // 16x16 quads
constexpr double kVertices = 289.0;

struct Counts {
  std::uint64_t charged;
  std::uint64_t strict;
};

Counts run(const Mesh& grid, const std::string& algo, unsigned target, unsigned simulated) {
  ReorderParams params;
  params.cache_size = target;
  const Ordering ordering = find_reorder_algorithm(algo).run(grid, params);
  return {eviction_charged_transforms(ordering.indices, ordering.type, simulated, ordering.restart_index),
          simulate_vertex_stream(ordering.indices, ordering.type, VertexCachePolicy::Fifo, simulated,
                                 ordering.restart_index)
              .misses};
}

std::string strict_note(const Counts& counts, double per) {
  if (counts.charged == counts.strict) return "";
  char text[96];
  std::snprintf(text, sizeof text, "strict FIFO: %llu misses (%.3f)", static_cast<unsigned long long>(counts.strict),
                double(counts.strict) / per);
  return text;
}

}  // namespace

std::vector<ReproducedFigure> reproduce_castano() {
  const Mesh grid = make_grid(16, 16);
  const std::string paper = "Castano 2009", paper_mesh = "16x16 grid (289 v, 512 t)", our_mesh = "grid:16x16";
  struct Row {
    const char* method;
    const char* algo;
    double acmr20, acmr16, acmr12;
    const char* note;
  };
  const Row rows[] = {
      {"Scanline", "scanline", 1.062, 1.062, 1.062, ""},
      {"NVTriStrip", "nvstrip", 0.818, 0.775, 0.875, ""},
      {"Morton", "morton", 0.719, 0.750, 0.812, ""},
      // His row is not a figure of the algorithm: his implementation's look-ahead copies 8 bytes of
      // the cache (sizeof of an expression instead of n entries), so it starts from two valid entries
      // and stale memory; emulating that reproduces 0.807 at FIFO 12. Ours is the algorithm.
      {"K-Cache-Reorder", "kcache", 0.711, 0.766, 0.807,
       "his implementation's look-ahead copies only 8 bytes of the cache; ours: the algorithm as published"},
      {"Hilbert", "hilbert", 0.699, 0.754, 0.797, ""},
      {"Forsyth", "forsyth", 0.666, 0.699, 0.859, ""},
      {"Tipsy", "tipsy", 0.658, 0.711, 0.758, ""},
      {"Optimal", "grid", 0.564, 0.598, 0.600, ""},
  };
  std::vector<ReproducedFigure> figures;
  for (const Row& row : rows) {
    const std::pair<unsigned, double> sizes[] = {{20, row.acmr20}, {16, row.acmr16}, {12, row.acmr12}};
    for (const auto& [cache, published] : sizes) {
      const Counts counts = run(grid, row.algo, cache, cache);
      std::string note = row.note;
      const std::string strict = strict_note(counts, kTriangles);
      if (!strict.empty()) note += (note.empty() ? "" : "; ") + strict;
      figures.push_back({paper, std::string(row.method) + ", FIFO " + std::to_string(cache) + ": ACMR", paper_mesh,
                         our_mesh, published, double(counts.charged) / kTriangles, note});
    }
  }
  const Counts wrong_size = run(grid, "grid", 8, 16);
  figures.push_back({paper, "Optimal made for FIFO 8, run on 16: ATVR", paper_mesh, our_mesh, 1.125,
                     double(wrong_size.charged) / kVertices, strict_note(wrong_size, kVertices)});

  // The smallest cache for which the grid order transforms every vertex once.
  unsigned minimum = 0;
  for (unsigned cache = 3; cache <= 40 && !minimum; ++cache)
    if (run(grid, "grid", cache, cache).strict == 289) minimum = cache;
  figures.push_back(
      {paper, "Smallest FIFO with ATVR 1 (W + 2)", paper_mesh, our_mesh, std::int64_t{18}, std::int64_t{minimum}, ""});
  return figures;
}

}  // namespace rastrace

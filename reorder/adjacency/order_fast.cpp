// The "fast" ordering of adjacency primitives: Tipsy (Sander, Nehab, Barczak 2007) extended as in
// Sander, Nehab, Chlamtac, Hoppe 2008, section 6. See reorder/adjacency/order.h.
#include <stdexcept>

#include "reorder/adjacency/order.h"

namespace rastrace {

std::vector<std::uint32_t> order_adjacency_fast(const AdjacencyPrimitives& primitives, std::uint32_t vertex_count,
                                                unsigned cache_size) {
  const std::uint32_t P = static_cast<std::uint32_t>(primitives.size());
  const std::uint32_t* six = primitives.indices.data();
  if (cache_size == 0) throw std::invalid_argument("adjacency fast ordering: cache size 0");

  // vertex -> primitives whose cover face uses it (CSR); live = how many are not emitted yet.
  std::vector<std::uint32_t> offsets(vertex_count + 1, 0), live(vertex_count, 0);
  for (std::uint32_t p = 0; p < P; ++p)
    for (unsigned c = 0; c < 6; c += 2) {
      const std::uint32_t v = six[6 * p + c];
      if (c == 2 && v == six[6 * p]) continue;  // a degenerate cover face lists a vertex once
      if (c == 4 && (v == six[6 * p] || v == six[6 * p + 2])) continue;
      ++live[v];
    }
  for (std::uint32_t v = 0; v < vertex_count; ++v) offsets[v + 1] = offsets[v] + live[v];
  std::vector<std::uint32_t> fans(offsets[vertex_count]);
  {
    std::vector<std::uint32_t> fill(offsets.begin(), offsets.end() - 1);
    for (std::uint32_t p = 0; p < P; ++p)
      for (unsigned c = 0; c < 6; c += 2) {
        const std::uint32_t v = six[6 * p + c];
        if (c == 2 && v == six[6 * p]) continue;
        if (c == 4 && (v == six[6 * p] || v == six[6 * p + 2])) continue;
        fans[fill[v]++] = p;
      }
  }

  std::vector<std::uint32_t> order;
  order.reserve(P);
  std::vector<std::uint8_t> emitted(P, 0);
  std::vector<std::uint64_t> stamp(vertex_count, 0);
  std::uint64_t time = std::uint64_t{cache_size} + 1;
  std::vector<std::uint32_t> dead_end, candidates;
  dead_end.reserve(6 * std::size_t{P});
  std::uint32_t cursor = 0;
  constexpr std::uint32_t kNone = 0xFFFFFFFFu;
  std::uint32_t fan = P ? six[0] : kNone;
  const std::uint64_t k = cache_size;

  while (fan != kNone) {
    candidates.clear();
    for (std::uint32_t i = offsets[fan]; i < offsets[fan + 1]; ++i) {
      const std::uint32_t p = fans[i];
      if (emitted[p]) continue;
      emitted[p] = 1;
      order.push_back(p);
      for (unsigned c = 0; c < 6; ++c) {
        const std::uint32_t v = six[6 * p + c];
        if (time - stamp[v] > k) stamp[v] = time++;
        dead_end.push_back(v);
        candidates.push_back(v);
      }
      for (unsigned c = 0; c < 6; c += 2) {
        const std::uint32_t v = six[6 * p + c];
        if (c == 2 && v == six[6 * p]) continue;
        if (c == 4 && (v == six[6 * p] || v == six[6 * p + 2])) continue;
        --live[v];
      }
    }
    // Next fanning vertex: the oldest candidate whose remaining primitives (at most 5 misses
    // each) would still find it in the cache.
    std::uint32_t next = kNone;
    std::int64_t best = -1;
    for (const std::uint32_t v : candidates) {
      if (live[v] == 0) continue;
      std::int64_t priority = 0;
      if (time - stamp[v] + 5 * std::uint64_t{live[v]} <= k) priority = static_cast<std::int64_t>(time - stamp[v]);
      if (priority > best) {
        best = priority;
        next = v;
      }
    }
    while (next == kNone && !dead_end.empty()) {
      const std::uint32_t v = dead_end.back();
      dead_end.pop_back();
      if (live[v] > 0) next = v;
    }
    while (next == kNone && cursor < vertex_count) {
      if (live[cursor] > 0) next = cursor;
      ++cursor;
    }
    fan = next;
  }
  return order;
}

}  // namespace rastrace

// The "careful" ordering of adjacency primitives: K-Cache-Reorder (Lin and Yu 2006) extended as in
// Sander, Nehab, Chlamtac, Hoppe 2008, section 6. See reorder/adjacency_order.h.
#include <stdexcept>
#include <algorithm>

#include "reorder/adjacency_order.h"

namespace rastrace {
namespace {

constexpr std::uint32_t kNone = 0xFFFFFFFFu;

// A FIFO post-transform cache as timestamps, plus a ring of its last `entries` insertions so the
// resident vertices can be listed.
class Fifo {
 public:
  Fifo(std::uint32_t vertex_count, unsigned entries)
      : entries_(entries), stamp_(vertex_count, 0), time_(std::uint64_t{entries} + 1), ring_(entries, kNone) {}
  bool contains(std::uint32_t v) const { return time_ - stamp_[v] <= entries_; }
  std::uint64_t age(std::uint32_t v) const { return time_ - stamp_[v]; }
  void access(std::uint32_t v) {
    if (contains(v)) return;
    ring_[time_ % entries_] = v;
    stamp_[v] = time_++;
  }
  // Resident vertices, oldest first.
  template <typename Visit>
  void for_each_resident(Visit&& visit) const {
    for (std::uint64_t t = time_ - entries_; t < time_; ++t) {
      const std::uint32_t v = ring_[t % entries_];
      if (v != kNone && stamp_[v] == t) visit(v);
    }
  }

 private:
  std::uint64_t entries_;
  std::vector<std::uint64_t> stamp_;
  std::uint64_t time_;
  std::vector<std::uint32_t> ring_;
};

}  // namespace

std::vector<std::uint32_t> order_adjacency_careful(const AdjacencyPrimitives& primitives, std::uint32_t vertex_count,
                                                   unsigned cache_size) {
  const std::uint32_t P = static_cast<std::uint32_t>(primitives.size());
  const std::uint32_t* six = primitives.indices.data();
  if (cache_size == 0) throw std::invalid_argument("adjacency careful ordering: cache size 0");

  // vertex -> primitives referencing it anywhere among their six indices (each once).
  auto first_time = [&](std::uint32_t p, unsigned c) {
    for (unsigned j = 0; j < c; ++j)
      if (six[6 * p + j] == six[6 * p + c]) return false;
    return true;
  };
  std::vector<std::uint32_t> offsets(vertex_count + 1, 0), live(vertex_count, 0);
  for (std::uint32_t p = 0; p < P; ++p)
    for (unsigned c = 0; c < 6; ++c)
      if (first_time(p, c)) ++live[six[6 * p + c]];
  for (std::uint32_t v = 0; v < vertex_count; ++v) offsets[v + 1] = offsets[v] + live[v];
  std::vector<std::uint32_t> rings(offsets[vertex_count]);
  {
    std::vector<std::uint32_t> fill(offsets.begin(), offsets.end() - 1);
    for (std::uint32_t p = 0; p < P; ++p)
      for (unsigned c = 0; c < 6; ++c)
        if (first_time(p, c)) rings[fill[six[6 * p + c]]++] = p;
  }

  Fifo cache(vertex_count, cache_size);
  std::vector<std::uint8_t> emitted(P, 0);
  std::vector<std::uint32_t> order, ring, dead_end;
  order.reserve(P);
  std::vector<std::uint32_t> counted(vertex_count, kNone);  // per-evaluation stamp
  std::uint32_t evaluation = 0;
  std::uint32_t cursor = 0;

  // Misses of a set of primitives against the current cache, ignoring evictions inside the set.
  auto ring_misses = [&](std::uint32_t v) {
    ++evaluation;
    std::uint32_t misses = 0;
    for (std::uint32_t i = offsets[v]; i < offsets[v + 1]; ++i) {
      const std::uint32_t p = rings[i];
      if (emitted[p]) continue;
      for (unsigned c = 0; c < 6; ++c) {
        const std::uint32_t w = six[6 * p + c];
        if (counted[w] == evaluation) continue;
        counted[w] = evaluation;
        misses += !cache.contains(w);
      }
    }
    return misses;
  };
  auto primitive_misses = [&](std::uint32_t p) {
    std::uint32_t misses = 0;
    for (unsigned c = 0; c < 6; ++c) misses += first_time(p, c) && !cache.contains(six[6 * p + c]);
    return misses;
  };
  auto emit = [&](std::uint32_t p) {
    emitted[p] = 1;
    order.push_back(p);
    for (unsigned c = 0; c < 6; ++c) {
      const std::uint32_t w = six[6 * p + c];
      cache.access(w);
      if (first_time(p, c)) {
        --live[w];
        dead_end.push_back(w);
      }
    }
  };

  std::vector<std::uint32_t> resident;
  resident.reserve(cache_size);
  while (order.size() < P) {
    // Focus vertex: the resident vertex whose ring costs the fewest misses; on ties the one with
    // more primitives left, then the oldest (it is the next to be evicted).
    resident.clear();
    cache.for_each_resident([&](std::uint32_t v) { resident.push_back(v); });
    std::uint32_t focus = kNone, focus_misses = 0;
    for (const std::uint32_t v : resident) {
      if (live[v] == 0) continue;
      const std::uint32_t misses = ring_misses(v);
      if (focus == kNone || misses < focus_misses || (misses == focus_misses && live[v] > live[focus])) {
        focus = v;
        focus_misses = misses;
      }
    }
    while (focus == kNone && !dead_end.empty()) {
      const std::uint32_t v = dead_end.back();
      dead_end.pop_back();
      if (live[v] > 0) focus = v;
    }
    while (focus == kNone) {
      if (live[cursor] > 0) focus = cursor;
      ++cursor;
    }
    // Emit the ring, each time the primitive with the fewest misses now; on ties the one using the
    // oldest resident vertex, before it is evicted.
    ring.clear();
    for (std::uint32_t i = offsets[focus]; i < offsets[focus + 1]; ++i)
      if (!emitted[rings[i]]) ring.push_back(rings[i]);
    while (!ring.empty()) {
      std::size_t pick = 0;
      std::uint32_t fewest = 7;
      std::uint64_t oldest = 0;
      for (std::size_t i = 0; i < ring.size(); ++i) {
        const std::uint32_t m = primitive_misses(ring[i]);
        std::uint64_t age = 0;
        for (unsigned c = 0; c < 6; ++c)
          if (cache.contains(six[6 * ring[i] + c])) age = std::max(age, cache.age(six[6 * ring[i] + c]));
        if (m < fewest || (m == fewest && age > oldest)) {
          oldest = age;
          fewest = m;
          pick = i;
        }
      }
      emit(ring[pick]);
      ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(pick));
    }
  }
  return order;
}

}  // namespace rastrace

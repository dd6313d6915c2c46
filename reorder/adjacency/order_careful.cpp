// The "careful" ordering of adjacency primitives: K-Cache-Reorder (Lin and Yu 2006) extended as in
// Sander, Nehab, Chlamtac, Hoppe 2008, section 6, with a two-step look-ahead. See
// reorder/adjacency/order.h.
#include <algorithm>
#include <stdexcept>

#include "reorder/adjacency/order.h"

namespace rastrace {
namespace {

constexpr std::uint32_t kNone = 0xFFFFFFFFu;
// A resident vertex that a ring completes will never be reloaded; one about to leave the FIFO
// would most likely have been, so the bonus grows with its age: kCompletionWeight * age / K
// misses. Chosen at FIFO 24 on fandisk, triceratops and bunny00, checked at 12-32 (with 0, CM/V at 24 is
// 1-2.4% higher) and on meshes it was not tuned on: elephant, mushroom and cow (docs/PERFORMANCE.md). The misses are
// counted per ring, not per primitive: dividing by the ring's size (as kcache does for triangles) made CM/V 6-9%
// higher. Costs are kept in units of 1/K miss so that they are exact integers.
constexpr std::int64_t kCompletionWeight = 2;
// Look-ahead: the kBreadth[0] cheapest rings are each tried, then after each the kBreadth[1]
// cheapest next rings, then the best third ring is costed; the first ring of the cheapest
// sequence is emitted. Without it CM/V at cache 24 is 2-3% higher, with one level up to 1%;
// breadths {3, 3} or three levels gain another 0.2-1.6% for twice the time.
constexpr unsigned kDepth = 2;
constexpr std::size_t kBreadth[kDepth] = {3, 2};

struct Candidate {
  std::uint32_t vertex;
  std::uint32_t live;  // primitives left in its ring
  std::int64_t cost;   // in 1/K misses
};

class CarefulOrder {
 public:
  CarefulOrder(const AdjacencyPrimitives& primitives, std::uint32_t vertex_count, unsigned cache_size)
      : P_(static_cast<std::uint32_t>(primitives.size())),
        V_(vertex_count),
        k_(cache_size),
        six_(primitives.indices.data()),
        live_(vertex_count, 0),
        offsets_(vertex_count + 1, 0),
        stamp_(vertex_count, 0),
        time_(std::uint64_t{cache_size} + 1),
        fifo_(cache_size, kNone),
        emitted_(P_, 0),
        sim_mark_(vertex_count, 0),
        sim_stamp_(vertex_count, 0),
        live_mark_(vertex_count, 0),
        sim_live_(vertex_count, 0) {
    // vertex -> primitives referencing it anywhere among their six indices (each once).
    for (std::uint32_t p = 0; p < P_; ++p)
      for (unsigned c = 0; c < 6; ++c)
        if (first_time(p, c)) ++live_[six_[6 * p + c]];
    for (std::uint32_t v = 0; v < V_; ++v) offsets_[v + 1] = offsets_[v] + live_[v];
    rings_.resize(offsets_[V_]);
    std::vector<std::uint32_t> fill(offsets_.begin(), offsets_.end() - 1);
    for (std::uint32_t p = 0; p < P_; ++p)
      for (unsigned c = 0; c < 6; ++c)
        if (first_time(p, c)) rings_[fill[six_[6 * p + c]]++] = p;
  }

  std::vector<std::uint32_t> run() {
    std::vector<std::uint32_t> order, dead_end, sequence;
    order.reserve(P_);
    std::uint32_t cursor = 0;
    while (order.size() < P_) {
      std::uint32_t focus = kNone;
      search(0, &focus);
      while (focus == kNone && !dead_end.empty()) {  // no resident vertex has primitives left
        const std::uint32_t v = dead_end.back();
        dead_end.pop_back();
        if (live_[v] > 0) focus = v;
      }
      while (focus == kNone) {
        if (live_[cursor] > 0) focus = cursor;
        ++cursor;
      }
      sequence.clear();
      simulate(focus, &sequence);
      for (const std::uint32_t p : sequence) {
        emitted_[p] = 1;
        order.push_back(p);
        for (unsigned c = 0; c < 6; ++c) {
          const std::uint32_t w = six_[6 * p + c];
          if (!resident(w)) insert(w);
          if (first_time(p, c)) {
            --live_[w];
            dead_end.push_back(w);
          }
        }
      }
    }
    return order;
  }

 private:
  // A ring emitted and undone during the look-ahead.
  struct Level {
    std::vector<Candidate> candidates;
    std::vector<std::uint32_t> sequence, lives;
    std::vector<std::pair<std::uint32_t, std::uint64_t>> stamps;  // vertex, previous stamp
    std::vector<std::pair<std::uint32_t, std::uint32_t>> slots;   // FIFO slot, previous vertex
    std::uint64_t time = 0;
  };

  bool first_time(std::uint32_t p, unsigned c) const {
    for (unsigned j = 0; j < c; ++j)
      if (six_[6 * p + j] == six_[6 * p + c]) return false;
    return true;
  }
  bool resident(std::uint32_t v) const { return time_ - stamp_[v] <= k_; }
  void insert(std::uint32_t v) {
    fifo_[time_ % k_] = v;
    stamp_[v] = time_++;
  }

  // Emits the ring of v on a virtual copy of the FIFO (stamps and live counts overlaid by epoch),
  // each time the primitive with fewest misses, on ties the one using the oldest resident vertex.
  // Returns the cost: misses (reloads of vertices the ring itself pushes out included) minus the
  // age bonus of the resident vertices it completes. Appends the emission order to `sequence`.
  std::int64_t simulate(std::uint32_t v, std::vector<std::uint32_t>* sequence) {
    ++epoch_;
    std::uint64_t now = time_;
    inserted_.clear();
    ring_.clear();
    for (std::uint32_t i = offsets_[v]; i < offsets_[v + 1]; ++i)
      if (!emitted_[rings_[i]]) ring_.push_back(rings_[i]);
    auto stamp_of = [&](std::uint32_t w) { return sim_mark_[w] == epoch_ ? sim_stamp_[w] : stamp_[w]; };
    auto is_resident = [&](std::uint32_t w) { return now - stamp_of(w) <= k_; };
    std::uint32_t misses = 0;
    std::uint64_t completed_age = 0;
    while (!ring_.empty()) {
      std::size_t pick = 0;
      std::uint32_t fewest = 7;
      std::uint64_t oldest = 0;
      for (std::size_t i = 0; i < ring_.size(); ++i) {
        std::uint32_t m = 0;
        std::uint64_t age = 0;
        for (unsigned c = 0; c < 6; ++c) {
          const std::uint32_t w = six_[6 * ring_[i] + c];
          if (!first_time(ring_[i], c)) continue;
          if (is_resident(w))
            age = std::max(age, now - stamp_of(w));
          else
            ++m;
        }
        if (m < fewest || (m == fewest && age > oldest)) {
          fewest = m;
          oldest = age;
          pick = i;
        }
      }
      const std::uint32_t p = ring_[pick];
      ring_.erase(ring_.begin() + static_cast<std::ptrdiff_t>(pick));
      if (sequence) sequence->push_back(p);
      for (unsigned c = 0; c < 6; ++c) {
        const std::uint32_t w = six_[6 * p + c];
        if (is_resident(w)) continue;
        sim_mark_[w] = epoch_;
        sim_stamp_[w] = now++;
        inserted_.push_back(w);
        ++misses;
      }
      for (unsigned c = 0; c < 6; ++c) {
        if (!first_time(p, c)) continue;
        const std::uint32_t w = six_[6 * p + c];
        if (live_mark_[w] != epoch_) {
          live_mark_[w] = epoch_;
          sim_live_[w] = live_[w];
        }
        if (--sim_live_[w] == 0 && sim_mark_[w] != epoch_) completed_age += time_ - stamp_[w];
      }
    }
    return static_cast<std::int64_t>(misses * k_) - kCompletionWeight * static_cast<std::int64_t>(completed_age);
  }

  // The resident vertices with primitives left, cheapest ring first; ties to the larger ring,
  // then the older vertex (nearer eviction).
  void gather(std::vector<Candidate>& candidates) {
    candidates.clear();
    for (std::uint64_t t = time_ - k_; t < time_; ++t) {
      const std::uint32_t v = fifo_[t % k_];
      if (v == kNone || stamp_[v] != t || live_[v] == 0) continue;
      candidates.push_back({v, live_[v], simulate(v, nullptr)});
    }
    std::stable_sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
      if (a.cost != b.cost) return a.cost < b.cost;
      return a.live > b.live;
    });
  }

  // The cost of the cheapest sequence of depth - level + 1 rings from the current state; `best`
  // receives its first ring's vertex. A ring that costs nothing is taken without looking ahead.
  std::int64_t search(unsigned level, std::uint32_t* best) {
    std::vector<Candidate>& candidates = levels_[level].candidates;
    gather(candidates);
    if (candidates.empty()) return 0;
    if (best) *best = candidates[0].vertex;
    if (level == kDepth || candidates[0].cost <= 0) return candidates[0].cost;
    std::int64_t cheapest = 0;
    const std::size_t n = std::min(candidates.size(), kBreadth[level]);
    for (std::size_t j = 0; j < n; ++j) {
      const Candidate candidate = candidates[j];
      Level& undo = levels_[level + 1];
      undo.sequence.clear();
      simulate(candidate.vertex, &undo.sequence);
      apply(undo);
      const std::int64_t total = candidate.cost + search(level + 1, nullptr);
      revert(undo);
      if (j == 0 || total < cheapest) {
        cheapest = total;
        if (best) *best = candidate.vertex;
      }
    }
    return cheapest;
  }

  void apply(Level& undo) {
    undo.stamps.clear();
    undo.slots.clear();
    undo.lives.clear();
    undo.time = time_;
    for (const std::uint32_t p : undo.sequence) {
      emitted_[p] = 1;
      for (unsigned c = 0; c < 6; ++c) {
        const std::uint32_t w = six_[6 * p + c];
        if (!resident(w)) {
          undo.slots.emplace_back(static_cast<std::uint32_t>(time_ % k_), fifo_[time_ % k_]);
          undo.stamps.emplace_back(w, stamp_[w]);
          insert(w);
        }
        if (first_time(p, c)) {
          --live_[w];
          undo.lives.push_back(w);
        }
      }
    }
  }
  void revert(const Level& undo) {
    for (std::size_t i = undo.stamps.size(); i-- > 0;) {
      stamp_[undo.stamps[i].first] = undo.stamps[i].second;
      fifo_[undo.slots[i].first] = undo.slots[i].second;
    }
    for (const std::uint32_t w : undo.lives) ++live_[w];
    for (const std::uint32_t p : undo.sequence) emitted_[p] = 0;
    time_ = undo.time;
  }

  std::uint32_t P_, V_;
  std::uint64_t k_;
  const std::uint32_t* six_;
  std::vector<std::uint32_t> live_, offsets_, rings_;
  // The FIFO as timestamps (v resident while time_ - stamp_[v] <= k_) plus the vertex inserted at
  // each of the last k_ times, so the resident vertices can be listed oldest first.
  std::vector<std::uint64_t> stamp_;
  std::uint64_t time_;
  std::vector<std::uint32_t> fifo_;
  std::vector<std::uint8_t> emitted_;
  // simulate()'s overlay, valid where the mark equals the current epoch.
  std::uint64_t epoch_ = 0;  // about 250 simulations per ring: 32 bits could wrap on large meshes
  std::vector<std::uint64_t> sim_mark_;
  std::vector<std::uint64_t> sim_stamp_;
  std::vector<std::uint64_t> live_mark_;
  std::vector<std::uint32_t> sim_live_;
  std::vector<std::uint32_t> inserted_, ring_;
  Level levels_[kDepth + 1];
};

}  // namespace

std::vector<std::uint32_t> order_adjacency_careful(const AdjacencyPrimitives& primitives, std::uint32_t vertex_count,
                                                   unsigned cache_size) {
  if (cache_size == 0) throw std::invalid_argument("adjacency careful ordering: cache size 0");
  return CarefulOrder(primitives, vertex_count, cache_size).run();
}

}  // namespace rastrace

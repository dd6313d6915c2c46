// Hoppe 1999, section 6: local optimization of the face order (see local_opt.h).
#include "reorder/local_opt.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <numeric>
#include <span>
#include <string>

#include "core/error.h"
#include "core/progress.h"
#include "core/rng.h"
#include "reorder/greedy.h"
#include "reorder/strip.h"

namespace rastrace {

namespace {

constexpr int kCaches = 3;                 // sizes k-1, k, k+1
constexpr std::int64_t kStripCost = 6000;  // 6 bytes per strip, scaled by 1000
// The partners y of a face's vertex: every face of a vertex in at most kAllPartnersDegree faces
// (any well-formed mesh: the paper's rule), else the faces of the vertex within kNearWindow
// positions of x and kFarPartners spread over the rest (see best_from).
constexpr std::size_t kAllPartnersDegree = 32;
constexpr std::int64_t kNearWindow = 8;
constexpr std::size_t kFarPartners = 8;
// An evaluation re-simulates from a slice point until the caches agree with the stored ones again.
// Around a vertex in many faces they may never agree: on a fan every face re-reads the centre, a
// FIFO evicts it every k misses, and a perturbation shifts that phase for the rest of the order
// (24 vertices under a FIFO of 16 likewise), so each evaluation re-simulated the whole order. For
// perturbations of such faces the evaluation stops after this many faces without agreement, with
// the change so far: an estimate, which apply() checks against the true cost before keeping the
// perturbation. Faces of well-formed meshes are never crowded, and their evaluations stay exact.
constexpr std::int64_t kCrowdedEvaluationFaces = 256;

// The FIFO of the short re-simulations, as insertion time stamps (a vertex is resident while fewer
// than `cap` misses happened since it was inserted): O(1) per access for any cache size. clear()
// moves the clock past every stamp, so no array is ever cleared.
class StampFifo {
 public:
  void reset(unsigned cap, std::size_t vertices) {
    cap_ = cap;
    stamps_.assign(vertices, 0);
    clock_ = std::uint64_t{cap} + 1;
  }
  void clear() { clock_ += std::uint64_t{cap_} + 1; }
  bool access(std::uint32_t v) {
    if (clock_ - stamps_[v] <= cap_) return true;
    stamps_[v] = clock_++;
    return false;
  }
  void push(std::uint32_t v) { stamps_[v] = clock_++; }

 private:
  std::vector<std::uint64_t> stamps_;
  std::uint64_t clock_ = 1;
  unsigned cap_ = 0;
};

// Misses in a mask of at most 3 accesses (a table: the build does not assume a popcount instruction).
inline unsigned miss_count(std::uint8_t mask) {
  constexpr std::uint8_t kBits[8] = {0, 1, 1, 2, 1, 2, 2, 3};
  return kBits[mask & 7u];
}

// The vertices a face reads in the strip stream, in order (see Local::accesses).
struct AccessList {
  std::uint32_t v[3] = {0, 0, 0};
  std::uint32_t n = 0;
};

// Sums of per-position values over ranges, with point updates (a Fenwick tree): the reverse minus
// forward cost of the faces evaluate() skips inside a reversed piece, kept exact as F changes
// without an O(m) pass per applied perturbation.
class PrefixSums {
 public:
  void assign(const std::vector<std::int64_t>& values) {
    value_ = values;
    const std::size_t n = values.size();
    tree_.assign(n + 1, 0);
    for (std::size_t i = 1; i <= n; ++i) tree_[i] += values[i - 1];
    for (std::size_t i = 1; i <= n; ++i)
      if (const std::size_t j = i + (i & (~i + 1)); j <= n) tree_[j] += tree_[i];
  }
  void set(std::size_t i, std::int64_t value) {
    const std::int64_t delta = value - value_[i];
    if (delta == 0) return;
    value_[i] = value;
    for (std::size_t j = i + 1; j < tree_.size(); j += j & (~j + 1)) tree_[j] += delta;
  }
  // The sum of the values at positions [lo, hi).
  std::int64_t sum(std::size_t lo, std::size_t hi) const { return prefix(hi) - prefix(lo); }

 private:
  std::int64_t prefix(std::size_t end) const {
    std::int64_t total = 0;
    for (std::size_t j = end; j > 0; j -= j & (~j + 1)) total += tree_[j];
    return total;
  }
  std::vector<std::int64_t> value_;
  std::vector<std::int64_t> tree_;
};

// One perturbation as F' = concatenation of ranges of F (reversed or not), at most 5 pieces.
struct Segment {
  std::uint32_t lo = 0, hi = 0;  // F positions, inclusive
  bool reversed = false;
  std::uint32_t start = 0;  // F' position of its first face
  std::uint32_t size() const { return hi - lo + 1; }
};
struct CostModel {
  unsigned sizes[kCaches] = {0, 0, 0};  // FIFO entries; 0: cache not modelled
  std::int64_t weights[kCaches] = {0, 0, 0};
  std::int64_t strip_cost = 0;
};
struct Perturbation {
  enum Type : std::uint8_t { Reflect, Insert1, Insert2 } type = Reflect;
  std::uint32_t x = 0, y = 0;
  std::int64_t delta = 0;
};

class Local {
 public:
  // Hoppe's cost for a FIFO of k entries.
  static CostModel hoppe(unsigned k) {
    CostModel model;
    model.sizes[0] = k > 1 ? k - 1 : 0;
    model.sizes[1] = k;
    model.sizes[2] = k + 1;
    model.weights[0] = k > 1 ? 3 : 0;
    model.weights[1] = 32000;
    model.weights[2] = 2;
    model.strip_cost = kStripCost;
    return model;
  }
  Local(const Mesh& mesh, const MeshTopology& topology, const CostModel& model, std::vector<std::uint32_t>& order)
      : mesh_(mesh), t_(topology), idx_(mesh.indices.data()), F_(order), m_(static_cast<std::uint32_t>(order.size())) {
    for (int c = 0; c < kCaches; ++c) {
      size_[c] = model.sizes[c];
      weight_[c] = size_[c] ? model.weights[c] : 0;
    }
    strip_cost_ = model.strip_cost;
    pos_.resize(t_.face_count);
    for (int c = 0; c < kCaches; ++c) {
      fwd_[c].assign(t_.face_count, 0);
      rev_[c].assign(t_.face_count, 0);
      stamp_[c].assign(t_.vertex_count, 0);
      fifo_[c].reset(std::max(size_[c], 1u), t_.vertex_count);
    }
    fwd_list_.assign(t_.face_count, AccessList{});
    rev_list_.assign(t_.face_count, AccessList{});
    found_.assign(*std::max_element(size_, size_ + kCaches), 0);
    fwd_cost_.assign(t_.face_count, 0);
    rev_cost_.assign(t_.face_count, 0);
    face_mark_.assign(t_.face_count, 0);
    crowded_.assign(t_.face_count, 0);
    for (std::uint32_t f = 0; f < t_.face_count; ++f)
      for (int i = 0; i < 3; ++i)
        if (crowded_vertex(idx_[3 * std::size_t(f) + i])) crowded_[f] = 1;
    recompute();
  }

  std::int64_t cost() const { return cost_; }

  void run(const ReorderParams& params, LocalStats& stats) {
    stats.initial_cost = cost_;
    if (m_ < 3) {
      stats.final_cost = cost_;
      stats.converged = true;
      return;
    }
    std::vector<std::uint32_t> visit(t_.face_count);
    std::iota(visit.begin(), visit.end(), 0u);
    Rng rng(params.seed);
    shuffle(std::span(visit), rng);

    const std::uint64_t budget = params.iteration_budget;
    const auto start = std::chrono::steady_clock::now();
    bool out_of_budget = false;
    while (!out_of_budget) {
      ++stats.passes;
      Progress progress("local optimization, pass " + std::to_string(stats.passes),
                        budget ? std::min<std::uint64_t>(budget - stats.iterations, m_) : m_);
      bool improved = false;
      for (const std::uint32_t f : visit) {
        if (budget && stats.iterations >= budget) {
          out_of_budget = true;
          break;
        }
        // The clock every iteration: on meshes where a vertex is in thousands of faces (fans, few
        // vertices) one iteration can take milliseconds, and 64 of them overran a budget 70-fold.
        if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() >
                params.time_budget_seconds) {
          out_of_budget = true;
          break;
        }
        ++stats.iterations;
        progress.advance();
        const std::uint32_t x = pos_[f];
        if (pruned(x)) continue;
        Perturbation best = best_from(x, stats);
        if (best.delta >= 0) continue;
        // Chase a locally better perturbation: from y, the best partner z; stop when it points
        // back at x or stops improving.
        for (int chase = 0; chase < 8; ++chase) {
          const Perturbation next = best_from(best.y, stats);
          if (next.delta >= best.delta || next.y == best.x) break;
          best = next;
        }
        if (apply(best)) {
          ++stats.applied;
          improved = true;
        } else {
          ++stats.rejected;
        }
      }
      if (!budget && !improved) {
        stats.converged = true;
        break;
      }
    }
    stats.final_cost = cost_;
  }

 private:
  std::uint32_t at(std::int64_t q) const { return q < 0 || q >= std::int64_t(m_) ? kNoFace : F_[std::size_t(q)]; }
  bool continues(std::uint32_t a, std::uint32_t b) const {
    return a != kNoFace && b != kNoFace && strip_continues(mesh_, t_, a, b);
  }

  // The vertices face f reads in the strip stream strip.h emits, given the two faces before it
  // and the one after it: a strip's first face reads three (exit edge last), a face continuing
  // a strip reads its new vertex, preceded by the repeated pivot when the strip swaps. The pivot
  // matters: re-reading an evicted pivot shifts the whole FIFO.
  unsigned accesses(std::uint32_t before_prev, std::uint32_t prev, std::uint32_t f, std::uint32_t next,
                    std::uint32_t out[3]) const {
    const std::uint32_t* v = idx_ + 3 * std::size_t(f);
    if (continues(prev, f)) {
      const std::uint32_t* p = idx_ + 3 * std::size_t(prev);
      const std::uint32_t nv = not_in(v, p);
      // w: the newer vertex of the strip's last edge (prev's new vertex, or the second vertex of
      // prev's exit edge when prev started the strip).
      std::uint32_t w;
      if (continues(before_prev, prev)) {
        w = not_in(p, idx_ + 3 * std::size_t(before_prev));
      } else {
        unsigned s = 0;
        while (s < 2 && t_.neighbor(prev, s) != f) ++s;
        w = p[(s + 1) % 3];
      }
      if (continues(f, next)) {
        const int slot = edge_slot(v, w, nv);
        if (slot < 0 || t_.neighbor(f, unsigned(slot)) != next) {
          const std::uint32_t u = v[0] != nv && v[0] != w ? v[0] : v[1] != nv && v[1] != w ? v[1] : v[2];
          out[0] = u;
          out[1] = nv;
          return 2;
        }
      }
      out[0] = nv;
      return 1;
    }
    if (continues(f, next))
      for (unsigned s = 0; s < 3; ++s)
        if (t_.neighbor(f, s) == next) {
          out[0] = v[(s + 2) % 3];
          out[1] = v[s];
          out[2] = v[(s + 1) % 3];
          return 3;
        }
    out[0] = v[0];
    out[1] = v[1];
    out[2] = v[2];
    return 3;
  }
  // The first vertex of a that is not a vertex of b (a[0] if there is none).
  static std::uint32_t not_in(const std::uint32_t* a, const std::uint32_t* b) {
    for (int j = 0; j < 3; ++j)
      if (a[j] != b[0] && a[j] != b[1] && a[j] != b[2]) return a[j];
    return a[0];
  }

  std::int64_t weighted(const std::uint8_t masks[kCaches]) const {
    std::int64_t cost = 0;
    for (int c = 0; c < kCaches; ++c) cost += weight_[c] * miss_count(masks[c]);
    return cost;
  }

  // Full simulation of F forwards and backwards: the stored miss bits, costs and prefix sums.
  void recompute() {
    for (std::uint32_t q = 0; q < m_; ++q) pos_[F_[q]] = q;
    for (int dir = 0; dir < 2; ++dir) {
      for (int c = 0; c < kCaches; ++c) clock_[c] += size_[c] + 2;  // invalidates every stamp
      for (std::uint32_t i = 0; i < m_; ++i) {
        const std::int64_t q = dir == 0 ? i : m_ - 1 - i;
        const std::uint32_t f = F_[std::size_t(q)];
        const std::uint32_t prev = at(dir == 0 ? q - 1 : q + 1), next = at(dir == 0 ? q + 1 : q - 1);
        AccessList& stored = (dir == 0 ? fwd_list_ : rev_list_)[f];
        stored.n = accesses(at(dir == 0 ? q - 2 : q + 2), prev, f, next, stored.v);
        const std::uint32_t* list = stored.v;
        const unsigned n = stored.n;
        std::uint8_t masks[kCaches] = {0, 0, 0};
        for (int c = 0; c < kCaches; ++c) {
          if (size_[c] == 0) continue;
          for (unsigned j = 0; j < n; ++j) {
            std::uint32_t& s = stamp_[c][list[j]];
            if (clock_[c] - s <= size_[c]) continue;
            s = clock_[c]++;
            masks[c] |= std::uint8_t(1u << j);
          }
          (dir == 0 ? fwd_ : rev_)[c][f] = masks[c];
        }
        (dir == 0 ? fwd_cost_ : rev_cost_)[f] = weighted(masks);
      }
    }
    cost_ = strip_cost_ * strip_starts(0, std::int64_t(m_) - 1);
    std::vector<std::int64_t> skipped(m_);
    for (std::uint32_t q = 0; q < m_; ++q) {
      const std::uint32_t f = F_[q];
      cost_ += fwd_cost_[f];
      skipped[q] = rev_cost_[f] - fwd_cost_[f];
    }
    rev_minus_fwd_.assign(skipped);
  }

  // Faces at F positions [lo, hi] that start a strip.
  std::int64_t strip_starts(std::int64_t lo, std::int64_t hi) const {
    std::int64_t starts = 0;
    for (std::int64_t q = std::max<std::int64_t>(lo, 0); q <= std::min<std::int64_t>(hi, std::int64_t(m_) - 1); ++q)
      starts += q == 0 || !continues(F_[std::size_t(q) - 1], F_[std::size_t(q)]);
    return starts;
  }

  // Loads the caches with the state just before F position p in the forward traversal (or, when
  // reverse, just before p in the reverse traversal): the last `size` stored misses.
  void load(std::int64_t p, bool reverse) {
    for (int c = 0; c < kCaches; ++c) {
      if (size_[c] == 0) continue;
      std::uint32_t* found = found_.data();
      unsigned n = 0;
      const unsigned want = size_[c];
      const std::vector<AccessList>& lists = reverse ? rev_list_ : fwd_list_;
      for (std::int64_t q = reverse ? p + 1 : p - 1; q >= 0 && q < std::int64_t(m_) && n < want;
           q += reverse ? 1 : -1) {
        const std::uint32_t f = F_[std::size_t(q)];
        const std::uint8_t mask = (reverse ? rev_ : fwd_)[c][f];
        if (!mask) continue;
        const AccessList& list = lists[f];
        for (unsigned j = list.n; j-- > 0 && n < want;)
          if (mask & (1u << j)) found[n++] = list.v[j];
      }
      fifo_[c].clear();
      for (unsigned j = n; j-- > 0;) fifo_[c].push(found[j]);
    }
  }

  // Builds F' for a perturbation; returns false if it is not applicable.
  bool segments(const Perturbation& p, Segment* seg, int& count) const {
    const std::uint32_t x = p.x, y = p.y;
    count = 0;
    auto add = [&](std::int64_t lo, std::int64_t hi, bool reversed) {
      if (lo > hi) return;
      seg[count].lo = std::uint32_t(lo);
      seg[count].hi = std::uint32_t(hi);
      seg[count].reversed = reversed;
      ++count;
    };
    const std::int64_t last = std::int64_t(m_) - 1;
    switch (p.type) {
      case Perturbation::Reflect: {
        const std::int64_t lo = std::min(x, y), hi = std::max(x, y);
        if (lo == hi) return false;
        add(0, lo - 1, false);
        add(lo, hi, true);
        add(hi + 1, last, false);
        break;
      }
      case Perturbation::Insert1:
        if (x == y) return false;
        if (y > x) {
          add(0, std::int64_t(x) - 1, false);
          add(x + 1, y, false);
          add(x, x, false);
          add(std::int64_t(y) + 1, last, false);
        } else {
          add(0, std::int64_t(y) - 1, false);
          add(x, x, false);
          add(y, std::int64_t(x) - 1, false);
          add(std::int64_t(x) + 1, last, false);
        }
        break;
      case Perturbation::Insert2:
        if (x + 1 >= m_ || y == x || y == x + 1) return false;
        if (y > x) {
          add(0, std::int64_t(x) - 1, false);
          add(x + 2, y, false);
          add(x, x + 1, false);
          add(std::int64_t(y) + 1, last, false);
        } else {
          add(0, std::int64_t(y) - 1, false);
          add(x, x + 1, false);
          add(y, std::int64_t(x) - 1, false);
          add(std::int64_t(x) + 2, last, false);
        }
        break;
    }
    std::uint32_t start = 0;
    for (int i = 0; i < count; ++i) {
      seg[i].start = start;
      start += seg[i].size();
    }
    return true;
  }

  static std::uint32_t face_in(const std::vector<std::uint32_t>& F, const Segment& s, std::uint32_t j) {
    const std::uint32_t offset = j - s.start;
    return F[s.reversed ? s.hi - offset : s.lo + offset];
  }
  std::uint32_t prime_at(const Segment* seg, int count, std::int64_t j) const {
    if (j < 0 || j >= std::int64_t(m_)) return kNoFace;
    int i = count - 1;
    while (seg[i].start > j) --i;
    return face_in(F_, seg[i], std::uint32_t(j));
  }

  // Cost change of a perturbation, by re-simulating only near its slice points.
  std::int64_t evaluate(const Perturbation& p, LocalStats& stats) {
    Segment seg[5];
    int count = 0;
    if (!segments(p, seg, count)) return 0;
    ++stats.evaluations;
    // Strip changes happen only at the slice points.
    std::int64_t delta = 0;
    for (int i = 0; i + 1 < count; ++i) {
      const std::uint32_t a = face_in(F_, seg[i], seg[i].start + seg[i].size() - 1);
      const std::uint32_t b = face_in(F_, seg[i + 1], seg[i + 1].start);
      delta += continues(a, b) ? 0 : strip_cost_;
    }
    {
      Segment sorted[5];
      std::copy(seg, seg + count, sorted);
      for (int i = 1; i < count; ++i)  // insertion sort by F position (at most 4 pieces)
        for (int k = i; k > 0 && sorted[k].lo < sorted[k - 1].lo; --k) std::swap(sorted[k], sorted[k - 1]);
      for (int i = 0; i + 1 < count; ++i) delta -= continues(F_[sorted[i].hi], F_[sorted[i + 1].lo]) ? 0 : strip_cost_;
    }
    // Misses: from the last untouched face (its successor changed) onwards; F' and F agree
    // before it, so the caches start from F's stored state.
    std::int64_t j = !seg[0].reversed && seg[0].lo == 0 ? std::int64_t(seg[0].hi) : 0;
    int s = 0;
    load(j, false);  // before F' position j: untouched prefix, so F's own state
    unsigned sync[kCaches] = {0, 0, 0};
    int sync_segment = s;
    const std::int64_t give_up = crowded_[F_[p.x]] || crowded_[F_[p.y]] ? kCrowdedEvaluationFaces : std::int64_t(m_);
    std::int64_t unsynced = 0;
    for (; j < std::int64_t(m_); ++j) {
      if (++unsynced > give_up) break;  // an estimate: apply() checks the true cost
      while (s + 1 < count && seg[s + 1].start <= j) ++s;
      if (s != sync_segment) {
        sync_segment = s;
        sync[0] = sync[1] = sync[2] = 0;
      }
      const Segment& g = seg[s];
      const std::uint32_t offset = std::uint32_t(j) - g.start;
      const std::int64_t q = g.reversed ? g.hi - offset : g.lo + offset;  // F position
      const std::uint32_t f = F_[std::size_t(q)];
      const std::uint32_t before_prev = prime_at(seg, count, j - 2);
      const std::uint32_t prev = prime_at(seg, count, j - 1), next = prime_at(seg, count, j + 1);
      const bool same_context = g.reversed ? prev == at(q + 1) && next == at(q - 1) && before_prev == at(q + 2)
                                           : prev == at(q - 1) && next == at(q + 1) && before_prev == at(q - 2);
      // Away from the slice points a face reads what it reads in F (or in F's reverse traversal).
      AccessList fresh;
      if (!same_context) fresh.n = accesses(before_prev, prev, f, next, fresh.v);
      const AccessList& list = same_context ? (g.reversed ? rev_list_ : fwd_list_)[f] : fresh;
      std::uint8_t masks[kCaches] = {0, 0, 0};
      for (int c = 0; c < kCaches; ++c) {
        if (size_[c] == 0) continue;
        for (unsigned a = 0; a < list.n; ++a)
          if (!fifo_[c].access(list.v[a])) masks[c] |= std::uint8_t(1u << a);
      }
      delta += weighted(masks) - fwd_cost_[f];
      bool same = same_context;
      for (int c = 0; c < kCaches && same; ++c) same = masks[c] == (g.reversed ? rev_ : fwd_)[c][f];
      if (!same) {
        sync[0] = sync[1] = sync[2] = 0;
        continue;
      }
      bool synced = true;
      for (int c = 0; c < kCaches; ++c) {
        sync[c] += unsigned(miss_count(masks[c]));
        synced &= sync[c] >= size_[c];
      }
      if (!synced) continue;
      // The caches agree with F's: the rest of this piece behaves as stored, up to its last face
      // (whose successor changed).
      if (s == count - 1 && !g.reversed && g.hi == m_ - 1) return delta;
      const std::int64_t end = std::int64_t(g.start) + g.size() - 1;  // F' position of the piece's last face
      if (j + 1 < end) {
        if (g.reversed) {
          // Skipped F positions lo+1 .. q-1 keep their reverse-traversal costs.
          delta += rev_minus_fwd_.sum(std::size_t(g.lo) + 1, std::size_t(q));
          load(g.lo, true);
        } else {
          load(g.hi, false);
        }
        j = end - 1;
      }
      unsynced = 0;
    }
    return delta;
  }

  Perturbation best_from(std::uint32_t x, LocalStats& stats) {
    Perturbation best;
    best.x = x;
    best.y = x;
    best.delta = 0;
    const std::uint32_t f = F_[x];
    ++mark_;
    auto consider = [&](std::uint32_t y) {
      for (const Perturbation::Type type : {Perturbation::Reflect, Perturbation::Insert1, Perturbation::Insert2}) {
        Perturbation p;
        p.type = type;
        p.x = x;
        p.y = y;
        p.delta = evaluate(p, stats);
        if (p.delta < best.delta) best = p;
      }
    };
    face_mark_[f] = mark_;
    if (x > 0) {
      face_mark_[F_[x - 1]] = mark_;
      consider(x - 1);
    }
    if (x + 1 < m_) {
      face_mark_[F_[x + 1]] = mark_;
      consider(x + 1);
    }
    // At a strip's end, the strip's other end: Reflect then turns the whole strip around.
    const bool starts = x == 0 || !continues(F_[x - 1], f), ends = x + 1 == m_ || !continues(f, F_[x + 1]);
    if (starts != ends) {
      std::int64_t y = x;
      if (starts)
        while (y + 1 < std::int64_t(m_) && continues(F_[std::size_t(y)], F_[std::size_t(y) + 1])) ++y;
      else
        while (y > 0 && continues(F_[std::size_t(y) - 1], F_[std::size_t(y)])) --y;
      if (face_mark_[F_[std::size_t(y)]] != mark_) {
        face_mark_[F_[std::size_t(y)]] = mark_;
        consider(std::uint32_t(y));
      }
    }
    const std::uint32_t* v = idx_ + 3 * std::size_t(f);
    auto consider_face = [&](std::uint32_t g) {
      if (face_mark_[g] == mark_) return;
      face_mark_[g] = mark_;
      consider(pos_[g]);
    };
    for (int i = 0; i < 3; ++i) {
      const std::span<const std::uint32_t> faces = t_.faces_of_vertex(v[i]);
      if (!crowded_vertex(v[i])) {
        for (const std::uint32_t g : faces) consider_face(g);
        continue;
      }
      // A vertex in many faces (a fan's centre, a non-manifold edge, a mesh of few vertices):
      // trying every face of it makes one x cost O(degree) evaluations and a pass O(m * degree),
      // a fan of 3,000 faces then spends the whole time budget. Bounded instead: the faces of v
      // near x in the order (the partners of the short moves, which do most of the gain) and a
      // stride through the rest (far moves), its start turning with x so that successive passes
      // reach different faces.
      const std::int64_t lo = std::max<std::int64_t>(0, std::int64_t(x) - kNearWindow);
      const std::int64_t hi = std::min<std::int64_t>(std::int64_t(m_) - 1, std::int64_t(x) + kNearWindow);
      for (std::int64_t q = lo; q <= hi; ++q) {
        const std::uint32_t g = F_[std::size_t(q)];
        const std::uint32_t* w = idx_ + 3 * std::size_t(g);
        if (w[0] == v[i] || w[1] == v[i] || w[2] == v[i]) consider_face(g);
      }
      const std::size_t stride = faces.size() / kFarPartners;
      for (std::size_t j = (x + stats.passes) % stride; j < faces.size(); j += stride) consider_face(faces[j]);
    }
    return best;
  }

  // A vertex in more faces than the paper's rule can afford as partners (see kAllPartnersDegree).
  bool crowded_vertex(std::uint32_t v) const { return t_.faces_of_vertex(v).size() > kAllPartnersDegree; }

  bool pruned(std::uint32_t x) const {
    const std::uint32_t f = F_[x];
    const std::uint32_t prev = at(std::int64_t(x) - 1), next = at(std::int64_t(x) + 1);
    if (!continues(prev, f) || !continues(f, next)) return false;  // strip ends are always tried
    const unsigned misses = miss_count(fwd_[1][prev]) + miss_count(fwd_[1][f]) + miss_count(fwd_[1][next]);
    return misses < 3;
  }

  // Applies p, then checks the true cost; undoes it if the cost did not drop.
  bool apply(const Perturbation& p) {
    Segment seg[5];
    int count = 0;
    if (!segments(p, seg, count)) return false;
    // F' differs from F only between lo and hi.
    const std::int64_t lo = !seg[0].reversed && seg[0].lo == 0 ? std::int64_t(seg[0].size()) : 0;
    const Segment& last = seg[count - 1];
    const std::int64_t hi = !last.reversed && last.start == last.lo && last.hi == m_ - 1 ? std::int64_t(last.start) - 1
                                                                                         : std::int64_t(m_) - 1;
    const std::int64_t before = cost_;
    old_.assign(F_.begin() + lo, F_.begin() + hi + 1);
    new_.clear();
    for (int i = 0; i < count; ++i)
      for (std::uint32_t j = seg[i].start; j < seg[i].start + seg[i].size(); ++j)
        if (std::int64_t(j) >= lo && std::int64_t(j) <= hi) new_.push_back(face_in(F_, seg[i], j));
    replace(lo, hi, new_);
    if (cost_ < before) return true;
    replace(lo, hi, old_);
    return false;
  }

  // Writes faces into F positions [lo, hi] and brings the stored state and the cost up to date.
  void replace(std::int64_t lo, std::int64_t hi, const std::vector<std::uint32_t>& faces) {
    cost_ -= strip_cost_ * strip_starts(lo, hi + 1);
    std::copy(faces.begin(), faces.end(), F_.begin() + lo);
    cost_ += strip_cost_ * strip_starts(lo, hi + 1);
    resimulate(lo, hi);
  }

  // After F changed between positions lo and hi: re-simulates forwards from just before lo and
  // backwards from just after hi, each until the caches agree with the stored bits again.
  void resimulate(std::int64_t lo, std::int64_t hi) {
    for (std::int64_t q = lo; q <= hi; ++q) {
      const std::uint32_t f = F_[std::size_t(q)];
      pos_[f] = std::uint32_t(q);
      rev_minus_fwd_.set(std::size_t(q), rev_cost_[f] - fwd_cost_[f]);
    }
    for (int dir = 0; dir < 2; ++dir) {
      const bool reverse = dir == 1;
      std::int64_t q =
          reverse ? std::min<std::int64_t>(std::int64_t(m_) - 1, hi + 1) : std::max<std::int64_t>(0, lo - 1);
      load(q, reverse);
      unsigned sync[kCaches] = {0, 0, 0};
      for (; q >= 0 && q < std::int64_t(m_); q += reverse ? -1 : 1) {
        const std::uint32_t f = F_[std::size_t(q)];
        AccessList& list = (reverse ? rev_list_ : fwd_list_)[f];
        list.n = reverse ? accesses(at(q + 2), at(q + 1), f, at(q - 1), list.v)
                         : accesses(at(q - 2), at(q - 1), f, at(q + 1), list.v);
        std::uint8_t masks[kCaches] = {0, 0, 0};
        for (int c = 0; c < kCaches; ++c) {
          if (size_[c] == 0) continue;
          for (unsigned a = 0; a < list.n; ++a)
            if (!fifo_[c].access(list.v[a])) masks[c] |= std::uint8_t(1u << a);
        }
        bool same = reverse ? q < lo - 2 : q > hi + 2;
        for (int c = 0; c < kCaches; ++c) {
          std::uint8_t& stored = (reverse ? rev_ : fwd_)[c][f];
          same = same && stored == masks[c];
          stored = masks[c];
        }
        std::int64_t& face_cost = (reverse ? rev_cost_ : fwd_cost_)[f];
        const std::int64_t cost = weighted(masks);
        if (!reverse) cost_ += cost - face_cost;
        face_cost = cost;
        rev_minus_fwd_.set(std::size_t(q), rev_cost_[f] - fwd_cost_[f]);
        if (!same) {
          sync[0] = sync[1] = sync[2] = 0;
          continue;
        }
        bool synced = true;
        for (int c = 0; c < kCaches; ++c) {
          sync[c] += unsigned(miss_count(masks[c]));
          synced = synced && sync[c] >= size_[c];
        }
        if (synced) break;
      }
    }
  }

  const Mesh& mesh_;
  const MeshTopology& t_;
  const std::uint32_t* idx_;
  std::vector<std::uint32_t>& F_;
  std::uint32_t m_;
  unsigned size_[kCaches];
  std::int64_t weight_[kCaches];
  std::int64_t strip_cost_ = 0;
  std::vector<std::uint32_t> pos_;
  std::vector<std::uint8_t> fwd_[kCaches], rev_[kCaches];  // miss bits per face, in access order
  std::vector<AccessList> fwd_list_, rev_list_;            // what each face reads in F, forwards and backwards
  std::vector<std::uint32_t> found_;                       // load()'s scratch: the last misses
  std::vector<std::int64_t> fwd_cost_, rev_cost_;          // weighted misses per face
  PrefixSums rev_minus_fwd_;                               // over F positions: rev - fwd cost
  std::vector<std::uint32_t> stamp_[kCaches];
  std::uint32_t clock_[kCaches] = {1u << 20, 1u << 20, 1u << 20};
  StampFifo fifo_[kCaches];
  std::vector<std::uint32_t> face_mark_;
  std::vector<std::uint8_t> crowded_;  // the face has a vertex in more than kAllPartnersDegree faces
  std::uint32_t mark_ = 0;
  std::vector<std::uint32_t> old_, new_;  // apply()'s scratch: F[lo..hi] before and after
  std::int64_t cost_ = 0;
};

}  // namespace

void hoppe_local_optimize(const Mesh& mesh, const MeshTopology& topology, const ReorderParams& params,
                          std::vector<std::uint32_t>& order, LocalStats* stats) {
  if (params.cache_size == 0) throw InputError("local: cache size 0: expected at least 1 entry");
  if (order.size() != topology.face_count)
    throw InputError("local: order has " + std::to_string(order.size()) + " faces, mesh has " +
                     std::to_string(topology.face_count));
  LocalStats local_stats;
  if (params.policy == VertexCachePolicy::Fifo) {
    Local local(mesh, topology, Local::hoppe(params.cache_size), order);
    local.run(params, local_stats);
  }
  if (stats) *stats = local_stats;
}

Ordering reorder_local(const Mesh& mesh, const ReorderParams& params) {
  const MeshTopology topology = build_mesh_topology(mesh);
  std::vector<std::uint32_t> order = hoppe_greedy_order(mesh, topology, params);
  hoppe_local_optimize(mesh, topology, params, order);
  return strip_ordering(mesh, topology, std::move(order));
}

}  // namespace rastrace

// K-Cache-Reorder: Lin and Yu, "An Improved Vertex Caching Scheme for 3D Mesh Rendering", IEEE
// TVCG 12(4), 2006, as its independent public implementations agree on it (reorder/kcache.h).
//
// The FIFO is kept as push serial numbers, not as an array that shifts: push number s put
// ring[s % k] in the cache, and v is resident while pushes - serial[v] < k. A look-ahead then
// needs no copy of the cache: the candidate's pushes get serials above the current count in a
// scratch array stamped per candidate, and every resident test reads that array first. So one
// candidate costs its fan's corners, not K, and a step costs O(K x fan), as in the paper.
//
// That fan is the whole mesh at the centre of a vertex fan, which stays in the cache and would be
// looked ahead at every step (quadratic). A large fan's look-ahead is skipped when a lower bound
// of its cost already exceeds the best candidate's, so it could not win: every vertex of the fan
// outside the cache is pushed at least once, and there are at least
// (other corners of its live faces) / (most faces the centre shares with one vertex) of them.
#include "reorder/kcache.h"

#include <algorithm>
#include <functional>
#include <optional>
#include <queue>
#include <utility>

#include "reorder/vertex_faces.h"

namespace rastrace {

namespace {

// Every step scores every resident vertex: larger targets are ordered as this one.
constexpr std::uint32_t kMaxCache = 1024;
constexpr std::uint8_t kPending = 2;
// Vertices in at least this many faces get the look-ahead's lower bound (others are cheap).
constexpr std::uint32_t kLargeFan = 64;

// The cost 1.0 C1 - 0.5 C2 + 1.3 C3, with C3 = pushes / K, scaled by 10 K: integers, so that
// ties are exact and the tie rule decides them.
std::int64_t scaled_cost(std::uint32_t k, std::uint32_t pushes, std::uint32_t triangles,
                         std::uint32_t pushes_to_leave) {
  return 10 * std::int64_t(k) * pushes - 5 * std::int64_t(k) * triangles + 13 * std::int64_t(pushes_to_leave);
}

class KCacheReorder {
 public:
  KCacheReorder(const Mesh& mesh, std::uint32_t k)
      : topology_(build_vertex_faces(mesh)),
        idx_(mesh.indices.data()),
        k_(k),
        live_(topology_.vertex_count),
        emitted_(topology_.face_count, 0),
        serial_(topology_.vertex_count, 0),
        ring_(k, 0),
        scratch_epoch_(topology_.vertex_count, 0),
        scratch_serial_(topology_.vertex_count, 0) {
    for (std::uint32_t v = 0; v < topology_.vertex_count; ++v) {
      live_[v] = topology_.vertex_face_offsets[v + 1] - topology_.vertex_face_offsets[v];
      if (live_[v] > 0) fewest_.emplace(live_[v], v);
    }
    bound_fans();
  }

  Ordering run() {
    ordering_.face_order.reserve(topology_.face_count);
    ordering_.indices.reserve(3 * std::size_t(topology_.face_count));
    while (ordering_.face_order.size() < topology_.face_count) emit_fan(choose_focus());
    return std::move(ordering_);
  }

 private:
  bool resident(std::uint32_t v) const { return serial_[v] != 0 && pushes_ - serial_[v] < k_; }

  void push(std::uint32_t v) {
    serial_[v] = ++pushes_;
    ring_[pushes_ % k_] = v;
  }

  // A degenerate face lists each distinct vertex once (as the vertex-face lists do).
  static bool distinct_corner(const std::uint32_t* c, int i) {
    return !((i > 0 && c[0] == c[i]) || (i > 1 && c[1] == c[i]));
  }
  const std::uint32_t* corners(std::uint32_t face) const { return idx_ + 3 * std::size_t(face); }

  static unsigned distinct_corners(const std::uint32_t* c) {
    return 1u + (c[1] != c[0]) + (c[2] != c[0] && c[2] != c[1]);
  }

  // For the large fans: other_corners_[v], the live faces' distinct corners other than v, and
  // widest_[v], the most faces v shares with any one other vertex (0 for the small fans).
  void bound_fans() {
    other_corners_.assign(topology_.vertex_count, 0);
    widest_.assign(topology_.vertex_count, 0);
    std::vector<std::uint32_t> shared(topology_.vertex_count, 0);
    for (std::uint32_t v = 0; v < topology_.vertex_count; ++v) {
      if (live_[v] < kLargeFan) continue;
      for (const std::uint32_t face : topology_.faces_of_vertex(v)) {
        const std::uint32_t* c = corners(face);
        other_corners_[v] += distinct_corners(c) - 1;
        for (int n = 0; n < 3; ++n)
          if (distinct_corner(c, n) && c[n] != v) widest_[v] = std::max(widest_[v], ++shared[c[n]]);
      }
      for (const std::uint32_t face : topology_.faces_of_vertex(v))
        for (int n = 0; n < 3; ++n) shared[corners(face)[n]] = 0;
    }
  }
  // A lower bound of cost(v): at least ceil(other corners / widest) distinct vertices besides v,
  // all but the k resident ones pushed; C3 x K at least 1.
  std::int64_t cost_lower_bound(std::uint32_t v) const {
    const std::uint32_t others = (other_corners_[v] + widest_[v] - 1) / widest_[v];
    return scaled_cost(k_, others > k_ ? others - k_ : 0, live_[v], 1);
  }

  // The look-ahead for candidate v: emit v's remaining fan on a copy of the cache.
  std::int64_t cost(std::uint32_t v) {
    ++epoch_;
    const auto serial = [&](std::uint32_t u) { return scratch_epoch_[u] == epoch_ ? scratch_serial_[u] : serial_[u]; };
    std::uint32_t extra = 0;  // pushes of the look-ahead (C1)
    for (const std::uint32_t face : topology_.faces_of_vertex(v)) {
      if (emitted_[face]) continue;
      const std::uint32_t* c = corners(face);
      for (int n = 0; n < 3; ++n) {
        if (!distinct_corner(c, n)) continue;
        const std::uint32_t s = serial(c[n]);
        if (s != 0 && pushes_ + extra - s < k_) continue;
        ++extra;
        scratch_epoch_[c[n]] = epoch_;
        scratch_serial_[c[n]] = pushes_ + extra;
      }
    }
    // C3 x K: pushes until v leaves the copy; K if it has left already.
    const std::uint32_t age = pushes_ + extra - serial(v);
    const std::uint32_t to_leave = age < k_ ? k_ - age : k_;
    return scaled_cost(k_, extra, live_[v], to_leave);
  }

  std::uint32_t choose_focus() {
    // The candidates, oldest entry first. The small fans are looked ahead first: the best of
    // them bounds the winner's cost, so a large fan whose lower bound exceeds it is left out.
    candidates_.clear();
    std::optional<std::int64_t> best_small;
    const std::uint32_t first = pushes_ >= k_ ? pushes_ - k_ + 1 : 1;
    for (std::uint32_t s = first; s <= pushes_; ++s) {
      const std::uint32_t v = ring_[s % k_];
      if (live_[v] == 0) continue;
      if (widest_[v] > 0) {
        candidates_.push_back({v, std::nullopt});
        continue;
      }
      const std::int64_t c = cost(v);
      candidates_.push_back({v, c});
      if (!best_small || c < *best_small) best_small = c;
    }
    std::int64_t best = 0;
    std::uint32_t focus = 0;
    bool found = false;
    // `<=` lets the most recently entered win ties.
    for (auto& [v, c] : candidates_) {
      if (!c) {
        if (best_small && cost_lower_bound(v) > *best_small) continue;  // cannot win
        c = cost(v);
      }
      if (!found || *c <= best) {
        best = *c;
        focus = v;
        found = true;
      }
    }
    if (found) return focus;
    // No resident vertex has triangles left: restart at the vertex with the fewest (lowest id
    // on ties). The heap holds stale entries from before each decrement; they are skipped.
    while (fewest_.top().first != live_[fewest_.top().second]) fewest_.pop();
    return fewest_.top().second;
  }

  void emit(std::uint32_t face) {
    emitted_[face] = 1;
    ordering_.face_order.push_back(face);
    const std::uint32_t* c = corners(face);
    ordering_.indices.insert(ordering_.indices.end(), c, c + 3);
    const unsigned others = distinct_corners(c) - 1;
    for (int n = 0; n < 3; ++n) {
      if (!distinct_corner(c, n)) continue;
      if (widest_[c[n]] > 0) other_corners_[c[n]] -= others;
      if (--live_[c[n]] > 0) fewest_.emplace(live_[c[n]], c[n]);
    }
  }

  // After u enters the cache, every other triangle of u whose corners are all resident is drawn
  // too. They are found at that push but drawn just after the fan triangle that caused it: drawn
  // before it, they would fetch its corners in another order than the simulated FIFO did, and
  // the stream would pay other misses than the ones the choices were made on.
  void collect_completed(std::uint32_t u, std::uint32_t current) {
    for (const std::uint32_t face : topology_.faces_of_vertex(u)) {
      if (emitted_[face] || face == current) continue;
      const std::uint32_t* c = corners(face);
      if (!resident(c[0]) || !resident(c[1]) || !resident(c[2])) continue;
      emitted_[face] = kPending;
      completed_.push_back(face);
    }
  }

  void emit_fan(std::uint32_t focus) {
    fan_.clear();
    for (const std::uint32_t face : topology_.faces_of_vertex(focus))
      if (!emitted_[face]) fan_.push_back(face);
    for (const std::uint32_t face : fan_) {
      if (emitted_[face]) continue;  // completed by an earlier push of this fan
      const std::uint32_t* c = corners(face);
      for (int n = 0; n < 3; ++n) {
        if (!distinct_corner(c, n) || resident(c[n])) continue;
        push(c[n]);
        collect_completed(c[n], face);
      }
      emit(face);
      for (const std::uint32_t completed : completed_) emit(completed);
      completed_.clear();
    }
  }

  const MeshTopology topology_;
  const std::uint32_t* idx_;
  const std::uint32_t k_;
  std::vector<std::uint32_t> live_;    // unemitted faces per vertex
  std::vector<std::uint8_t> emitted_;  // 0, 1, or kPending: completed, to be drawn after the fan triangle
  std::vector<std::uint32_t> serial_;  // push number that last brought v in; 0: never
  std::vector<std::uint32_t> ring_;    // ring_[s % k]: the vertex of push s
  std::uint32_t pushes_ = 0;
  std::vector<std::uint32_t> scratch_epoch_, scratch_serial_;  // the look-ahead's pushes
  std::uint32_t epoch_ = 0;
  std::priority_queue<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::pair<std::uint32_t, std::uint32_t>>,
                      std::greater<>>
      fewest_;  // (live faces, vertex), smallest first
  std::vector<std::uint32_t> fan_, completed_;
  std::vector<std::uint32_t> other_corners_, widest_;                              // bound_fans()
  std::vector<std::pair<std::uint32_t, std::optional<std::int64_t>>> candidates_;  // choose_focus's scratch
  Ordering ordering_;
};

}  // namespace

Ordering reorder_kcache(const Mesh& mesh, const ReorderParams& params) {
  return KCacheReorder(mesh, std::clamp(params.cache_size, 1u, kMaxCache)).run();
}

}  // namespace rastrace

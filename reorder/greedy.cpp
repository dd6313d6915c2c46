// Hoppe 1999, section 5: greedy strip-growing (see greedy.h). The output is drawn as sequential
// strips with restarts (strip.h), Hoppe's indexed-strip interface.
#include "reorder/greedy.h"

#include <algorithm>
#include <array>
#include <limits>

#include "core/error.h"
#include "reorder/strip.h"

namespace rastrace {

namespace {

// The cache being optimized for, with a cheap way to run many short "what if" simulations from
// the current state without copying it.
template <bool kFifo>
class LookaheadCache {
 public:
  LookaheadCache(unsigned k, std::uint32_t vertices) : k_(k), ring_(k, kNone), lru_(), sim_lru_() {
    if (kFifo) {
      stamp_.assign(vertices, 0);
      sim_.assign(vertices, SimEntry{});
      clock_ = k + 1;
    } else {
      lru_.reserve(k);
      sim_lru_.reserve(k);
    }
  }

  bool access(std::uint32_t v) {
    if (kFifo) {
      if (clock_ - stamp_[v] <= k_) return true;
      stamp_[v] = clock_++;
      ring_[ring_pos_] = v;
      ring_pos_ = ring_pos_ + 1 == k_ ? 0 : ring_pos_ + 1;
      return false;
    }
    return lru_access(lru_, v);
  }
  bool contains(std::uint32_t v) const {
    if (kFifo) return clock_ - stamp_[v] <= k_;
    return std::find(lru_.begin(), lru_.end(), v) != lru_.end();
  }
  // Resident vertices (any order); kNone entries are empty slots.
  const std::vector<std::uint32_t>& resident() const { return kFifo ? ring_ : lru_; }

  // Starts a simulation from the current state.
  void sim_begin() {
    if (kFifo) {
      ++tag_;
      sim_clock_ = clock_;
    } else {
      sim_lru_ = lru_;
    }
  }
  bool sim_access(std::uint32_t v) {
    if (kFifo) {
      // FIFO as timestamps continuing the real clock: a vertex not touched by this simulation
      // keeps its real insertion stamp, so nothing has to be copied.
      SimEntry& entry = sim_[v];
      const std::uint32_t s = entry.tag == tag_ ? entry.stamp : stamp_[v];
      if (sim_clock_ - s <= k_) return true;
      entry.tag = tag_;
      entry.stamp = sim_clock_++;
      return false;
    }
    return lru_access(sim_lru_, v);
  }

  static constexpr std::uint32_t kNone = 0xFFFFFFFFu;

 private:
  bool lru_access(std::vector<std::uint32_t>& list, std::uint32_t v) {
    for (std::size_t i = 0; i < list.size(); ++i)
      if (list[i] == v) {
        std::rotate(list.begin(), list.begin() + std::ptrdiff_t(i), list.begin() + std::ptrdiff_t(i) + 1);
        return true;
      }
    if (list.size() < k_)
      list.push_back(v);
    else
      list.back() = v;
    std::rotate(list.begin(), list.end() - 1, list.end());
    return false;
  }

  std::uint32_t k_;
  // FIFO
  struct SimEntry {
    std::uint32_t tag = 0, stamp = 0;
  };
  std::vector<std::uint32_t> stamp_;
  std::vector<SimEntry> sim_;
  std::uint32_t clock_ = 0, sim_clock_ = 0, tag_ = 0;
  std::vector<std::uint32_t> ring_;  // the last k vertices inserted: exactly the residents
  std::uint32_t ring_pos_ = 0;
  // LRU: most recent first
  std::vector<std::uint32_t> lru_, sim_lru_;
};

// A corner names a face to visit and the edge it is entered through: 3 * face + slot. Entering
// through slot e, the face's left vertex is v[e], the right v[e+1], the new one v[e+2]; the
// counter-clockwise (left) exit is slot e+2, the clockwise (right) exit slot e+1.
constexpr std::uint32_t kNoCorner = 0xFFFFFFFFu;

template <bool kFifo>
class Greedy {
 public:
  Greedy(const Mesh& mesh, const MeshTopology& topology, const ReorderParams& params)
      : t_(topology), k_(params.cache_size), cache_(params.cache_size, topology.vertex_count) {
    if (k_ == 0) throw InputError("greedy: cache size 0: expected at least 1 entry");
    const std::uint32_t F = t_.face_count;
    mark_.assign(F, 0);
    unvisited_neighbors_.resize(F);
    for (std::uint32_t f = 0; f < F; ++f) unvisited_neighbors_[f] = static_cast<std::uint8_t>(t_.neighbor_count(f));
    for (std::uint32_t f = F; f-- > 0;) buckets_[unvisited_neighbors_[f]].push_back(f);
    queue_.reserve(F);
    sim_queue_.reserve(64);
    faces_.resize(F);
    for (std::uint32_t f = 0; f < F; ++f)
      for (std::uint32_t s = 0; s < 3; ++s) {
        faces_[f].v[s] = mesh.indices[3 * std::size_t(f) + s];
        faces_[f].across[s] = kNoCorner;
      }
    for (std::uint32_t f = 0; f < F; ++f)
      for (std::uint32_t s = 0; s < 3; ++s) {
        const std::uint32_t g = t_.neighbor(f, s);
        if (g == kNoFace) continue;
        const std::uint32_t edge = t_.face_edges[3 * f + s];
        for (std::uint32_t j = 0; j < 3; ++j)
          if (t_.neighbor(g, j) == f && t_.face_edges[3 * g + j] == edge) {
            faces_[f].across[s] = 3 * g + j;
            break;
          }
      }
  }

  std::vector<std::uint32_t> run(GreedyStats* stats) {
    std::vector<std::uint32_t> order;
    order.reserve(t_.face_count);
    const std::uint32_t maxnf = kFifo ? k_ + 5 : k_ / 2 + 5;
    const std::uint32_t initial_best = std::max(1u, k_ / 2);
    std::uint32_t c = kNoCorner;
    std::uint32_t strip_faces = 0;
    std::uint32_t best = initial_best;  // i_min
    for (;;) {
      if (c == kNoCorner) {
        strip_faces = 0;
        best = initial_best;
        while (queue_head_ < queue_.size() && c == kNoCorner) {
          const std::uint32_t q = queue_[queue_head_++];
          if (!processed(q / 3)) c = q;
        }
        queue_.clear();
        queue_head_ = 0;
        if (c == kNoCorner) {
          c = initial_corner();
          if (c == kNoCorner) break;
          ++stats_.from_scratch;
        }
      }
      while (queue_head_ < queue_.size() && (processed(queue_[queue_head_] / 3) || queue_[queue_head_] / 3 == c / 3))
        ++queue_head_;
      // Lookahead: restart only if C(0) beats every C(i), i in 1..maxnf-1.
      const Score value0 = simulate(0, c, strip_faces, maxnf);
      if (best >= maxnf) best = maxnf - 1;
      Score max_value = simulate(best, c, strip_faces, maxnf);
      bool restart = false;
      if (!(max_value >= value0)) {
        const std::uint32_t old_best = best;
        for (std::uint32_t i = 1; i < maxnf; ++i) {
          if (i == old_best) continue;
          const Score value = simulate(i, c, strip_faces, maxnf);
          if (value >= max_value) {
            max_value = value;
            best = i;
            if (max_value >= value0) break;
          }
        }
        restart = !(max_value >= value0);
      }
      if (restart) {
        ++stats_.restarts;
        c = kNoCorner;
        continue;
      }
      const std::uint32_t f = c / 3, e = c % 3;
      process(f);
      order.push_back(f);
      const std::uint32_t* v = faces_[f].v;
      cache_.access(v[e]);
      cache_.access(v[(e + 1) % 3]);
      cache_.access(v[(e + 2) % 3]);
      ++strip_faces;
      const std::uint32_t inner = cross(f, (e + 2) % 3), outer = cross(f, (e + 1) % 3);
      const bool inner_open = inner != kNoCorner && !processed(inner / 3);
      const bool outer_open = outer != kNoCorner && !processed(outer / 3);
      if (inner_open) {
        if (outer_open) queue_.push_back(outer);
        c = inner;
      } else if (outer_open) {
        c = outer;
      } else {
        c = kNoCorner;
      }
    }
    if (stats) *stats = stats_;
    return order;
  }

 private:
  // Hits per visited face as an exact fraction (0 when nothing was visited).
  struct Score {
    std::uint32_t hits = 0, faces = 0;
    bool operator>=(const Score& o) const {
      return std::uint64_t(hits) * std::max(o.faces, 1u) >= std::uint64_t(o.hits) * std::max(faces, 1u);
    }
  };

  bool processed(std::uint32_t f) const { return mark_[f] == kProcessed; }
  bool sim_visited(std::uint32_t f) const { return mark_[f] >= sim_num_; }

  // The corner entering the neighbour across f's slot s, or kNoCorner.
  std::uint32_t cross(std::uint32_t f, std::uint32_t s) const { return faces_[f].across[s]; }

  void process(std::uint32_t f) {
    mark_[f] = kProcessed;
    for (unsigned s = 0; s < 3; ++s) {
      const std::uint32_t g = t_.neighbor(f, s);
      if (g == kNoFace || processed(g)) continue;
      buckets_[--unvisited_neighbors_[g]].push_back(g);
    }
  }

  std::uint32_t fewest_neighbors_face() {
    for (unsigned b = 0; b < 4; ++b) {
      std::vector<std::uint32_t>& bucket = buckets_[b];
      while (!bucket.empty() && (processed(bucket.back()) || unvisited_neighbors_[bucket.back()] != b))
        bucket.pop_back();
      if (!bucket.empty()) return bucket.back();
    }
    return kNoFace;
  }

  // Restart from scratch: favour faces with vertices in the cache, then fewest unvisited
  // neighbours, then the lowest id; enter through a closed edge so the strip turns left next.
  std::uint32_t initial_corner() {
    std::uint32_t best = kNoFace;
    int best_cached = -1, best_neighbors = 4;
    for (const std::uint32_t v : cache_.resident()) {
      if (v == LookaheadCache<kFifo>::kNone) continue;
      for (const std::uint32_t f : t_.faces_of_vertex(v)) {
        if (processed(f)) continue;
        const std::uint32_t* fv = faces_[f].v;
        const int cached = int(cache_.contains(fv[0])) + int(cache_.contains(fv[1])) + int(cache_.contains(fv[2]));
        const int neighbors = unvisited_neighbors_[f];
        if (cached > best_cached ||
            (cached == best_cached && (neighbors < best_neighbors || (neighbors == best_neighbors && f < best)))) {
          best = f;
          best_cached = cached;
          best_neighbors = neighbors;
        }
      }
    }
    if (best == kNoFace) best = fewest_neighbors_face();
    if (best == kNoFace) return kNoCorner;
    auto closed = [&](std::uint32_t s) {
      const std::uint32_t g = t_.neighbor(best, s);
      return g == kNoFace || processed(g);
    };
    std::uint32_t e = 0;
    for (std::uint32_t s = 0; s < 3; ++s)
      if (closed(s)) {
        e = s;
        break;
      }
    if (closed((e + 2) % 3)) e = (e + 2) % 3;
    return 3 * best + e;
  }

  // Hoppe's lookahead: continue the strip from corner oc for `restart_after` faces, then restart
  // from the queue, and so on until maxnf faces are visited or none is reachable.
  Score simulate(std::uint32_t restart_after, std::uint32_t oc, std::uint32_t strip_faces, std::uint32_t maxnf) {
    ++stats_.simulations;
    ++sim_num_;
    cache_.sim_begin();
    std::size_t main_head = queue_head_;
    sim_queue_.clear();
    std::size_t sim_head = 0;
    std::uint32_t c = oc;
    std::uint32_t visited = 0, hits = 0, event = restart_after;
    for (;;) {
      if (visited == event) {
        if (visited == maxnf) break;
        event = visited < restart_after ? restart_after : maxnf;
        c = kNoCorner;
        while (c == kNoCorner) {
          std::uint32_t q;
          if (main_head < queue_.size())
            q = queue_[main_head++];
          else if (sim_head < sim_queue_.size())
            q = sim_queue_[sim_head++];
          else
            break;
          if (!sim_visited(q / 3)) c = q;
        }
        if (c == kNoCorner) break;
        main_head = queue_.size();
        sim_head = sim_queue_.size();
        strip_faces = 0;
      }
      ++visited;
      const std::uint32_t f = c / 3, e = c % 3;
      mark_[f] = sim_num_;
      const std::uint32_t* v = faces_[f].v;
      // A strip's first face is read from its right vertex (Hoppe's MeshReorder does the same).
      const std::uint32_t first = strip_faces++ == 0 ? (e + 1) % 3 : e;
      hits += cache_.sim_access(v[first]);
      hits += cache_.sim_access(v[(first + 1) % 3]);
      hits += cache_.sim_access(v[(first + 2) % 3]);
      const std::uint32_t inner = cross(f, (e + 2) % 3);
      if (inner != kNoCorner && !sim_visited(inner / 3)) {
        const std::uint32_t outer = cross(f, (e + 1) % 3);
        if (outer != kNoCorner && !sim_visited(outer / 3)) sim_queue_.push_back(outer);
        c = inner;
        continue;
      }
      const std::uint32_t outer = cross(f, (e + 1) % 3);
      if (outer != kNoCorner && !sim_visited(outer / 3))
        c = outer;
      else
        event = visited;  // the strip cannot continue
    }
    return Score{hits, visited};
  }

  static constexpr std::uint32_t kProcessed = std::numeric_limits<std::uint32_t>::max();

  const MeshTopology& t_;
  std::uint32_t k_;
  LookaheadCache<kFifo> cache_;
  std::vector<std::uint32_t> mark_;  // kProcessed, or the last simulation that visited the face
  std::uint32_t sim_num_ = 0;
  std::vector<std::uint8_t> unvisited_neighbors_;
  std::array<std::vector<std::uint32_t>, 4> buckets_;
  std::vector<std::uint32_t> queue_, sim_queue_;
  // What a simulation reads per face, in one cache line: its vertices and the corner entering
  // the neighbour across each of its slots (kNoCorner at a border).
  struct FaceRecord {
    std::uint32_t v[3];
    std::uint32_t across[3];
  };
  std::vector<FaceRecord> faces_;
  std::size_t queue_head_ = 0;
  GreedyStats stats_;
};

}  // namespace

std::vector<std::uint32_t> hoppe_greedy_order(const Mesh& mesh, const MeshTopology& topology,
                                              const ReorderParams& params, GreedyStats* stats) {
  if (params.policy == VertexCachePolicy::Fifo) return Greedy<true>(mesh, topology, params).run(stats);
  return Greedy<false>(mesh, topology, params).run(stats);
}

Ordering reorder_greedy(const Mesh& mesh, const ReorderParams& params) {
  const MeshTopology topology = build_mesh_topology(mesh);
  return strip_ordering(mesh, topology, hoppe_greedy_order(mesh, topology, params));
}

}  // namespace rastrace

// Hoppe 1999, section 5: greedy strip-growing (see greedy.h). The output is drawn as sequential
// strips with restarts (strip.h), Hoppe's indexed-strip interface.
//
// Speed: nearly all the time goes into the lookahead (about 3 simulations of up to k + 5 faces
// per face drawn), so a simulation touches one 32-byte record per face (vertices, the corners
// across its edges, its visit mark) and writes the cache state in place with an undo log instead
// of a per-simulation copy or tag check. Its hot state lives in locals of the simulation, which
// the compiler keeps in registers (members would be reloaded after every store to an array).
#include "reorder/greedy.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <limits>
#include <string>
#include <type_traits>

#include "core/error.h"
#include "reorder/removable_positions.h"
#include "reorder/strip.h"

namespace rastrace {

namespace {

constexpr std::uint32_t kNone = 0xFFFFFFFFu;

// What a simulation overwrote in a per-vertex array (a FIFO stamp, an LRU slot).
struct UndoEntry {
  std::uint32_t vertex, stamp;
};

// Slot arithmetic without % 3.
constexpr std::uint32_t kNext[3] = {1, 2, 0};
constexpr std::uint32_t kPrev[3] = {2, 0, 1};

// FIFO of k entries as insertion time stamps: v is resident iff clock - stamp[v] <= k.
class FifoCache {
 public:
  FifoCache(unsigned k, std::uint32_t vertices, std::size_t max_sim_misses)
      : k_(k), clock_(k + 1), stamp_(vertices, 0), ring_(k, kNone), undo_(max_sim_misses) {}

  bool access(std::uint32_t v) {
    if (clock_ - stamp_[v] <= k_) return true;
    stamp_[v] = clock_++;
    ring_[ring_pos_] = v;
    ring_pos_ = ring_pos_ + 1 == k_ ? 0 : ring_pos_ + 1;
    return false;
  }
  bool contains(std::uint32_t v) const { return clock_ - stamp_[v] <= k_; }
  // Calls visit(v) for every resident vertex (the last k inserted).
  template <class Visit>
  void for_each_resident(Visit visit) const {
    for (const std::uint32_t v : ring_)
      if (v != kNone) visit(v);
  }

  // A "what if" run from the current state: it continues the real clock and writes stamps in
  // place, logging what it overwrote; the destructor puts them back (in reverse order, so a
  // vertex inserted twice ends with its real stamp).
  class Sim {
   public:
    explicit Sim(FifoCache& cache)
        : stamp_(cache.stamp_.data()), undo_(cache.undo_.data()), k_(cache.k_), clock_(cache.clock_) {}
    Sim(const Sim&) = delete;
    Sim& operator=(const Sim&) = delete;
    ~Sim() {
      while (misses_ > 0) {
        --misses_;
        stamp_[undo_[misses_].vertex] = undo_[misses_].stamp;
      }
    }
    std::uint32_t access(std::uint32_t v) {
      const std::uint32_t old = stamp_[v];
      if (clock_ - old <= k_) return 1;
      undo_[misses_++] = UndoEntry{v, old};
      stamp_[v] = clock_++;
      return 0;
    }

   private:
    std::uint32_t* stamp_;
    UndoEntry* undo_;
    std::uint32_t k_, clock_;
    std::size_t misses_ = 0;
  };

 private:
  friend class Sim;
  std::uint32_t k_, clock_;
  std::vector<std::uint32_t> stamp_;
  std::vector<std::uint32_t> ring_;
  std::uint32_t ring_pos_ = 0;
  std::vector<UndoEntry> undo_;
};

// LRU of k entries as slots in a doubly linked list, most recent first: v is resident iff
// slot[slot_of[v]].vertex == v; a hit moves its slot to the front, a miss reuses the last slot
// (empty ones start at the back). O(1) per access where a list of vertices needs a search and a
// shift. A simulation works on a copy of the k slots and undoes its slot_of writes, as the FIFO
// does its stamps.
class LruCache {
 private:
  struct Slot {
    std::uint32_t vertex, prev, next;
  };
  struct Ends {
    std::uint32_t head, tail;
  };
  static void to_front(Slot* slots, Ends& list, std::uint32_t s) {
    if (s == list.head) return;
    const std::uint32_t prev = slots[s].prev, next = slots[s].next;
    slots[prev].next = next;
    if (s == list.tail)
      list.tail = prev;
    else
      slots[next].prev = prev;
    slots[s].next = list.head;
    slots[list.head].prev = s;
    list.head = s;
  }
  // Puts v in the least recently used slot, moved to the front; returns the slot.
  static std::uint32_t replace_last(Slot* slots, Ends& list, std::uint32_t v) {
    const std::uint32_t s = list.tail;
    slots[s].vertex = v;
    to_front(slots, list, s);
    return s;
  }

 public:
  LruCache(unsigned k, std::uint32_t vertices, std::size_t max_sim_misses)
      : slot_of_(vertices, 0), slots_(k), sim_slots_(k), undo_(max_sim_misses) {
    for (std::uint32_t s = 0; s < k; ++s) slots_[s] = Slot{kNone, s - 1, s + 1};  // s - 1 wraps at 0: unused
    list_.head = 0;
    list_.tail = k - 1;
  }

  bool access(std::uint32_t v) {
    const std::uint32_t s = slot_of_[v];
    if (slots_[s].vertex == v) {
      to_front(slots_.data(), list_, s);
      return true;
    }
    slot_of_[v] = replace_last(slots_.data(), list_, v);
    return false;
  }
  bool contains(std::uint32_t v) const { return slots_[slot_of_[v]].vertex == v; }
  // Calls visit(v) for every resident vertex.
  template <class Visit>
  void for_each_resident(Visit visit) const {
    for (const Slot& slot : slots_)
      if (slot.vertex != kNone) visit(slot.vertex);
  }

  class Sim {
   public:
    explicit Sim(LruCache& cache)
        : slot_of_(cache.slot_of_.data()),
          slots_(cache.sim_slots_.data()),
          undo_(cache.undo_.data()),
          list_(cache.list_) {
      std::memcpy(slots_, cache.slots_.data(), cache.slots_.size() * sizeof(Slot));
    }
    Sim(const Sim&) = delete;
    Sim& operator=(const Sim&) = delete;
    ~Sim() {
      while (misses_ > 0) {
        --misses_;
        slot_of_[undo_[misses_].vertex] = undo_[misses_].stamp;
      }
    }
    std::uint32_t access(std::uint32_t v) {
      const std::uint32_t s = slot_of_[v];
      if (slots_[s].vertex == v) {
        to_front(slots_, list_, s);
        return 1;
      }
      undo_[misses_++] = UndoEntry{v, s};
      slot_of_[v] = replace_last(slots_, list_, v);
      return 0;
    }

   private:
    std::uint32_t* slot_of_;
    Slot* slots_;
    UndoEntry* undo_;
    Ends list_;
    std::size_t misses_ = 0;
  };

 private:
  std::vector<std::uint32_t> slot_of_;  // any slot for a vertex never cached
  std::vector<Slot> slots_, sim_slots_;
  Ends list_{};
  std::vector<UndoEntry> undo_;
};

// A corner names a face to visit and the edge it is entered through: 4 * face + slot. Entering
// through slot e, the face's left vertex is v[e], the right v[e+1], the new one v[e+2]; the
// counter-clockwise (left) exit is slot e+2, the clockwise (right) exit slot e+1.
constexpr std::uint32_t kNoCorner = kNone;
// Limits the corners (4 * face + slot, the border face included) and the 32-bit cache clocks,
// which advance by up to 3 per face for the real order and as much again within a simulation.
constexpr std::uint32_t kMaxFaces = 1u << 29;
// A restart from scratch skips the faces of the two largest resident vertices when both are in
// at least this many faces (see best_cached_face); below it, every face is looked at.
constexpr std::size_t kFanValence = 64;

template <class Cache>
class Greedy {
 public:
  Greedy(const Mesh& mesh, const MeshTopology& topology, const ReorderParams& params)
      : t_(topology),
        k_(params.cache_size),
        maxnf_(std::is_same_v<Cache, FifoCache> ? k_ + 5 : k_ / 2 + 5),
        cache_(params.cache_size, topology.vertex_count, 3 * std::size_t(std::min(maxnf_, topology.face_count)) + 3),
        open_edge_faces_(static_cast<std::uint32_t>(topology.edge_faces.size())),
        repeats_corner_(topology.vertex_count, 0) {
    if (k_ == 0) throw InputError("greedy: cache size 0: expected at least 1 entry");
    const std::uint32_t F = t_.face_count;
    if (F >= kMaxFaces)
      throw InputError("greedy: " + std::to_string(F) + " faces: at most " + std::to_string(kMaxFaces - 1) +
                       " supported");
    unvisited_neighbors_.resize(F);
    for (std::uint32_t f = 0; f < F; ++f) unvisited_neighbors_[f] = static_cast<std::uint8_t>(t_.neighbor_count(f));
    for (std::uint32_t f = F; f-- > 0;) buckets_[unvisited_neighbors_[f]].push_back(f);
    queue_.reserve(F);
    sim_queue_.resize(std::size_t(std::min(maxnf_, F)) + 1);
    // Record F is the border: every edge without a neighbour leads to it, and it is always
    // processed, so "is the face across open?" is one mark comparison.
    border_ = 4 * F;
    faces_.resize(std::size_t(F) + 1);
    faces_[F].mark = kProcessed;
    const std::uint32_t* idx = mesh.indices.data();
    for (std::uint32_t f = 0; f < F; ++f) {
      const std::uint32_t* c = idx + 3 * std::size_t(f);
      if (c[0] == c[1] || c[1] == c[2] || c[0] == c[2])
        for (int n = 0; n < 3; ++n) repeats_corner_[c[n]] = 1;
    }
    for (std::uint32_t f = 0; f < F; ++f) {
      FaceRecord& r = faces_[f];
      for (std::uint32_t s = 0; s < 3; ++s) {
        r.v[s] = idx[3 * std::size_t(f) + s];
        r.across[s] = border_;
        const std::uint32_t g = t_.face_neighbors[3 * std::size_t(f) + s];
        if (g == kNoFace) continue;
        const std::uint32_t edge = t_.face_edges[3 * std::size_t(f) + s];
        for (std::uint32_t j = 0; j < 3; ++j)
          if (t_.face_neighbors[3 * std::size_t(g) + j] == f && t_.face_edges[3 * std::size_t(g) + j] == edge) {
            r.across[s] = 4 * g + j;
            break;
          }
      }
    }
  }

  std::vector<std::uint32_t> run(GreedyStats* stats) {
    std::vector<std::uint32_t> order;
    order.reserve(t_.face_count);
    const std::uint32_t maxnf = maxnf_;
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
          if (!processed(q >> 2)) c = q;
        }
        queue_.clear();
        queue_head_ = 0;
        if (c == kNoCorner) {
          c = initial_corner();
          if (c == kNoCorner) break;
          ++stats_.from_scratch;
        }
      }
      while (queue_head_ < queue_.size() && (processed(queue_[queue_head_] >> 2) || queue_[queue_head_] >> 2 == c >> 2))
        ++queue_head_;
      // Lookahead: restart only if C(0) beats every C(i), i in 1..maxnf-1.
      const Score value0 = simulate(0, c, strip_faces);
      if (best >= maxnf) best = maxnf - 1;
      Score max_value = simulate(best, c, strip_faces);
      bool restart = false;
      if (!(max_value >= value0)) {
        const std::uint32_t old_best = best;
        for (std::uint32_t i = 1; i < maxnf; ++i) {
          if (i == old_best) continue;
          const Score value = simulate(i, c, strip_faces);
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
      const std::uint32_t f = c >> 2, e = c & 3;
      process(f);
      order.push_back(f);
      const std::uint32_t* v = faces_[f].v;
      cache_.access(v[e]);
      cache_.access(v[kNext[e]]);
      cache_.access(v[kPrev[e]]);
      ++strip_faces;
      const std::uint32_t inner = faces_[f].across[kPrev[e]], outer = faces_[f].across[kNext[e]];
      const bool inner_open = !processed(inner >> 2);
      const bool outer_open = !processed(outer >> 2);
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

  // What a simulation reads per face, in one aligned 32-byte block: its vertices, the corner
  // entering the neighbour across each slot (the border record's at a border) and its mark: kProcessed,
  // or the number of the last simulation that visited it.
  struct alignas(32) FaceRecord {
    std::uint32_t v[3];
    std::uint32_t across[3];
    std::uint32_t mark = 0;
    std::uint32_t unused = 0;
  };
  static constexpr std::uint32_t kProcessed = std::numeric_limits<std::uint32_t>::max();

  bool processed(std::uint32_t f) const { return faces_[f].mark == kProcessed; }

  void process(std::uint32_t f) {
    faces_[f].mark = kProcessed;
    for (unsigned s = 0; s < 3; ++s) {
      const std::uint32_t e = t_.face_edges[3 * std::size_t(f) + s];
      if (e == kNoEdge) continue;
      const std::span<const std::uint32_t> around = t_.faces_of_edge(e);
      const auto place = std::lower_bound(around.begin(), around.end(), f) - around.begin();
      open_edge_faces_.remove(t_.edge_face_offsets[e] + static_cast<std::uint32_t>(place));
    }
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

  // A restart's choice among the faces with vertices in the cache: most cached corners, then
  // fewest unvisited neighbours, then the lowest id. A total order, so the winner does not depend
  // on the order faces are offered in, and offering a face with too few cached corners is
  // harmless once the face itself is also offered with its true count.
  struct Candidate {
    std::uint32_t face = kNoFace;
    int cached = -1, neighbors = 4;
    void offer(std::uint32_t f, int c, int n) {
      if (c > cached || (c == cached && (n < neighbors || (n == neighbors && f < face)))) {
        face = f;
        cached = c;
        neighbors = n;
      }
    }
  };
  void offer_faces_of(std::uint32_t v, Candidate& best) const {
    for (const std::uint32_t f : t_.faces_of_vertex(v)) {
      if (processed(f)) continue;
      const std::uint32_t* fv = faces_[f].v;
      best.offer(f, int(cache_.contains(fv[0])) + int(cache_.contains(fv[1])) + int(cache_.contains(fv[2])),
                 unvisited_neighbors_[f]);
    }
  }
  // The unprocessed face on edge (a, b) with the fewest unvisited neighbours, lowest id first.
  std::uint32_t open_face_of_edge(std::uint32_t a, std::uint32_t b) {
    const std::uint32_t e = t_.find_edge(a, b);
    if (e == kNoEdge) return kNoFace;
    std::uint32_t best = kNoFace;
    unsigned fewest = 4;
    const std::uint32_t end = t_.edge_face_offsets[e + 1];
    for (std::uint32_t j = open_edge_faces_.first(t_.edge_face_offsets[e]); j < end;
         j = open_edge_faces_.first(j + 1)) {
      const std::uint32_t f = t_.edge_faces[j];
      if (unvisited_neighbors_[f] < fewest) {
        best = f;
        fewest = unvisited_neighbors_[f];
        if (fewest == 0) break;  // faces come in increasing id
      }
    }
    return best;
  }

  // Hoppe's choice over every unprocessed face around the resident vertices. Looking at them all
  // at every restart is quadratic where two resident vertices a, b share thousands of faces (an
  // edge fan: every face is its own strip, so every face is a restart). So when a and b, the
  // resident vertices in the most faces, are both large and in no degenerate face, the faces of
  // the other resident vertices are offered first. Every face of a or b with a cached corner
  // elsewhere has then been offered with its true count; the rest have two cached corners (the
  // faces of edge a-b) or one. So a best with 3 stands; otherwise the best face of edge a-b is
  // offered with 2, and only if the best still has fewer than 2 are a's and b's faces scanned.
  std::uint32_t best_cached_face() {
    resident_.clear();
    cache_.for_each_resident([&](std::uint32_t v) { resident_.push_back(v); });
    const auto valence = [&](std::uint32_t v) { return t_.faces_of_vertex(v).size(); };
    std::uint32_t a = kNone, b = kNone;
    for (const std::uint32_t v : resident_) {
      if (a == kNone || valence(v) > valence(a)) {
        b = a;
        a = v;
      } else if (b == kNone || valence(v) > valence(b)) {
        b = v;
      }
    }
    Candidate best;
    if (b == kNone || valence(b) < kFanValence || repeats_corner_[a] || repeats_corner_[b]) {
      for (const std::uint32_t v : resident_) offer_faces_of(v, best);
      return best.face;
    }
    for (const std::uint32_t v : resident_)
      if (v != a && v != b) offer_faces_of(v, best);
    if (best.cached == 3) return best.face;
    const std::uint32_t on_edge = open_face_of_edge(a, b);
    if (on_edge != kNoFace) best.offer(on_edge, 2, unvisited_neighbors_[on_edge]);
    if (best.cached >= 2) return best.face;
    offer_faces_of(a, best);
    offer_faces_of(b, best);
    return best.face;
  }

  // Restart from scratch: favour faces with vertices in the cache (best_cached_face), else the
  // face with the fewest unvisited neighbours; enter through a closed edge so the strip turns
  // left next.
  std::uint32_t initial_corner() {
    std::uint32_t best = best_cached_face();
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
    if (closed(kPrev[e])) e = kPrev[e];
    return 4 * best + e;
  }

  // Hoppe's lookahead: continue the strip from corner oc for `restart_after` faces, then restart
  // from the queue, and so on until maxnf faces are visited or none is reachable.
  Score simulate(std::uint32_t restart_after, std::uint32_t oc, std::uint32_t strip_faces) {
    ++stats_.simulations;
    if (sim_num_ + 1 == kProcessed) {  // marks are about to wrap: forget every old simulation
      for (FaceRecord& r : faces_)
        if (r.mark != kProcessed) r.mark = 0;
      sim_num_ = 0;
    }
    const std::uint32_t sim = ++sim_num_;
    typename Cache::Sim cache(cache_);
    FaceRecord* const faces = faces_.data();
    const std::uint32_t* const queue = queue_.data();
    const std::size_t queue_size = queue_.size();
    std::uint32_t* const sim_queue = sim_queue_.data();
    const std::uint32_t maxnf = maxnf_;
    std::size_t main_head = queue_head_;
    std::uint32_t sim_size = 0, sim_head = 0;
    std::uint32_t c = oc;
    std::uint32_t visited = 0, hits = 0;
    // Faces are visited up to `limit`: the forced restart, then the horizon maxnf. A strip that
    // cannot continue sets limit = visited, which restarts it from the queues.
    std::uint32_t limit = restart_after;
    bool first_face = strip_faces == 0;
    for (;;) {
      if (visited == limit) {
        if (visited == maxnf) break;
        limit = visited < restart_after ? restart_after : maxnf;
        c = kNoCorner;
        while (c == kNoCorner) {
          std::uint32_t q;
          if (main_head < queue_size)
            q = queue[main_head++];
          else if (sim_head < sim_size)
            q = sim_queue[sim_head++];
          else
            break;
          if (faces[q >> 2].mark < sim) c = q;
        }
        if (c == kNoCorner) break;
        main_head = queue_size;
        sim_head = sim_size;
        first_face = true;
      }
      while (visited != limit) {
        ++visited;
        FaceRecord& r = faces[c >> 2];
        const std::uint32_t e = c & 3;
        r.mark = sim;
        if (first_face) {
          // A strip's first face is read from its right vertex (Hoppe's MeshReorder does the same).
          first_face = false;
          hits += cache.access(r.v[kNext[e]]);
          hits += cache.access(r.v[kPrev[e]]);
          hits += cache.access(r.v[e]);
        } else {
          hits += cache.access(r.v[e]);
          hits += cache.access(r.v[kNext[e]]);
          hits += cache.access(r.v[kPrev[e]]);
        }
        const std::uint32_t inner = r.across[kPrev[e]], outer = r.across[kNext[e]];
        const bool outer_open = faces[outer >> 2].mark < sim;
        if (faces[inner >> 2].mark < sim) {
          if (outer_open) sim_queue[sim_size++] = outer;
          c = inner;
        } else if (outer_open) {
          c = outer;
        } else {
          limit = visited;  // the strip cannot continue
        }
      }
    }
    return Score{hits, visited};
  }

  const MeshTopology& t_;
  std::uint32_t k_, maxnf_;
  Cache cache_;
  std::uint32_t sim_num_ = 0;
  std::vector<std::uint8_t> unvisited_neighbors_;
  std::array<std::vector<std::uint32_t>, 4> buckets_;
  std::vector<std::uint32_t> queue_, sim_queue_;
  std::vector<FaceRecord> faces_;  // one per face, then the border record
  std::uint32_t border_ = 0;       // the border record's corner
  std::size_t queue_head_ = 0;
  GreedyStats stats_;
  RemovablePositions open_edge_faces_;        // places in t_.edge_faces of unprocessed faces
  std::vector<std::uint8_t> repeats_corner_;  // per vertex: in a degenerate face
  std::vector<std::uint32_t> resident_;       // scratch of best_cached_face
};

}  // namespace

std::vector<std::uint32_t> hoppe_greedy_order(const Mesh& mesh, const MeshTopology& topology,
                                              const ReorderParams& params, GreedyStats* stats) {
  if (params.policy == VertexCachePolicy::Fifo) return Greedy<FifoCache>(mesh, topology, params).run(stats);
  return Greedy<LruCache>(mesh, topology, params).run(stats);
}

Ordering reorder_greedy(const Mesh& mesh, const ReorderParams& params) {
  const MeshTopology topology = build_mesh_topology(mesh);
  return strip_ordering(mesh, topology, hoppe_greedy_order(mesh, topology, params));
}

}  // namespace rastrace

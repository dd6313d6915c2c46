// A triangle order for batch-based vertex reuse (the NVIDIA model of Kerbl, Kenzel, Ivanchenko,
// Schmalstieg, Steinberger, "Revisiting the Vertex Cache: Understanding and Optimizing Vertex
// Processing on the modern GPU", HPG 2018; cache_sim/kerbl_batch.h). Their observation is that
// a batch of 32 triangles (96 indices) shades each of its vertices once, and nothing is reused
// between batches; so an order should cut the mesh into compact patches of 32 triangles with as
// few vertices as possible, one patch per batch, rather than sweep fans through a FIFO.
//
// Ours builds the batches greedily while running the batch model itself: the next triangle is,
// among the live triangles around the open batch's vertices, the one that adds the fewest shader
// invocations to the batch (the model's own count, so a vertex whose last use has left the reuse
// window counts as new); ties go to the triangle whose vertices have the fewest live triangles
// left (it closes the patch's border instead of widening it), then to the one using the batch
// vertex closest to leaving the reuse window (used before it is lost, as Tipsy's time stamps
// favour), then to the lower face id. Those two tie-breaks were chosen on fandisk, triceratops and
// bunny00 (with cost alone the order is worse than Forsyth's); docs/PERFORMANCE.md also gives
// meshes they were not chosen on. When no
// triangle fits, the next batch is seeded next to the last one: at the live vertex of the closed
// batch with the fewest live triangles (a corner of what is left, as Tipsy's dead-end rule picks),
// else at the first live face in file order. Deterministic.
//
// Cost: about 200 cost queries per triangle on a well-formed mesh (every live triangle around a
// batch of up to 32 vertices). A vertex in thousands of triangles (a fan centre, an edge shared by
// every face, a mesh on a few vertices) would make that quadratic, so a batch vertex with more
// than kSmallFan live triangles is only walked while its triangles can still win: the fan has a
// lower bound on its triangles' scores (large_fan_bound below), its triangles are visited in
// increasing face id until the bound shows no later one can beat the best so far, and a visited
// triangle whose border and unreusable corners already lose is not scored (that bound is the sum
// of three per-vertex terms kept current as the batch moves, so a mesh on few vertices, whose
// fans' bounds are loose and whose walks visit hundreds of triangles a step, pays three loads and
// one comparison per triangle visited). The faces that led
// the previous step's search are scored first, so the best so far is good from the start. The
// choice is the same triangle as a full scan's (score and face id order all candidates, and only
// candidates that provably lose are skipped); tests/reorder/orders_on_real_meshes_test.cpp pins
// the streams of the full scan. On the pathological corpus (bench/pathological.cpp) the
// quadratic steps were the fans of an edge or a vertex in every face (now a few triangles per
// step) and a mesh on 24 vertices (a few fans walked per step).
#include <algorithm>
#include <array>
#include <limits>

#include "cache_sim/kerbl_batch.h"
#include "reorder/ordering.h"
#include "reorder/vertex_faces.h"

namespace rastrace {

namespace {

constexpr std::uint64_t kWindow = 42;    // NVIDIA's reuse window (kerbl_batch.h)
constexpr std::uint32_t kSmallFan = 16;  // live triangles up to which a batch vertex is scanned whole
// No corner reuses a batch vertex whose last_use is more than this many indices back: every
// reuse window is under 45 indices (kerbl_batch.h), and the model may have seen the vertex up to
// two indices after last_use (at a repeated corner of a degenerate triangle).
constexpr std::uint64_t kReuseReach = 46;

// A candidate's score: fewer added invocations, then fewer live triangles on its vertices, then
// the oldest reused batch vertex (its age `oldest` at most kWindow); lower is better.
std::uint64_t pack_score(std::uint64_t cost, std::uint64_t border, std::uint64_t oldest) {
  return (cost << 48) | (border << 8) | (kWindow - oldest);
}

// Each vertex's live triangles in increasing face id: its CSR segment, from which a walk drops
// the emitted triangles it passes (the live ones it passed are shifted up to the first one it did
// not reach), so each slot is dropped once in all and a walk costs what it visits.
class LiveFaceLists {
 public:
  LiveFaceLists(const MeshTopology& topology, const std::uint32_t* indices)
      : entries_(topology.vertex_faces.size()),
        begin_(topology.vertex_face_offsets.begin(), topology.vertex_face_offsets.end() - 1),
        end_(topology.vertex_face_offsets.begin() + 1, topology.vertex_face_offsets.end()) {
    for (std::size_t j = 0; j < entries_.size(); ++j) {
      const std::uint32_t f = topology.vertex_faces[j];
      const std::uint32_t* c = indices + 3 * std::size_t(f);
      entries_[j] = {f, {c[0], c[1], c[2]}};
    }
  }

  // Calls visit(f, corners of f) for v's live faces in increasing id until it returns false.
  template <typename Visit>
  void walk(std::uint32_t v, const std::vector<std::uint8_t>& emitted, Visit&& visit) {
    Entry* const entries = entries_.data();
    const std::uint32_t begin = begin_[v], end = end_[v];
    std::uint32_t kept = begin;
    for (std::uint32_t at = begin; at < end; ++at) {
      const Entry e = entries[at];
      if (emitted[e.face]) continue;
      if (!visit(e.face, e.corners)) {
        if (kept != at) std::copy_backward(entries + begin, entries + kept, entries + at);
        begin_[v] = at - (kept - begin);
        return;
      }
      entries[kept++] = e;
    }
    end_[v] = kept;
  }

 private:
  // A face and its corners, so a walk reads no index buffer.
  struct Entry {
    std::uint32_t face;
    std::uint32_t corners[3];
  };
  std::vector<Entry> entries_;
  std::vector<std::uint32_t> begin_, end_;
};

}  // namespace

Ordering reorder_batch(const Mesh& mesh, const ReorderParams&) {
  const MeshTopology topology = build_vertex_faces(mesh);
  const std::uint32_t vertex_count = topology.vertex_count, face_count = topology.face_count;
  const std::uint32_t* idx = mesh.indices.data();
  const auto degenerate = [idx](std::uint32_t f) {
    const std::uint32_t* c = idx + 3 * std::size_t(f);
    return c[0] == c[1] || c[1] == c[2] || c[0] == c[2];
  };

  std::vector<std::uint32_t> live(vertex_count), live_degenerate(vertex_count, 0);
  for (std::uint32_t v = 0; v < vertex_count; ++v) {
    live[v] = topology.vertex_face_offsets[v + 1] - topology.vertex_face_offsets[v];
    for (const std::uint32_t f : topology.faces_of_vertex(v)) live_degenerate[v] += degenerate(f);
  }
  LiveFaceLists live_faces(topology, idx);
  // Per vertex, what its corner brings to a large-fan triangle's lower bound (see the walk
  // below), packed so that three of them add up to pack_score(new corners, border, kWindow):
  // (lost << 48) + (live << 8). An emitted corner's entry is set in emit (its live count fell, and
  // it is in the batch, just used); entries otherwise only become too low, never too high (a
  // vertex gets lost as the window moves on or its batch closes), so a stale entry is a weaker
  // bound, never a wrong one. Steps with a large fan refresh the open and the just-closed batch's.
  std::vector<std::uint64_t> corner_bound(vertex_count);
  for (std::uint32_t v = 0; v < vertex_count; ++v) corner_bound[v] = (std::uint64_t{1} << 48) + (std::uint64_t{live[v]} << 8);
  std::vector<std::uint8_t> emitted(face_count, 0);
  std::vector<std::uint64_t> in_batch(vertex_count, 0);  // the batch number (1-based) a vertex was last in
  std::vector<std::uint64_t> last_use(vertex_count, 0);  // stream position of the vertex's last use
  std::uint64_t position = 0;
  std::vector<std::uint32_t> batch_vertices, closed_batch;
  KerblBatch model(KerblGpu::NvidiaD3d);
  const unsigned batch_index_limit = model.parameters().batch_indices;
  const unsigned batch_vertex_limit = model.parameters().batch_vertices;
  std::uint64_t batch = 0;
  std::uint64_t batch_triangles = 0, batch_invocations = 0;  // the open batch's, as the model counts
  std::uint32_t scan = 0;                                    // faces below are emitted

  std::vector<std::uint32_t> order;
  order.reserve(face_count);
  const auto emit = [&](std::uint32_t f) {
    const std::uint64_t invocations_before = model.invocations();
    model.primitive(idx + 3 * std::size_t(f), 3);
    if (model.batches() != batch) {  // the model opened a batch
      batch = model.batches();
      closed_batch.swap(batch_vertices);
      batch_vertices.clear();
      batch_triangles = batch_invocations = 0;
    }
    ++batch_triangles;
    batch_invocations += model.invocations() - invocations_before;
    emitted[f] = 1;
    order.push_back(f);
    const bool is_degenerate = degenerate(f);
    for (unsigned j = 0; j < 3; ++j) {
      const std::uint32_t v = idx[3 * std::size_t(f) + j];
      if ((j == 1 && v == idx[3 * std::size_t(f)]) ||
          (j == 2 && (v == idx[3 * std::size_t(f)] || v == idx[3 * std::size_t(f) + 1])))
        continue;
      --live[v];
      live_degenerate[v] -= is_degenerate;
      last_use[v] = position + j;
      corner_bound[v] = std::uint64_t{live[v]} << 8;
      if (in_batch[v] != batch) {
        in_batch[v] = batch;
        batch_vertices.push_back(v);
      }
    }
    position += 3;
  };

  // The exact score of a live triangle, or false if it does not fit in the open batch.
  // The last faces that took the lead in a step's search (the winner and the runners-up before
  // it): scored first in the next step, while still candidates, so that a large fan's walk starts
  // against a good best and its losing faces are dismissed by the border check.
  std::array<std::uint32_t, 8> runners_up{};
  std::size_t runner_up_count = 0;
  std::vector<std::uint32_t> hints;
  std::uint32_t best = face_count;
  std::uint64_t best_score = std::numeric_limits<std::uint64_t>::max();
  const auto consider = [&](std::uint32_t f) {
    const unsigned cost = model.append_cost(idx + 3 * std::size_t(f));
    if (cost == KerblBatch::kDoesNotFit) return;
    std::uint64_t border = 0, oldest = 0;
    for (unsigned j = 0; j < 3; ++j) {
      const std::uint32_t u = idx[3 * std::size_t(f) + j];
      border += live[u];
      if (in_batch[u] == batch && position - last_use[u] <= kWindow) oldest = std::max(oldest, position - last_use[u]);
    }
    const std::uint64_t score = pack_score(cost, border, oldest);
    if (score < best_score || (score == best_score && f < best)) {
      best_score = score;
      best = f;
      runners_up[runner_up_count++ % runners_up.size()] = f;
    }
  };

  // Invocations a triangle adds at least: its distinct corners outside the open batch or out of
  // reach of every reuse window.
  const auto new_corners = [&](const std::uint32_t* c) {
    const auto lost = [&](std::uint32_t u) { return in_batch[u] != batch || position - last_use[u] > kReuseReach; };
    return std::uint64_t{lost(c[0])} + (c[1] != c[0] && lost(c[1])) + (c[2] != c[0] && c[2] != c[1] && lost(c[2]));
  };
  std::uint64_t bound_batch = 0;
  const auto refresh_corner_bounds = [&] {
    const auto refresh = [&](std::uint32_t u) {
      const bool lost = in_batch[u] != batch || position - last_use[u] > kReuseReach;
      corner_bound[u] = (std::uint64_t{lost} << 48) + (std::uint64_t{live[u]} << 8);
    };
    if (bound_batch != batch) {
      bound_batch = batch;
      for (const std::uint32_t u : closed_batch) refresh(u);
    }
    for (const std::uint32_t u : batch_vertices) refresh(u);
  };
  struct LargeFan {
    std::uint64_t bound;
    unsigned min_cost;
    std::uint32_t vertex;
  };
  std::vector<LargeFan> large;
  while (order.size() < face_count) {
    // The cheapest live triangle that fits in the open batch (none fits in a batch of full
    // index count).
    best = face_count;
    best_score = std::numeric_limits<std::uint64_t>::max();
    large.clear();
    if (batch_triangles * 3 + 3 <= batch_index_limit) {
      for (const std::uint32_t v : batch_vertices) {
        if (live[v] == 0) continue;
        if (live[v] > kSmallFan) {
          large.push_back({0, 0, v});
          continue;
        }
        live_faces.walk(v, emitted, [&](std::uint32_t f, const std::uint32_t*) {
          consider(f);
          return true;
        });
      }
    }
    if (!large.empty()) {
      for (const std::uint32_t f : hints) {
        const std::uint32_t* c = idx + 3 * std::size_t(f);
        if (!emitted[f] && (in_batch[c[0]] == batch || in_batch[c[1]] == batch || in_batch[c[2]] == batch)) consider(f);
      }
      // large_fan_bound: a live triangle of a large fan v not yet considered has no small batch
      // vertex (those were all scanned), so each of its other corners is either a large batch
      // vertex still in some corner's reuse window (at best reused: no cost, its live count to
      // the border) or not (one invocation, at least 1 to the border). With k = min(2, such
      // other fans) corners of the first kind the cost is at least (v outside the window) + 2 - k,
      // and a triangle that reaches it has k of them: its border is at least live[v], the k
      // smallest of their live counts and 2 - k. Its age is at most the oldest large fan's. A
      // degenerate triangle has fewer other corners: a fan with live degenerate triangles gets
      // the bound 0 (walked whole).
      const auto reusable = [&](std::uint32_t v) { return position - last_use[v] <= kReuseReach; };
      std::array<std::uint32_t, 3> smallest{};  // the three reusable large fans with the fewest live triangles
      std::size_t found = 0, reusable_count = 0;
      std::uint64_t oldest = 0;
      for (const LargeFan& fan : large) {
        const std::uint32_t v = fan.vertex;
        if (position - last_use[v] <= kWindow) oldest = std::max(oldest, position - last_use[v]);
        if (!reusable(v)) continue;
        ++reusable_count;
        std::size_t at = found;
        while (at > 0 && live[smallest[at - 1]] > live[v]) --at;
        if (at < 3) {
          for (std::size_t i = std::min<std::size_t>(found, 2); i > at; --i) smallest[i] = smallest[i - 1];
          smallest[at] = v;
          found = std::min<std::size_t>(found + 1, 3);
        }
      }
      for (LargeFan& fan : large) {
        const std::uint32_t v = fan.vertex;
        if (live_degenerate[v] > 0) continue;  // bound 0, cost 0
        const std::uint64_t others = std::min<std::uint64_t>(2, reusable_count - reusable(v));
        std::uint64_t border = live[v] + (2 - others);
        for (std::size_t i = 0, taken = 0; i < found && taken < others; ++i)
          if (smallest[i] != v) {
            border += live[smallest[i]];
            ++taken;
          }
        fan.min_cost = static_cast<unsigned>(!reusable(v) + 2 - others);
        fan.bound = pack_score(fan.min_cost, border, oldest);
      }
      refresh_corner_bounds();
      std::sort(large.begin(), large.end(), [](const LargeFan& a, const LargeFan& b) {
        return a.bound != b.bound ? a.bound < b.bound : a.vertex < b.vertex;
      });
      for (const LargeFan& fan : large) {
        if (batch_invocations + fan.min_cost > batch_vertex_limit) continue;  // none fits
        live_faces.walk(fan.vertex, emitted, [&](std::uint32_t f, const std::uint32_t* c) {
          if (fan.bound > best_score || (fan.bound == best_score && f > best)) return false;
          // Its border and the corners that cannot be reused (the oldest possible age) already
          // lose: not scored.
          if (c[0] != c[1] && c[1] != c[2] && c[0] != c[2]) {
            if (corner_bound[c[0]] + corner_bound[c[1]] + corner_bound[c[2]] > best_score) return true;
          } else {
            const std::uint64_t border = std::uint64_t{live[c[0]]} + live[c[1]] + live[c[2]];
            if (pack_score(new_corners(c), border, kWindow) > best_score) return true;
          }
          consider(f);
          return true;
        });
      }
    }
    hints.assign(runners_up.begin(), runners_up.begin() + std::min(runner_up_count, runners_up.size()));
    runner_up_count = 0;
    if (best == face_count) {
      // Seed the next batch beside the last one, at a corner of what is left.
      std::uint32_t seed_vertex = vertex_count;
      for (const std::vector<std::uint32_t>* around : {&batch_vertices, &closed_batch})
        for (const std::uint32_t v : *around)
          if (live[v] > 0 && (seed_vertex == vertex_count || live[v] < live[seed_vertex])) seed_vertex = v;
      if (seed_vertex != vertex_count) {
        live_faces.walk(seed_vertex, emitted, [&](std::uint32_t f, const std::uint32_t*) {
          best = f;
          return false;
        });
      } else {
        while (emitted[scan]) ++scan;
        best = scan;
      }
    }
    emit(best);
  }
  return list_ordering(mesh, std::move(order));
}

}  // namespace rastrace

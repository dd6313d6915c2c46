// Forsyth: Tom Forsyth, "Linear-Speed Vertex Cache Optimisation", 2006, with his published
// constants: a 32-entry LRU cache model, cache decay power 1.5, last-triangle score 0.75,
// valence boost scale 2.0 and power 0.5.
//
// Every vertex has a score: 0.75 if it is one of the last triangle's three vertices, else
// (1 - (p - 3) / (32 - 3))^1.5 at LRU position p, 0 outside the model cache; plus
// 2.0 * live^-0.5, so vertices with few triangles left get finished early; -1 with none left.
// A triangle scores the sum of its vertices; the highest-scoring triangle touching the model
// cache is emitted next, its vertices move to the front of the LRU, and only the scores of cached
// vertices and their triangles are updated: linear time. The model does not depend on the target
// cache, which is the point of the method (one order for every GPU).
// When no cached vertex has a live triangle (a dead end) Forsyth searches all triangles; here
// the most recently evicted vertex that still has triangles is resumed (its best triangle), and
// failing that the next live triangle in input order, which keeps the method linear.
//
// A vertex in more live triangles than the model cache has entries offers only the first 32 of
// them (in its segment's order) as candidates, when it is cached and when it is resumed after a
// dead end; the rest stay reachable through their other vertices and come forward as the
// vertex's triangles are emitted. Without the cap every step rescored every live triangle of
// every cached vertex (the cached vertices' scores all move with the LRU), which is quadratic
// when a vertex is in thousands of triangles (an edge or a vertex shared by every face, a mesh
// on a few vertices: bench/pathological.cpp). Such a vertex's valence boost is negligible and its
// cache score is shared by all its triangles, so the ranking among them rests on their other
// corners. Manifold-like meshes have valences far below 32 (at most 11 on the CGAL meshes), so
// their orders are unchanged; tests/reorder/orders_on_real_meshes_test.cpp pins them.
//
// Parameters: none that change the order (cache size and policy are ignored; 32 is the
// model). ACMR on real meshes about 0.63-0.75 at FIFO 16. Deterministic.
#include <algorithm>
#include <cmath>
#include <utility>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "reorder/ordering.h"
#include "reorder/vertex_faces.h"

namespace rastrace {

namespace {

constexpr int kModelCache = 32;
constexpr float kCacheDecayPower = 1.5f;
constexpr float kLastTriangleScore = 0.75f;
constexpr float kValenceBoostScale = 2.0f;
constexpr float kValenceBoostPower = 0.5f;
constexpr std::uint32_t kValenceTable = 64;
// A vertex offers at most this many of its live triangles as candidates (the first ones of its
// segment); see the file comment. Above any valence of a manifold-like mesh (at most 11 on the
// CGAL meshes of docs/PERFORMANCE.md), so only vertices in thousands of triangles are affected.
constexpr std::uint32_t kCandidatesPerVertex = kModelCache;

// Every vertex score the loop needs, by LRU position (-1: not cached) and live triangle count,
// each computed once here by the same float operations as the formula: position p's term plus
// the valence boost, -1 with no live triangle. Counts of kValenceTable and more (rare) use the
// formula.
struct ScoreTables {
  float cache[kModelCache];
  float valence[kValenceTable];
  // [p + 1][live]; rows past the model cache (positions 32..34, briefly held while the LRU is
  // rebuilt) score as uncached.
  float by_position[kModelCache + 4][kValenceTable];
  ScoreTables() {
    for (int p = 0; p < kModelCache; ++p)
      cache[p] = p < 3 ? kLastTriangleScore : std::pow(1.0f - float(p - 3) / float(kModelCache - 3), kCacheDecayPower);
    valence[0] = 0.0f;
    for (std::uint32_t n = 1; n < kValenceTable; ++n)
      valence[n] = kValenceBoostScale * std::pow(float(n), -kValenceBoostPower);
    for (int p = -1; p < kModelCache + 3; ++p)
      for (std::uint32_t n = 0; n < kValenceTable; ++n) by_position[p + 1][n] = formula(p < kModelCache ? p : -1, n);
  }
  float formula(int position, std::uint32_t live) const {
    if (live == 0) return -1.0f;
    const float boost =
        live < kValenceTable ? valence[live] : kValenceBoostScale * std::pow(float(live), -kValenceBoostPower);
    return (position >= 0 ? cache[position] : 0.0f) + boost;
  }
  float score(int position, std::uint32_t live) const {
    if (live < kValenceTable) [[likely]]
      return by_position[position + 1][live];
    return formula(position, live);
  }
  // The score at LRU slot `slot` (0..34; 32 and up is outside the model cache).
  float at(int slot, std::uint32_t live) const {
    if (live < kValenceTable) [[likely]]
      return by_position[slot + 1][live];
    return formula(slot < kModelCache ? slot : -1, live);
  }
};

constexpr std::uint32_t kGather = 8;

// out[g] = begin + g for g < kGather.
inline void gather_slots(std::uint32_t* out, std::uint32_t begin) {
#if defined(__SSE2__)
  const __m128i base = _mm_set1_epi32(static_cast<int>(begin));
  _mm_storeu_si128(reinterpret_cast<__m128i*>(out), _mm_add_epi32(base, _mm_setr_epi32(0, 1, 2, 3)));
  _mm_storeu_si128(reinterpret_cast<__m128i*>(out + 4), _mm_add_epi32(base, _mm_setr_epi32(4, 5, 6, 7)));
#else
  for (std::uint32_t g = 0; g < kGather; ++g) out[g] = begin + g;
#endif
}

}  // namespace

Ordering reorder_forsyth(const Mesh& mesh, const ReorderParams& /*params*/) {
  static const ScoreTables tables;
  const MeshTopology topology = build_vertex_faces(mesh);
  const std::uint32_t vertex_count = topology.vertex_count, face_count = topology.face_count;
  const std::uint32_t* idx = mesh.indices.data();

  // Live faces of each vertex sit at the front of its CSR segment; emitted ones are swapped out.
  // Each entry carries the face's vertices, so scoring a face reads no index buffer.
  struct Entry {
    std::uint32_t face, v0, v1, v2;
  };
  const std::vector<std::uint32_t>& offsets = topology.vertex_face_offsets;
  std::vector<Entry> entries(topology.vertex_faces.size());
  for (std::size_t j = 0; j < entries.size(); ++j) {
    const std::uint32_t f = topology.vertex_faces[j];
    entries[j] = Entry{f, idx[3 * std::size_t(f)], idx[3 * std::size_t(f) + 1], idx[3 * std::size_t(f) + 2]};
  }
  std::vector<std::uint32_t> live(vertex_count);
  for (std::uint32_t v = 0; v < vertex_count; ++v) live[v] = offsets[v + 1] - offsets[v];
  // Where each face sits in the segment of the vertex at its corner k (first corner of a repeated
  // vertex): an emitted face is swapped out of a segment of thousands of faces in O(1).
  const auto corner_of = [](const Entry& e, std::uint32_t v) { return e.v0 == v ? 0u : e.v1 == v ? 1u : 2u; };
  std::vector<std::uint32_t> slot_of(3 * std::size_t(face_count));
  for (std::uint32_t v = 0; v < vertex_count; ++v)
    for (std::uint32_t j = offsets[v]; j < offsets[v + 1]; ++j)
      slot_of[3 * std::size_t(entries[j].face) + corner_of(entries[j], v)] = j;
  std::vector<float> vertex_score(vertex_count);
  for (std::uint32_t v = 0; v < vertex_count; ++v) vertex_score[v] = tables.score(-1, live[v]);
  std::vector<std::uint8_t> emitted(face_count, 0);
  // A triangle's score is summed when it is looked at, from its vertices' scores (a degenerate
  // triangle counts its repeated vertex twice): cheaper than pushing every vertex score change
  // to its triangles, since only the triangles of the ~32 cached vertices are ever looked at,
  // and most of their scores change with every triangle (the vertices shift in the LRU).
  const float* const vs = vertex_score.data();
  const auto entry_score = [vs](const Entry& e) { return vs[e.v0] + vs[e.v1] + vs[e.v2]; };

  std::vector<std::uint32_t> evicted_stack;
  evicted_stack.reserve(vertex_count);
  std::uint32_t max_valence = 0;
  for (std::uint32_t v = 0; v < vertex_count; ++v) max_valence = std::max(max_valence, live[v]);
  std::vector<std::uint32_t> candidates(
      std::size_t(kModelCache + 3) * std::max(kGather, std::min(max_valence, kCandidatesPerVertex)) + kGather);
  // The LRU, most recent first, and the buffer the next one is built in (then swapped).
  std::uint32_t cache_storage[2][kModelCache + 3];
  std::uint32_t* cache = cache_storage[0];
  std::uint32_t* next_cache = cache_storage[1];
  int cache_size = 0;

  Ordering ordering;
  ordering.face_order.resize(face_count);
  ordering.indices.resize(mesh.indices.size());
  std::uint32_t* order_out = ordering.face_order.data();
  std::uint32_t* index_out = ordering.indices.data();

  // Forsyth starts from the best triangle of the whole mesh.
  const auto face_score = [&](std::uint32_t f) {
    const std::uint32_t* c = idx + 3 * std::size_t(f);
    return vs[c[0]] + vs[c[1]] + vs[c[2]];
  };
  std::int64_t best = face_count > 0 ? 0 : -1;
  float best_score = face_count > 0 ? face_score(0) : 0.0f;
  for (std::uint32_t f = 1; f < face_count; ++f) {
    const float score = face_score(f);
    if (score > best_score) {
      best_score = score;
      best = f;
    }
  }
  std::uint32_t input_cursor = 0;

  while (best >= 0) {
    const auto face = static_cast<std::uint32_t>(best);
    emitted[face] = 1;
    *order_out++ = face;
    const std::uint32_t* corners = idx + 3 * std::size_t(face);
    const std::uint32_t a = corners[0], b = corners[1], c = corners[2];
    *index_out++ = a;
    *index_out++ = b;
    *index_out++ = c;

    // New LRU: the triangle's distinct vertices first, then the old entries. One pass builds it,
    // scores every vertex for its new position and gathers the candidate triangles in the order
    // that breaks ties (cache order, then segment order). It is branch-free where the outcome
    // is a coin flip: whether an old entry is one of the triangle's vertices (it is written
    // anyway and not counted; its score is set right after the pass), and how many live faces a
    // vertex has (a loop per vertex over them would end at an unpredictable count: kGather
    // slots are written and live[v] of them kept).
    int next_size = 0;
    std::uint32_t candidate_count = 0;
    const auto gather = [&](std::uint32_t v, std::uint32_t keep) {
      const std::uint32_t begin = offsets[v], count = std::min(live[v], kCandidatesPerVertex);
      std::uint32_t* out = candidates.data() + candidate_count;
      if (count <= kGather) [[likely]] {
        gather_slots(out, begin);
      } else {
        for (std::uint32_t g = 0; g < count; ++g) out[g] = begin + g;
      }
      candidate_count += keep * count;
    };
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t v = corners[i];
      if ((i > 0 && a == v) || (i > 1 && b == v)) continue;
      next_cache[next_size++] = v;
      const std::uint32_t last = offsets[v] + live[v] - 1, j = slot_of[3 * std::size_t(face) + i];
      std::swap(entries[j], entries[last]);
      slot_of[3 * std::size_t(entries[j].face) + corner_of(entries[j], v)] = j;
      slot_of[3 * std::size_t(face) + i] = last;
      --live[v];
      gather(v, 1);
    }
    const int fresh = next_size;
    for (int i = 0; i < cache_size; ++i) {
      const std::uint32_t v = cache[i];
      const std::uint32_t keep = (v != a) & (v != b) & (v != c);
      next_cache[next_size] = v;
      vertex_score[v] = tables.at(next_size, live[v]);
      gather(v, keep);
      next_size += static_cast<int>(keep);
    }
    for (int i = 0; i < fresh; ++i) vertex_score[next_cache[i]] = tables.at(i, live[next_cache[i]]);
    for (int i = kModelCache; i < next_size; ++i) {  // pushed out of the model cache (scored so)
      const std::uint32_t v = next_cache[i];
      if (live[v] > 0) evicted_stack.push_back(v);
      candidate_count -= std::min(live[v], kCandidatesPerVertex);  // the last ones gathered
    }
    std::swap(cache, next_cache);
    cache_size = std::min(next_size, kModelCache);

    best = -1;
    best_score = 0.0f;
    for (std::uint32_t n = 0; n < candidate_count; ++n) {
      const Entry& e = entries[candidates[n]];
      const float score = entry_score(e);
      if (score > best_score) {
        best_score = score;
        best = e.face;
      }
    }
    if (best >= 0) continue;
    while (best < 0 && !evicted_stack.empty()) {
      const std::uint32_t v = evicted_stack.back();
      evicted_stack.pop_back();
      for (const Entry *e = entries.data() + offsets[v], *end = e + std::min(live[v], kCandidatesPerVertex); e != end;
           ++e) {
        const float score = entry_score(*e);
        if (best < 0 || score > best_score) {
          best_score = score;
          best = e->face;
        }
      }
    }
    if (best >= 0) continue;
    while (input_cursor < face_count && emitted[input_cursor]) ++input_cursor;
    if (input_cursor < face_count) best = input_cursor;
  }
  return ordering;
}

}  // namespace rastrace

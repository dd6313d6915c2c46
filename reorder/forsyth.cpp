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
// Parameters: none that change the order (cache size and policy are ignored; 32 is the
// model). ACMR on real meshes about 0.63-0.75 at FIFO 16. Deterministic.
#include <algorithm>
#include <cmath>

#include "reorder/vertex_faces.h"
#include "reorder/ordering.h"

namespace rastrace {

namespace {

constexpr int kModelCache = 32;
constexpr float kCacheDecayPower = 1.5f;
constexpr float kLastTriangleScore = 0.75f;
constexpr float kValenceBoostScale = 2.0f;
constexpr float kValenceBoostPower = 0.5f;
constexpr std::uint32_t kValenceTable = 64;

struct ScoreTables {
  float cache[kModelCache];
  float valence[kValenceTable];
  ScoreTables() {
    for (int p = 0; p < kModelCache; ++p)
      cache[p] = p < 3 ? kLastTriangleScore
                       : std::pow(1.0f - float(p - 3) / float(kModelCache - 3), kCacheDecayPower);
    valence[0] = 0.0f;
    for (std::uint32_t n = 1; n < kValenceTable; ++n) valence[n] = kValenceBoostScale * std::pow(float(n), -kValenceBoostPower);
  }
  float score(int position, std::uint32_t live) const {
    if (live == 0) return -1.0f;
    const float boost = live < kValenceTable ? valence[live] : kValenceBoostScale * std::pow(float(live), -kValenceBoostPower);
    return (position >= 0 ? cache[position] : 0.0f) + boost;
  }
};

}  // namespace

Ordering reorder_forsyth(const Mesh& mesh, const ReorderParams& /*params*/) {
  static const ScoreTables tables;
  const MeshTopology topology = build_vertex_faces(mesh);
  const std::uint32_t vertex_count = topology.vertex_count, face_count = topology.face_count;
  const std::uint32_t* idx = mesh.indices.data();

  // Live faces of each vertex sit at the front of its CSR segment; emitted ones are swapped out.
  std::vector<std::uint32_t> faces(topology.vertex_faces);
  const std::vector<std::uint32_t>& offsets = topology.vertex_face_offsets;
  std::vector<std::uint32_t> live(vertex_count);
  for (std::uint32_t v = 0; v < vertex_count; ++v) live[v] = offsets[v + 1] - offsets[v];
  std::vector<float> vertex_score(vertex_count);
  for (std::uint32_t v = 0; v < vertex_count; ++v) vertex_score[v] = tables.score(-1, live[v]);
  std::vector<std::uint8_t> emitted(face_count, 0);
  // A triangle's score is summed when it is looked at, from its vertices' scores (a degenerate
  // triangle counts its repeated vertex twice): cheaper than pushing every vertex score change
  // to its triangles, since only the triangles of the ~32 cached vertices are ever looked at.
  const auto face_score = [&](std::uint32_t f) {
    const std::uint32_t* c = idx + 3 * std::size_t(f);
    return vertex_score[c[0]] + vertex_score[c[1]] + vertex_score[c[2]];
  };

  std::vector<std::uint32_t> evicted_stack;
  evicted_stack.reserve(vertex_count);
  std::uint32_t cache[kModelCache + 3];
  int cache_size = 0;
  std::uint32_t next_cache[kModelCache + 3];

  Ordering ordering;
  ordering.face_order.reserve(face_count);
  ordering.indices.resize(mesh.indices.size());
  std::uint32_t* index_out = ordering.indices.data();

  // Forsyth starts from the best triangle of the whole mesh.
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
    ordering.face_order.push_back(face);
    const std::uint32_t* corners = idx + 3 * std::size_t(face);
    *index_out++ = corners[0];
    *index_out++ = corners[1];
    *index_out++ = corners[2];

    // New LRU: the triangle's distinct vertices first, then the old entries.
    int next_size = 0;
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t v = corners[i];
      if ((i > 0 && corners[0] == v) || (i > 1 && corners[1] == v)) continue;
      next_cache[next_size++] = v;
      const std::uint32_t begin = offsets[v], end = begin + live[v];
      for (std::uint32_t j = begin; j < end; ++j) {
        if (faces[j] == face) {
          faces[j] = faces[end - 1];
          faces[end - 1] = face;
          break;
        }
      }
      --live[v];
    }
    for (int i = 0; i < cache_size; ++i) {
      const std::uint32_t v = cache[i];
      if (v != corners[0] && v != corners[1] && v != corners[2]) next_cache[next_size++] = v;
    }

    for (int i = 0; i < next_size; ++i) {
      const std::uint32_t v = next_cache[i];
      const int p = i < kModelCache ? i : -1;
      if (p < 0 && live[v] > 0) evicted_stack.push_back(v);
      vertex_score[v] = tables.score(p, live[v]);
    }
    cache_size = std::min(next_size, kModelCache);
    for (int i = 0; i < cache_size; ++i) cache[i] = next_cache[i];

    best = -1;
    best_score = 0.0f;
    for (int i = 0; i < cache_size; ++i) {
      const std::uint32_t v = cache[i];
      for (std::uint32_t j = offsets[v], end = offsets[v] + live[v]; j < end; ++j) {
        const float score = face_score(faces[j]);
        if (score > best_score) {
          best_score = score;
          best = faces[j];
        }
      }
    }
    if (best >= 0) continue;
    while (best < 0 && !evicted_stack.empty()) {
      const std::uint32_t v = evicted_stack.back();
      evicted_stack.pop_back();
      for (std::uint32_t j = offsets[v], end = offsets[v] + live[v]; j < end; ++j) {
        const float score = face_score(faces[j]);
        if (best < 0 || score > best_score) {
          best_score = score;
          best = faces[j];
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

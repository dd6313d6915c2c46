#include "reorder/adjacency/assign.h"

#include <chrono>
#include <limits>
#include <stdexcept>

namespace rastrace {
namespace {

constexpr std::uint32_t kNone = 0xFFFFFFFFu;

// Hopcroft-Karp on a bipartite graph given as CSR from the left side. match_left[u] is the CSR
// entry used by u (so callers can attach data to entries), match_right[v] the left node.
// Iterative depth-first search: augmenting paths can be long on big meshes.
struct Bipartite {
  std::uint32_t left = 0, right = 0;
  std::vector<std::uint32_t> offsets;  // left + 1
  std::vector<std::uint32_t> targets;  // right node per entry
};

struct BipartiteMatching {
  std::vector<std::uint32_t> match_left, match_right;
  std::uint32_t size = 0;
};

BipartiteMatching hopcroft_karp(const Bipartite& g) {
  BipartiteMatching m;
  m.match_left.assign(g.left, kNone);
  m.match_right.assign(g.right, kNone);
  // Greedy start: most vertices match at once.
  for (std::uint32_t u = 0; u < g.left; ++u)
    for (std::uint32_t k = g.offsets[u]; k < g.offsets[u + 1]; ++k)
      if (m.match_right[g.targets[k]] == kNone) {
        m.match_left[u] = k;
        m.match_right[g.targets[k]] = u;
        ++m.size;
        break;
      }
  constexpr std::uint32_t kInf = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> dist(g.left), queue, cursor(g.left), stack;
  for (;;) {
    // Breadth-first layering from the free left nodes.
    queue.clear();
    for (std::uint32_t u = 0; u < g.left; ++u) {
      dist[u] = m.match_left[u] == kNone ? 0 : kInf;
      if (dist[u] == 0) queue.push_back(u);
    }
    bool found = false;
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const std::uint32_t u = queue[head];
      for (std::uint32_t k = g.offsets[u]; k < g.offsets[u + 1]; ++k) {
        const std::uint32_t w = m.match_right[g.targets[k]];
        if (w == kNone)
          found = true;
        else if (dist[w] == kInf) {
          dist[w] = dist[u] + 1;
          queue.push_back(w);
        }
      }
    }
    if (!found) break;
    // Vertex-disjoint shortest augmenting paths along the layers.
    for (std::uint32_t u = 0; u < g.left; ++u) cursor[u] = g.offsets[u];
    for (std::uint32_t root = 0; root < g.left; ++root) {
      if (m.match_left[root] != kNone || dist[root] != 0) continue;
      stack.assign(1, root);
      while (!stack.empty()) {
        const std::uint32_t u = stack.back();
        if (cursor[u] == g.offsets[u + 1]) {
          dist[u] = kInf;  // dead end for this phase
          stack.pop_back();
          continue;
        }
        const std::uint32_t k = cursor[u];
        const std::uint32_t w = m.match_right[g.targets[k]];
        if (w == kNone) {
          // Augment along the stack: each left node takes the entry its cursor points at.
          for (std::size_t s = stack.size(); s-- > 0;) {
            const std::uint32_t x = stack[s];
            const std::uint32_t entry = cursor[x];
            m.match_left[x] = entry;
            m.match_right[g.targets[entry]] = x;
          }
          ++m.size;
          for (const std::uint32_t x : stack) dist[x] = kInf;
          stack.clear();
        } else if (dist[w] == dist[u] + 1) {
          stack.push_back(w);
        } else {
          ++cursor[u];
        }
      }
    }
  }
  return m;
}

}  // namespace

std::vector<std::uint32_t> cover_components(const AdjacencyDual& dual, const std::vector<std::uint8_t>& in_cover,
                                            std::uint32_t* component_count) {
  std::vector<std::uint32_t> component(dual.face_count, kNoFace), queue;
  std::uint32_t count = 0;
  for (std::uint32_t f = 0; f < dual.face_count; ++f) {
    if (!in_cover[f] || component[f] != kNoFace) continue;
    component[f] = count;
    queue.assign(1, f);
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const std::uint32_t x = queue[head];
      for (unsigned i = 0; i < 3; ++i) {
        const std::uint32_t g = dual.across(x, i);
        if (g != kNoFace && in_cover[g] && component[g] == kNoFace) {
          component[g] = count;
          queue.push_back(g);
        }
      }
    }
    ++count;
  }
  if (component_count) *component_count = count;
  return component;
}

FaceAssignment assign_uncovered_faces(const AdjacencyDual& dual, const std::vector<std::uint8_t>& in_cover) {
  const auto start = std::chrono::steady_clock::now();
  const std::uint32_t F = dual.face_count;
  FaceAssignment result;
  result.partner.assign(F, kNoFace);

  // Uncovered faces (left) and cover faces (right) renumbered densely.
  std::vector<std::uint32_t> dense(F, kNone), uncovered, cover;
  for (std::uint32_t f = 0; f < F; ++f) {
    dense[f] = static_cast<std::uint32_t>(in_cover[f] ? cover.size() : uncovered.size());
    (in_cover[f] ? cover : uncovered).push_back(f);
  }

  // 1. M: uncovered -> cover.
  Bipartite g1;
  g1.left = static_cast<std::uint32_t>(uncovered.size());
  g1.right = static_cast<std::uint32_t>(cover.size());
  g1.offsets.assign(1, 0);
  for (const std::uint32_t u : uncovered) {
    for (unsigned i = 0; i < 3; ++i) {
      const std::uint32_t c = dual.across(u, i);
      if (c == kNoFace || !in_cover[c]) throw std::logic_error("assignment: the cover leaves an edge uncovered");
      g1.targets.push_back(dense[c]);
    }
    g1.offsets.push_back(static_cast<std::uint32_t>(g1.targets.size()));
  }
  const BipartiteMatching m = hopcroft_karp(g1);
  if (m.size != g1.left) throw std::logic_error("assignment: no perfect matching of the uncovered faces");
  // cover_mate[c] / uncovered_mate[u]: dense ids of the current matching M.
  std::vector<std::uint32_t> cover_mate(g1.right, kNone), uncovered_mate(g1.left, kNone);
  for (std::uint32_t u = 0; u < g1.left; ++u) {
    uncovered_mate[u] = g1.targets[m.match_left[u]];
    cover_mate[uncovered_mate[u]] = u;
  }

  // Components of the cover; A = those without a boundary or degenerate face.
  std::uint32_t component_count = 0;
  const std::vector<std::uint32_t> component = cover_components(dual, in_cover, &component_count);
  result.components = component_count;
  std::vector<std::uint8_t> exempt(component_count, 0), reached(component_count, 0);
  for (std::uint32_t f = 0; f < F; ++f)
    if (in_cover[f] && !dual.interior(f)) exempt[component[f]] = 1;
  for (std::uint32_t c = 0; c < g1.right; ++c)
    if (cover_mate[c] != kNone) reached[component[cover[c]]] = 1;
  std::vector<std::uint32_t> free_id(component_count, kNone), free_components;
  for (std::uint32_t k = 0; k < component_count; ++k)
    if (!exempt[k]) {
      free_id[k] = static_cast<std::uint32_t>(free_components.size());
      free_components.push_back(k);
      if (!reached[k]) ++result.repaired_components;
    }
  result.free_components = static_cast<std::uint32_t>(free_components.size());

  if (result.repaired_components > 0) {
    // 2. N: components of A -> uncovered faces; each entry remembers the cover face it goes through.
    Bipartite g2;
    g2.left = static_cast<std::uint32_t>(free_components.size());
    g2.right = g1.left;
    std::vector<std::uint32_t> bucket_offsets(g2.left + 1, 0);
    for (const std::uint32_t c : cover)
      if (free_id[component[c]] != kNone)
        for (unsigned i = 0; i < 3; ++i) {
          const std::uint32_t u = dual.across(c, i);
          if (u != kNoFace && !in_cover[u]) ++bucket_offsets[free_id[component[c]] + 1];
        }
    for (std::uint32_t k = 0; k < g2.left; ++k) bucket_offsets[k + 1] += bucket_offsets[k];
    g2.offsets = bucket_offsets;
    g2.targets.resize(bucket_offsets[g2.left]);
    std::vector<std::uint32_t> via(g2.targets.size());
    for (const std::uint32_t c : cover) {
      const std::uint32_t k = free_id[component[c]];
      if (k == kNone) continue;
      for (unsigned i = 0; i < 3; ++i) {
        const std::uint32_t u = dual.across(c, i);
        if (u == kNoFace || in_cover[u]) continue;
        via[bucket_offsets[k]] = dense[c];
        g2.targets[bucket_offsets[k]++] = dense[u];
      }
    }
    const BipartiteMatching n = hopcroft_karp(g2);
    if (n.size != g2.left)
      throw std::logic_error("assignment: the cover is not minimal (a component has no free face)");
    std::vector<std::uint32_t> cover_n(g1.right, kNone);  // N at the level of cover faces
    for (std::uint32_t k = 0; k < g2.left; ++k) cover_n[via[n.match_left[k]]] = g2.targets[n.match_left[k]];

    // 3. Flip the alternating paths that start at a cover face in N but not in M.
    for (std::uint32_t k = 0; k < g2.left; ++k) {
      std::uint32_t previous = via[n.match_left[k]];
      if (cover_mate[previous] != kNone) continue;
      std::uint32_t u = cover_n[previous];
      for (;;) {
        const std::uint32_t next = uncovered_mate[u];
        uncovered_mate[u] = previous;
        cover_mate[previous] = u;
        if (cover_n[next] == kNone) {
          cover_mate[next] = kNone;
          break;
        }
        previous = next;
        u = cover_n[next];
      }
    }
  }

  for (std::uint32_t u = 0; u < g1.left; ++u) {
    result.partner[uncovered[u]] = cover[uncovered_mate[u]];
    result.partner[cover[uncovered_mate[u]]] = uncovered[u];
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

bool is_perfect_restricted_assignment(const AdjacencyDual& dual, const std::vector<std::uint8_t>& in_cover,
                                      const FaceAssignment& assignment) {
  const std::uint32_t F = dual.face_count;
  if (assignment.partner.size() != F || in_cover.size() != F) return false;
  for (std::uint32_t f = 0; f < F; ++f) {
    const std::uint32_t p = assignment.partner[f];
    if (!in_cover[f] && p == kNoFace) return false;  // not perfect
    if (p == kNoFace) continue;
    if (p >= F || assignment.partner[p] != f || in_cover[p] == in_cover[f]) return false;
    bool adjacent = false;
    for (unsigned i = 0; i < 3; ++i) adjacent = adjacent || dual.across(f, i) == p;
    if (!adjacent) return false;
  }
  std::uint32_t count = 0;
  const std::vector<std::uint32_t> component = cover_components(dual, in_cover, &count);
  std::vector<std::uint8_t> ok(count, 0);
  for (std::uint32_t f = 0; f < F; ++f)
    if (in_cover[f] && (!dual.interior(f) || assignment.partner[f] != kNoFace)) ok[component[f]] = 1;
  for (std::uint32_t k = 0; k < count; ++k)
    if (!ok[k]) return false;
  return true;
}

}  // namespace rastrace

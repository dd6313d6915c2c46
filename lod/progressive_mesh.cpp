// The progressive-mesh builder: greedy half-edge collapses in quadric-error order (Garland and
// Heckbert 1997) with a priority queue and lazy invalidation (each entry carries the change
// stamps of its two vertices and is dropped when popped stale), then the vanilla VIPM numbering
// (Forsyth 2001) of vertices and triangles.
#include "lod/progressive_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <queue>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "core/error.h"
#include "core/rng.h"
#include "lod/progressive_mesh_input.h"
#include "lod/progressive_mesh_quadric.h"
#include "lod/vanilla_numbering.h"

namespace rastrace {
namespace {

using lod_detail::Quadric;

struct Candidate {
  double cost;
  std::uint64_t tie;  // seeded order among equal costs
  std::uint32_t binned, kept;
  std::uint32_t binned_stamp, kept_stamp;
  // std::priority_queue pops the largest: "larger" here means worse.
  bool operator<(const Candidate& o) const {
    if (cost != o.cost) return cost > o.cost;
    if (tie != o.tie) return tie > o.tie;
    if (binned != o.binned) return binned > o.binned;
    return kept > o.kept;
  }
};

class Builder {
 public:
  Builder(const Mesh& mesh, const ProgressiveMeshParams& params) : params_(params) {
    const std::size_t n = mesh.vertex_count(), faces = mesh.face_count();
    positions_.resize(n);
    for (std::size_t v = 0; v < n; ++v) positions_[v] = glm::dvec3(mesh.positions[v]);
    face_.resize(faces);
    alive_.assign(faces, 1);
    vertex_faces_.resize(n);
    for (std::size_t f = 0; f < faces; ++f)
      for (int i = 0; i < 3; ++i) {
        face_[f][i] = mesh.indices[3 * f + i];
        vertex_faces_[face_[f][i]].push_back(static_cast<std::uint32_t>(f));
      }
    alive_count_ = static_cast<std::uint32_t>(faces);
    stamp_.assign(n, 0);
    refused_.assign(n, 0);
    build_quadrics();
  }

  std::vector<HalfEdgeCollapse> run(std::uint32_t min_triangles) {
    for (std::uint32_t v = 0; v < positions_.size(); ++v) push_edges_of(v, /*both_directions=*/false);
    std::vector<HalfEdgeCollapse> collapses;
    while (alive_count_ > min_triangles && !queue_.empty()) {
      const Candidate c = queue_.top();
      queue_.pop();
      if (stamp_[c.binned] != c.binned_stamp || stamp_[c.kept] != c.kept_stamp) continue;
      if (!allowed(c.binned, c.kept)) {
        refused_[c.binned] = refused_[c.kept] = 1;
        continue;
      }
      collapse(c.binned, c.kept);
      collapses.push_back({c.binned, c.kept, c.cost});
      refresh_around(c.kept);
    }
    return collapses;
  }

 private:
  void build_quadrics() {
    quadrics_.assign(positions_.size(), Quadric{});
    // Face planes, weighted by area so that a region's error does not depend on how finely it
    // is tessellated.
    for (const auto& f : face_) {
      const glm::dvec3 &a = positions_[f[0]], &b = positions_[f[1]], &c = positions_[f[2]];
      const glm::dvec3 cross = glm::cross(b - a, c - a);
      const double len = glm::length(cross);
      if (len <= 0.0) continue;
      const glm::dvec3 n = cross / len;
      const Quadric q = Quadric::plane(n, -glm::dot(n, a), 0.5 * len);
      for (const std::uint32_t v : f) quadrics_[v] += q;
    }
    // Boundary edges (one face): a plane through the edge, perpendicular to the face, keeps
    // border vertices on the border line.
    for (std::uint32_t f = 0; f < face_.size(); ++f)
      for (int i = 0; i < 3; ++i) {
        const std::uint32_t p = face_[f][i], q = face_[f][(i + 1) % 3];
        if (face_count_on_edge(p, q) != 1) continue;
        const glm::dvec3 &a = positions_[p], &b = positions_[q], &c = positions_[face_[f][(i + 2) % 3]];
        const glm::dvec3 edge = b - a;
        const glm::dvec3 normal = glm::cross(edge, c - a);
        const glm::dvec3 side = glm::cross(edge, normal);
        const double len = glm::length(side);
        if (len <= 0.0) continue;
        const glm::dvec3 n = side / len;
        const Quadric plane = Quadric::plane(n, -glm::dot(n, a), params_.boundary_weight * glm::dot(edge, edge));
        quadrics_[p] += plane;
        quadrics_[q] += plane;
      }
  }

  std::uint32_t face_count_on_edge(std::uint32_t a, std::uint32_t b) const {
    std::uint32_t count = 0;
    for (const std::uint32_t f : vertex_faces_[a]) count += has(f, b);
    return count;
  }
  bool has(std::uint32_t f, std::uint32_t v) const { return face_[f][0] == v || face_[f][1] == v || face_[f][2] == v; }

  // The vertices joined to v by an edge, each with the number of faces on that edge (1 on a
  // boundary edge, 2 inside).
  void ring(std::uint32_t v, std::vector<std::pair<std::uint32_t, std::uint32_t>>& out) const {
    out.clear();
    for (const std::uint32_t f : vertex_faces_[v])
      for (const std::uint32_t w : face_[f]) {
        if (w == v) continue;
        auto it = std::find_if(out.begin(), out.end(), [w](const auto& e) { return e.first == w; });
        if (it == out.end())
          out.emplace_back(w, 1);
        else
          ++it->second;
      }
  }
  static bool on_boundary(const std::vector<std::pair<std::uint32_t, std::uint32_t>>& r) {
    return std::any_of(r.begin(), r.end(), [](const auto& e) { return e.second == 1; });
  }

  void push(std::uint32_t binned, std::uint32_t kept) {
    const double cost = (quadrics_[binned] + quadrics_[kept]).evaluate(positions_[kept]);
    const std::uint64_t tie = mix64(params_.seed ^ mix64((std::uint64_t(binned) << 32) | kept));
    queue_.push({cost, tie, binned, kept, stamp_[binned], stamp_[kept]});
  }
  // Both half-edges of every edge at v (or, when !both_directions, only v -> w, which is how the
  // initial fill visits each half-edge exactly once).
  void push_edges_of(std::uint32_t v, bool both_directions) {
    ring(v, ring_a_);
    for (const auto& [w, count] : ring_a_) {
      push(v, w);
      if (both_directions) push(w, v);
    }
  }

  // After a collapse onto k, only the collapses that bin or keep k change cost (k's quadric
  // grew): stamp k so its old entries go stale, and queue its edges again. The checks of a
  // collapse near k may change too; a collapse that failed them is queued again once a
  // collapse touches one of its two vertices (they are flagged `refused_`).
  void refresh_around(std::uint32_t k) {
    ++stamp_[k];
    push_edges_of(k, /*both_directions=*/true);
    refused_[k] = 0;
    for (const auto& [w, count] : ring_a_)
      if (refused_[w]) retry_.push_back(w);
    for (const std::uint32_t w : retry_) {
      refused_[w] = 0;
      ring(w, ring_b_);
      for (const auto& [x, c] : ring_b_)
        if (x != k) push(w, x), push(x, w);
    }
    retry_.clear();
  }

  // The checks of a half-edge collapse binned -> kept.
  bool allowed(std::uint32_t b, std::uint32_t k) {
    ring(b, ring_a_);
    ring(k, ring_b_);
    const auto edge = std::find_if(ring_a_.begin(), ring_a_.end(), [k](const auto& e) { return e.first == k; });
    if (edge == ring_a_.end()) return false;  // not an edge
    // Link condition: the common neighbours of b and k are exactly the apexes of the faces on
    // edge b-k; and two border vertices may only merge along a border edge. Otherwise the
    // collapse pinches the surface into a non-manifold edge or vertex.
    opposite_.clear();
    for (const std::uint32_t f : vertex_faces_[b])
      if (has(f, k))
        for (const std::uint32_t w : face_[f])
          if (w != b && w != k) opposite_.push_back(w);
    for (const auto& [w, count] : ring_a_) {
      if (w == k) continue;
      const bool common = std::any_of(ring_b_.begin(), ring_b_.end(), [w = w](const auto& e) { return e.first == w; });
      if (common && std::find(opposite_.begin(), opposite_.end(), w) == opposite_.end()) return false;
    }
    if (edge->second == 2 && on_boundary(ring_a_) && on_boundary(ring_b_)) return false;
    // No vertex may lose its last face: k, and the apexes of the binned faces.
    std::uint32_t kept_faces = 0;
    for (const std::uint32_t f : vertex_faces_[k]) kept_faces += !has(f, b);
    const std::uint32_t changed = static_cast<std::uint32_t>(vertex_faces_[b].size() - opposite_.size());
    if (kept_faces + changed == 0) return false;
    for (const std::uint32_t w : opposite_)
      if (vertex_faces_[w].size() <= std::size_t(std::count(opposite_.begin(), opposite_.end(), w))) return false;
    // Each changed face (b, x, y) becomes (k, x, y): it must not exist already (the collapse of a
    // tetrahedron), and its normal must neither flip nor vanish.
    for (const std::uint32_t f : vertex_faces_[b]) {
      if (has(f, k)) continue;
      std::array<std::uint32_t, 3> t = face_[f];
      for (const std::uint32_t g : vertex_faces_[k]) {
        int shared = 0;
        for (const std::uint32_t w : t) shared += (w != b && has(g, w));
        if (shared == 2) return false;
      }
      const glm::dvec3 before = face_normal(t);
      for (auto& w : t)
        if (w == b) w = k;
      const glm::dvec3 after = face_normal(t);
      const double lb = glm::length(before), la = glm::length(after);
      if (glm::dot(before, after) <= 0.0 || la <= 1e-12 * lb) return false;
    }
    return true;
  }

  glm::dvec3 face_normal(const std::array<std::uint32_t, 3>& t) const {
    const glm::dvec3& a = positions_[t[0]];
    return glm::cross(positions_[t[1]] - a, positions_[t[2]] - a);
  }

  void collapse(std::uint32_t b, std::uint32_t k) {
    for (const std::uint32_t f : vertex_faces_[b]) {
      if (has(f, k)) {
        alive_[f] = 0;
        --alive_count_;
        for (const std::uint32_t w : face_[f])
          if (w != b) std::erase(vertex_faces_[w], f);
      } else {
        std::uint8_t corner = face_[f][0] == b ? 0 : face_[f][1] == b ? 1 : 2;
        face_[f][corner] = k;
        vertex_faces_[k].push_back(f);
      }
    }
    vertex_faces_[b].clear();
    quadrics_[k] += quadrics_[b];
    ++stamp_[b];
  }

  const ProgressiveMeshParams& params_;
  std::vector<glm::dvec3> positions_;
  std::vector<std::array<std::uint32_t, 3>> face_;  // current vertices (original ids)
  std::vector<std::uint8_t> alive_;
  std::uint32_t alive_count_ = 0;
  std::vector<std::vector<std::uint32_t>> vertex_faces_;  // alive faces using each vertex
  std::vector<Quadric> quadrics_;
  std::vector<std::uint32_t> stamp_;
  std::vector<std::uint8_t> refused_;  // a collapse binning or keeping this vertex was refused
  std::priority_queue<Candidate> queue_;
  // Scratch space reused by every check.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> ring_a_, ring_b_;
  std::vector<std::uint32_t> opposite_, retry_;
};

}  // namespace

ProgressiveMesh build_progressive_mesh(const Mesh& mesh, const ProgressiveMeshParams& params) {
  lod_detail::check_manifold_input(mesh);
  const std::uint32_t faces = static_cast<std::uint32_t>(mesh.face_count());
  const std::uint32_t min_triangles =
      params.min_triangles != 0 ? params.min_triangles : std::max<std::uint32_t>(16, faces / 50);
  if (min_triangles > faces)
    throw InputError("mesh '" + mesh.name + "': --min-triangles " + std::to_string(min_triangles) +
                     " is larger than its " + std::to_string(faces) + " triangles");

  // The builder finds the sequence; vanilla numbering (the binned faces and changed corners of
  // each collapse included) is the one any valid sequence gets.
  Builder builder(mesh, params);
  return progressive_mesh_from_collapses(mesh, builder.run(min_triangles));
}

}  // namespace rastrace

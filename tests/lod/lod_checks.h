// Checks shared by the progressive-mesh tests, written independently of the builder's own
// checks: a triangle set is a consistently oriented two-manifold, and a collapse sequence is a
// sequence of half-edge collapses that never flips a triangle and matches the reference LoDs.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "lod/progressive_mesh.h"

namespace rastrace::testing {

using Triangles = std::vector<std::array<std::uint32_t, 3>>;

// Every vertex 0..vertex_count-1 is used; around every vertex each neighbour is reached at most
// once as "next" and once as "previous" (so every edge has at most two faces, with opposite
// directions), the faces form a single fan, and no two faces share all three vertices.
inline void expect_manifold(const Triangles& triangles, std::uint32_t vertex_count, const std::string& what) {
  std::vector<std::uint32_t> offsets(vertex_count + 1, 0);
  for (const auto& t : triangles)
    for (const std::uint32_t v : t) {
      ASSERT_LT(v, vertex_count) << what;
      ++offsets[v + 1];
    }
  for (std::uint32_t v = 0; v < vertex_count; ++v) offsets[v + 1] += offsets[v];
  std::vector<std::uint32_t> faces(offsets.back()), fill(offsets.begin(), offsets.end() - 1);
  for (std::uint32_t f = 0; f < triangles.size(); ++f)
    for (const std::uint32_t v : triangles[f]) faces[fill[v]++] = f;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> fan;  // (next, previous) of v in each face
  for (std::uint32_t v = 0; v < vertex_count; ++v) {
    const std::uint32_t begin = offsets[v], end = offsets[v + 1];
    ASSERT_LT(begin, end) << what << ": vertex " << v << " in use but on no triangle";
    fan.clear();
    for (std::uint32_t i = begin; i < end; ++i) {
      const auto& t = triangles[faces[i]];
      const int c = t[0] == v ? 0 : t[1] == v ? 1 : 2;
      fan.emplace_back(t[(c + 1) % 3], t[(c + 2) % 3]);
    }
    for (std::size_t i = 0; i < fan.size(); ++i)
      for (std::size_t j = i + 1; j < fan.size(); ++j) {
        ASSERT_NE(fan[i].first, fan[j].first) << what << ": edge " << v << "->" << fan[i].first << " twice";
        ASSERT_NE(fan[i].second, fan[j].second) << what << ": edge " << fan[i].second << "->" << v << " twice";
        ASSERT_FALSE(fan[i].first == fan[j].second && fan[i].second == fan[j].first)
            << what << ": duplicate triangle at vertex " << v;
      }
    // Walk the fan: from a face whose previous neighbour starts no other face's next (a border),
    // or from any face if the fan is closed; the walk must reach every face.
    std::size_t start = 0;
    for (std::size_t i = 0; i < fan.size(); ++i)
      if (std::none_of(fan.begin(), fan.end(), [&](const auto& e) { return e.first == fan[i].second; })) start = i;
    std::size_t reached = 1;
    for (std::size_t at = start; reached <= fan.size();) {
      const auto it = std::find_if(fan.begin(), fan.end(), [&](const auto& e) { return e.second == fan[at].first; });
      if (it == fan.end() || std::size_t(it - fan.begin()) == start) break;
      at = std::size_t(it - fan.begin());
      ++reached;
    }
    ASSERT_EQ(reached, fan.size()) << what << ": the faces around vertex " << v << " are not one fan";
  }
}

inline glm::dvec3 normal_of(const std::vector<glm::vec3>& p, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  const glm::dvec3 pa(p[a]);
  return glm::cross(glm::dvec3(p[b]) - pa, glm::dvec3(p[c]) - pa);
}

// Walks the cursor through every collapse. At each: the binned vertex is the last one in use,
// the kept vertex shares an edge with it, the binned triangles are exactly the last ones alive
// and are the triangles on that edge, the changed triangles are exactly the others using the
// binned vertex, no changed triangle's normal turns by 90 degrees or more, and the drawn
// triangles equal triangles_at_lod. Every `full_every` LoDs (and at the last) the whole triangle
// set is checked to be a manifold.
inline void expect_valid_sequence(const ProgressiveMesh& pm, const std::vector<glm::vec3>& positions,
                                  std::size_t full_every, const std::string& what) {
  ProgressiveMeshCursor cursor(pm);
  std::vector<std::uint32_t> idx(cursor.indices().begin(), cursor.indices().end());
  idx.resize(3 * pm.triangles.size());
  for (std::size_t t = 0; t < pm.triangles.size(); ++t)
    for (int i = 0; i < 3; ++i) idx[3 * t + i] = pm.triangles[t][i];
  // vertex -> the drawn triangles using it, kept up to date from the index buffer's edits.
  std::vector<std::vector<std::uint32_t>> uses(pm.vertex_order.size());
  for (std::uint32_t t = 0; t < pm.triangles.size(); ++t)
    for (const std::uint32_t v : pm.triangles[t]) uses[v].push_back(t);
  for (std::size_t n = 0; n < pm.lod_count(); ++n) {
    const std::string at = what + " LoD " + std::to_string(n);
    const std::uint32_t count = pm.triangle_count_at(n);
    ASSERT_EQ(cursor.lod(), n);
    ASSERT_TRUE(std::equal(idx.begin(), idx.begin() + 3 * count, cursor.indices().begin(), cursor.indices().end()))
        << at << ": cursor differs from the record walk";
    if (n % full_every == 0 || n + 1 == pm.lod_count()) {
      const Triangles reference = triangles_at_lod(pm, n);
      ASSERT_EQ(reference.size(), count) << at;
      for (std::uint32_t t = 0; t < count; ++t)
        ASSERT_TRUE(std::equal(reference[t].begin(), reference[t].end(), idx.begin() + 3 * t))
            << at << " triangle " << t;
      expect_manifold(reference, pm.vertex_count_at(n), at);
      if (::testing::Test::HasFatalFailure()) return;
    }
    if (n == pm.collapses.size()) break;
    const CollapseRecord& c = pm.collapses[n];
    ASSERT_EQ(c.binned, pm.vertex_count_at(n) - 1) << at;
    ASSERT_LT(c.kept, c.binned) << at;
    ASSERT_EQ(c.binned_triangles.size(), count - pm.triangle_count_at(n + 1)) << at;
    ASSERT_FALSE(c.binned_triangles.empty()) << at << ": no triangle on the edge kept-binned";
    std::vector<std::uint32_t> on_edge, changed;
    std::sort(uses[c.binned].begin(), uses[c.binned].end());
    for (const std::uint32_t t : uses[c.binned]) {
      const std::uint32_t* v = &idx[3 * t];
      const bool has_b = v[0] == c.binned || v[1] == c.binned || v[2] == c.binned;
      const bool has_k = v[0] == c.kept || v[1] == c.kept || v[2] == c.kept;
      if (has_b && has_k) on_edge.push_back(t);
      if (has_b && !has_k) changed.push_back(t);
    }
    ASSERT_EQ(on_edge, c.binned_triangles) << at;
    ASSERT_EQ(changed, c.changed_triangles) << at;
    ASSERT_EQ(c.changed_corners.size(), changed.size()) << at;
    for (std::size_t i = 0; i < changed.size(); ++i) {
      const std::uint32_t corner = c.changed_corners[i];
      ASSERT_EQ(corner / 3, changed[i]) << at;
      ASSERT_EQ(idx[corner], c.binned) << at;
      std::uint32_t* v = &idx[3 * changed[i]];
      const glm::dvec3 before = normal_of(positions, v[0], v[1], v[2]);
      idx[corner] = c.kept;
      const glm::dvec3 after = normal_of(positions, v[0], v[1], v[2]);
      ASSERT_GT(glm::dot(before, after), 0.0) << at << ": triangle " << changed[i] << " flips";
    }
    for (const std::uint32_t t : c.binned_triangles) {
      ASSERT_GE(t, pm.triangle_count_at(n + 1)) << at;
      for (int i = 0; i < 3; ++i) std::erase(uses[idx[3 * t + i]], t);
    }
    for (const std::uint32_t t : changed) uses[c.kept].push_back(t);
    uses[c.binned].clear();
    ASSERT_TRUE(cursor.collapse());
  }
  // And back up: splits restore full detail exactly.
  cursor.set_lod(0);
  for (std::size_t t = 0; t < pm.triangles.size(); ++t)
    ASSERT_TRUE(std::equal(pm.triangles[t].begin(), pm.triangles[t].end(), cursor.indices().begin() + 3 * t))
        << what << ": split did not restore triangle " << t;
}

}  // namespace rastrace::testing

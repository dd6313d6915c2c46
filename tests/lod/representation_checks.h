// What the representation tests compare: the drawn (non-degenerate) triangles as unordered
// vertex triples, each rotated to start at its smallest vertex (winding kept).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "cache_sim/vertex_cache.h"
#include "lod/progressive_mesh.h"
#include "lod/vanilla_numbering.h"
#include "lod/vipm_representation.h"

namespace rastrace::testing {

using Triple = std::array<std::uint32_t, 3>;

inline Triple canonical(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  if (b < a && b < c) return {b, c, a};
  if (c < a && c < b) return {c, a, b};
  return {a, b, c};
}

// Sorted drawn triangles, vertex ids mapped through `to_original` when given.
inline std::vector<Triple> drawn_triangles(const VipmRepresentation& r,
                                           const std::vector<std::uint32_t>* to_original = nullptr) {
  std::vector<Triple> out;
  for (const VipmDraw& d : r.draws())
    for_each_triangle(d.indices, d.type, d.restart_index, [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
      if (a == b || b == c || a == c) return;
      if (to_original) a = (*to_original)[a], b = (*to_original)[b], c = (*to_original)[c];
      out.push_back(canonical(a, b, c));
    });
  std::sort(out.begin(), out.end());
  return out;
}

// The reference: the alive triangles of the progressive mesh at LoD n, by replaying its records.
inline std::vector<Triple> reference_triangles(const ProgressiveMesh& pm, std::uint32_t n,
                                               const std::vector<std::uint32_t>* to_original = nullptr) {
  TriangleReplay replay(pm);
  replay.advance_to(n);
  std::vector<Triple> out;
  for (std::uint32_t t = 0; t < replay.alive(); ++t) {
    Triple v = replay.triangle(t);
    if (to_original)
      for (std::uint32_t& x : v) x = (*to_original)[x];
    out.push_back(canonical(v[0], v[1], v[2]));
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace rastrace::testing

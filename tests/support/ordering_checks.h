// Checks shared by the ordering tests: an ordering's face_order is a permutation of the mesh's
// faces, and its index stream draws exactly those faces, in that order, with their winding.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cache_sim/vertex_cache.h"
#include "reorder/ordering.h"

namespace rastrace::testing {

inline bool same_winding(const std::uint32_t* face, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  for (int r = 0; r < 3; ++r)
    if (face[r] == a && face[(r + 1) % 3] == b && face[(r + 2) % 3] == c) return true;
  return false;
}

// face_order is a permutation, and the stream draws exactly those faces in that order with their
// original winding (extra triangles, such as Castano's prefetch row, must be degenerate).
inline void expect_permutation_with_winding(const Mesh& mesh, const Ordering& ordering, const std::string& what) {
  ASSERT_EQ(ordering.face_order.size(), mesh.face_count()) << what;
  std::vector<std::uint8_t> seen(mesh.face_count(), 0);
  for (const std::uint32_t f : ordering.face_order) {
    ASSERT_LT(f, mesh.face_count()) << what;
    ASSERT_FALSE(seen[f]) << what << ": face " << f << " twice";
    seen[f] = 1;
  }
  std::size_t next = 0;
  bool ok = true;
  for_each_triangle(ordering.indices, ordering.type, ordering.restart_index,
                    [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
                      if (next < ordering.face_order.size() &&
                          same_winding(mesh.indices.data() + 3 * std::size_t(ordering.face_order[next]), a, b, c)) {
                        ++next;
                      } else if (a != b && b != c && a != c) {
                        ok = false;
                      }
                    });
  EXPECT_TRUE(ok) << what << ": a drawn triangle is not the next face of face_order";
  EXPECT_EQ(next, ordering.face_order.size()) << what;
}

}  // namespace rastrace::testing

// Morton and Hilbert orders of triangle centroids: on a 16x16 lattice of cells the Hilbert order
// must step between edge-adjacent cells only (the flat mesh gets the 2D curve), in 3D between
// face-adjacent cells; the Morton order must be the Z pattern.
#include <cstdlib>

#include <gtest/gtest.h>

#include "reorder/ordering.h"

namespace rastrace {
namespace {

// One small triangle per cell (x, y) of an n x n lattice, with vertices (x, y), (x+1, y),
// (x, y+1): the bounding box is [0, n]^2, so every centroid quantizes into its own cell.
Mesh cell_triangles(int n) {
  Mesh mesh;
  mesh.name = "cells";
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      const auto base = static_cast<std::uint32_t>(mesh.positions.size());
      const float z = 0.0f;
      mesh.positions.emplace_back(float(x), float(y), z);
      mesh.positions.emplace_back(float(x + 1), float(y), z);
      mesh.positions.emplace_back(float(x), float(y + 1), z);
      mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2});
    }
  }
  return mesh;
}

TEST(SpaceFilling, HilbertStepsBetweenEdgeAdjacentCells) {
  const int n = 16;
  const Ordering ordering = reorder_hilbert(cell_triangles(n), ReorderParams{});
  ASSERT_EQ(ordering.face_order.size(), std::size_t(n * n));
  for (std::size_t i = 1; i < ordering.face_order.size(); ++i) {
    const int a = int(ordering.face_order[i - 1]), b = int(ordering.face_order[i]);
    EXPECT_EQ(std::abs(a % n - b % n) + std::abs(a / n - b / n), 1) << "step " << i;
  }
  // The curve starts in a corner and ends in the adjacent corner of the same side.
  const int first = int(ordering.face_order.front()), last = int(ordering.face_order.back());
  EXPECT_EQ(first, 0);
  EXPECT_TRUE(last == n - 1 || last == n * (n - 1)) << last;
}

TEST(SpaceFilling, MortonIsTheZPattern) {
  const int n = 4;
  const Ordering ordering = reorder_morton(cell_triangles(n), ReorderParams{});
  // Axis 0 (x) is the more significant bit of each pair: (0,0) (0,1) (1,0) (1,1) (0,2) ...
  const std::vector<std::uint32_t> expected = {0, 4, 1, 5, 8, 12, 9, 13, 2, 6, 3, 7, 10, 14, 11, 15};
  EXPECT_EQ(ordering.face_order, expected);
}

TEST(SpaceFilling, HilbertInThreeDimensionsStepsBetweenFaceAdjacentCells) {
  // One triangle per cell of an 8x8x8 lattice, vertices (x,y,z) (x+1,y,z) (x,y+1,z+1): centroid
  // in the cell, bounding box [0, 8]^3.
  const int n = 8;
  Mesh mesh;
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const auto base = static_cast<std::uint32_t>(mesh.positions.size());
        mesh.positions.emplace_back(float(x), float(y), float(z));
        mesh.positions.emplace_back(float(x + 1), float(y), float(z));
        mesh.positions.emplace_back(float(x), float(y + 1), float(z + 1));
        mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2});
      }
  const Ordering ordering = reorder_hilbert(mesh, ReorderParams{});
  ASSERT_EQ(ordering.face_order.size(), std::size_t(n * n * n));
  for (std::size_t i = 1; i < ordering.face_order.size(); ++i) {
    const int a = int(ordering.face_order[i - 1]), b = int(ordering.face_order[i]);
    const int dx = std::abs(a % n - b % n), dy = std::abs(a / n % n - b / n % n),
              dz = std::abs(a / (n * n) - b / (n * n));
    EXPECT_EQ(dx + dy + dz, 1) << "step " << i;
  }
}

}  // namespace
}  // namespace rastrace

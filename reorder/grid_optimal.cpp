// Castano's cache-optimal order for regular W x H grids ("Optimal grid rendering", 2009), the
// article's gridGen() applied to make_grid's layout (mesh.grid set): vertex (x, y) = (W+1)*y + x,
// quad (x, y) = faces 2(yW+x), 2(yW+x)+1.
//
// A FIFO cache of k entries renders a row of quads without losing a vertex it needs again when it
// can hold the row's top vertices plus the two of the quad being drawn: the grid is cut into
// columns of at most k-2 quads (the last may be narrower), each drawn in scanline order. A column
// whose two vertex rows do not both fit (2 * quads + 1 > k) first loads its bottom vertex row
// with degenerate triangles (v, v, v+1), the "prefetch row", so the vertices leaving the FIFO
// afterwards are always ones never used again. Degenerates go in Ordering::indices only;
// face_order stays a permutation of the faces, with their original winding.
//
// Results (16x16 grid, FIFO): k = 20 gives ACMR 0.564 / ATVR 1.000 (every vertex once) and
// k = 16 0.598 / 1.059, as the article prints. k = 12 gives 306 true misses (0.598 / 1.059) and
// ordered for 8, run on 8 or 16, 323 (ATVR 1.118); the article prints 307 (0.600 / 1.062) and
// 325 (1.125) because its simulator charged evictions, not misses: with that accounting
// (cache_sim/eviction_charged.h, `rastrace vcache --accounting evictions`) this order gives the
// article's figures exactly.
// The minimum cache for ATVR 1 on a W x W grid is W + 2. Caches below 3 entries are ordered as for 3
// (columns one quad wide), the narrowest the construction has.
// Throws InputError for a mesh that is not a make_grid grid.
#include <algorithm>
#include <string>

#include "core/error.h"
#include "reorder/ordering.h"

namespace rastrace {

namespace {

struct GridOrderBuilder {
  int width;
  int cache;
  const Mesh& mesh;
  Ordering& out;

  std::uint32_t vertex(int x, int y) const { return static_cast<std::uint32_t>((width + 1) * y + x); }

  void emit_face(std::uint32_t face) {
    out.face_order.push_back(face);
    out.indices.insert(out.indices.end(), mesh.indices.begin() + face * 3, mesh.indices.begin() + face * 3 + 3);
  }

  // Columns x0..x1 (vertex columns, x1 - x0 quads wide), rows y0..y1.
  void columns(int x0, int x1, int y0, int y1) {
    if (x1 - x0 + 1 < cache) {
      if (2 * (x1 - x0) + 1 > cache) {
        for (int x = x0; x < x1; ++x)
          out.indices.insert(out.indices.end(), {vertex(x, y0), vertex(x, y0), vertex(x + 1, y0)});
      }
      for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) {
          const auto quad = static_cast<std::uint32_t>(y * width + x);
          emit_face(2 * quad);
          emit_face(2 * quad + 1);
        }
      }
    } else {
      const int xm = x0 + cache - 2;
      columns(x0, xm, y0, y1);
      columns(xm, x1, y0, y1);
    }
  }
};

// mesh.grid promises make_grid's layout; a mesh edited since then would give a wrong order.
void check_grid_layout(const Mesh& mesh) {
  if (!mesh.grid)
    throw InputError("grid order: mesh '" + mesh.name +
                     "' is not a regular grid (expected a procedural grid such as grid:16x16)");
  const int w = mesh.grid->width, h = mesh.grid->height;
  const std::size_t quads = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  if (mesh.face_count() != 2 * quads || mesh.vertex_count() != static_cast<std::size_t>(w + 1) * (h + 1))
    throw InputError("grid order: mesh '" + mesh.name + "' has " + std::to_string(mesh.face_count()) + " faces and " +
                     std::to_string(mesh.vertex_count()) + " vertices, expected " + std::to_string(2 * quads) +
                     " and " + std::to_string((w + 1) * (h + 1)) + " for a " + std::to_string(w) + "x" +
                     std::to_string(h) + " grid");
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const auto v = [w](int vx, int vy) { return static_cast<std::uint32_t>((w + 1) * vy + vx); };
      const std::uint32_t a = v(x, y), b = v(x, y + 1), c = v(x + 1, y), d = v(x + 1, y + 1);
      const std::size_t f = 6 * (static_cast<std::size_t>(y) * w + x);
      const std::uint32_t* i = mesh.indices.data() + f;
      if (i[0] != a || i[1] != b || i[2] != c || i[3] != c || i[4] != b || i[5] != d)
        throw InputError("grid order: mesh '" + mesh.name + "' face " + std::to_string(f / 3) +
                         " does not follow the grid layout of quad (" + std::to_string(x) + ", " + std::to_string(y) +
                         ")");
    }
  }
}

}  // namespace

Ordering reorder_grid(const Mesh& mesh, const ReorderParams& params) {
  check_grid_layout(mesh);
  Ordering ordering;
  ordering.face_order.reserve(mesh.face_count());
  ordering.indices.reserve(mesh.indices.size() + 3 * static_cast<std::size_t>(mesh.grid->width));
  const int cache = static_cast<int>(std::clamp(params.cache_size, 3u, 1u << 30));
  GridOrderBuilder builder{mesh.grid->width, cache, mesh, ordering};
  builder.columns(0, mesh.grid->width, 0, mesh.grid->height);
  return ordering;
}

}  // namespace rastrace

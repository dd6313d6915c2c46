// Scanline order: rows of triangles swept one after another, the order a naive exporter or a
// height-field generator produces. The baseline of Castano, "Optimal grid rendering", 2009.
//
// On a make_grid grid (mesh.grid set) it is the quads row by row, left to right, both triangles
// of a quad together: 16x16 gives ACMR 1.062 / ATVR 1.882 at every FIFO size from 12 to 20, since
// each row reloads the vertices the previous row brought in.
// On any other mesh the same sweep is applied to triangle centroids: the bounding box's longest
// axis runs along the rows, the second longest across them, with as many rows as a square grid of
// the same face count would have (round(sqrt(F / 2))); faces are sorted by row, then by position
// along the row, then by index. On make_grid's layout this reproduces the grid order exactly.
// Parameters: none (cache size and policy are ignored). Deterministic.
#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

#include "reorder/ordering.h"
#include "scenes/bounding_box.h"

namespace rastrace {

Ordering reorder_scanline(const Mesh& mesh, const ReorderParams& /*params*/) {
  const std::size_t faces = mesh.face_count();
  std::vector<std::uint32_t> order(faces);
  std::iota(order.begin(), order.end(), 0u);
  if (mesh.grid || faces == 0) return list_ordering(mesh, std::move(order));

  const BoundingBox box = bounding_box(mesh.positions, mesh.indices);
  const glm::vec3 lo = box.lo, extent = box.extent();
  std::array<int, 3> axes = {0, 1, 2};
  std::stable_sort(axes.begin(), axes.end(), [&](int a, int b) { return extent[a] > extent[b]; });
  const int along = axes[0], across = axes[1];
  const double rows = std::max(1.0, std::round(std::sqrt(double(faces) / 2.0)));

  struct Key {
    std::int64_t row;
    float along;
  };
  std::vector<Key> keys(faces);
  for (std::size_t f = 0; f < faces; ++f) {
    const glm::vec3 c = (mesh.positions[mesh.indices[3 * f]] + mesh.positions[mesh.indices[3 * f + 1]] +
                         mesh.positions[mesh.indices[3 * f + 2]]) /
                        3.0f;
    // Non-finite coordinates (a NaN in a file) must still give a strict weak order: row 0, x 0.
    const double t = extent[across] > 0 ? (double(c[across]) - lo[across]) / extent[across] : 0.0;
    const double row = std::isfinite(t) ? std::clamp(std::floor(t * rows), 0.0, rows - 1) : 0.0;
    keys[f] = {static_cast<std::int64_t>(row), std::isfinite(c[along]) ? c[along] : 0.0f};
  }
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    if (keys[a].row != keys[b].row) return keys[a].row < keys[b].row;
    if (keys[a].along != keys[b].along) return keys[a].along < keys[b].along;
    return a < b;
  });
  return list_ordering(mesh, std::move(order));
}

}  // namespace rastrace

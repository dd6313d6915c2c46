// The greedy builder: a meshlet grows from a seed triangle by the triangle around its vertices
// that adds the fewest new vertices; among those, the one with the most corners whose last
// unplaced triangle it is (it finishes them: they will never be shaded again), then the one
// nearest the meshlet's centroid, which keeps meshlets round and their shared perimeter short.
// A meshlet closes when no triangle around it fits.
//
// Cost is the sum over vertices of the meshlets that hold them: every meshlet vertex that still
// has unplaced triangles when its meshlet closes is shaded again later. Finishing vertices first
// and keeping the front short both lower that count. Where the next meshlet starts matters as much:
// two seed rules are run and the set with fewer vertices kept (the first on a tie):
//   corner   the triangle around the closed meshlet with the fewest unplaced triangles at its
//            corners (a corner of the unplaced region: no sliver is left behind), nearest the
//            closed meshlet's centroid among equals
//   nearest  the triangle around the closed meshlet nearest its centroid
// Either rule falls back to the first unplaced triangle of the stream when the closed meshlet has
// none around it. The candidates are the unplaced triangles around the open meshlet's vertices,
// scanned afresh for each triangle: at most max_vertices vertex fans, no allocation in the loop.
#include <limits>

#include "reorder/meshlets/meshlet.h"

namespace rastrace {

namespace {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

enum class SeedRule { Corner, Nearest };

// Unplaced triangles around each vertex, as compressed rows; a placed triangle is swapped out
// of its vertices' rows so they only hold unplaced ones.
struct LiveFans {
  std::vector<std::uint32_t> offset, count, triangles;

  LiveFans(std::span<const std::uint32_t> indices, std::size_t vertex_count)
      : offset(vertex_count + 1, 0), count(vertex_count, 0), triangles(indices.size()) {
    for (const std::uint32_t v : indices) ++count[v];
    for (std::size_t v = 0; v < vertex_count; ++v) offset[v + 1] = offset[v] + count[v];
    std::vector<std::uint32_t> fill(offset.begin(), offset.end() - 1);
    for (std::size_t i = 0; i < indices.size(); ++i) triangles[fill[indices[i]]++] = static_cast<std::uint32_t>(i / 3);
  }
  std::span<const std::uint32_t> of(std::uint32_t v) const { return {triangles.data() + offset[v], count[v]}; }
  void remove(std::uint32_t v, std::uint32_t triangle) {
    std::uint32_t* row = triangles.data() + offset[v];
    for (std::uint32_t i = 0; i < count[v]; ++i)
      if (row[i] == triangle) {
        row[i] = row[--count[v]];
        return;
      }
  }
};

float distance2(const glm::vec3& a, const glm::vec3& b) {
  const glm::vec3 d = a - b;
  return d.x * d.x + d.y * d.y + d.z * d.z;
}

MeshletSet grow_meshlets(std::span<const std::uint32_t> indices, std::span<const glm::vec3> centroid,
                         std::size_t vertex_count, const MeshletLimits& limits, SeedRule rule) {
  const std::size_t triangle_count = indices.size() / 3;
  MeshletAccumulator meshlets(vertex_count, limits);
  LiveFans fans(indices, vertex_count);
  std::vector<bool> placed(triangle_count, false);
  std::size_t next_unplaced = 0;  // every triangle before it in the stream is placed
  glm::vec3 sum(0.0f);            // centroid sum of the open meshlet's triangles
  const auto corner = [&](std::uint32_t t, int k) { return indices[3 * std::size_t{t} + k]; };
  const auto place = [&](std::uint32_t t) {
    meshlets.append(corner(t, 0), corner(t, 1), corner(t, 2));
    placed[t] = true;
    sum += centroid[t];
    for (int k = 0; k < 3; ++k) fans.remove(corner(t, k), t);  // a repeated corner: the second finds nothing
  };

  std::vector<std::uint32_t> closed;  // the vertices of the meshlet just closed
  std::uint32_t seed = triangle_count ? 0 : kNone;
  for (std::size_t placed_count = 0; placed_count < triangle_count;) {
    place(seed);
    ++placed_count;
    for (;;) {  // grow
      const glm::vec3 center = sum / float(meshlets.open().triangle_count);
      std::uint32_t best = kNone, best_extra = kNone, best_finished = 0;
      float best_distance = std::numeric_limits<float>::max();
      for (const std::uint32_t v : meshlets.open_vertices())
        for (const std::uint32_t t : fans.of(v)) {
          const std::uint32_t a = corner(t, 0), b = corner(t, 1), c = corner(t, 2);
          if (!meshlets.fits(a, b, c)) continue;
          const std::uint32_t extra = meshlets.new_vertices(a, b, c);
          if (extra > best_extra) continue;
          const std::uint32_t finished = (fans.count[a] == 1) + (fans.count[b] == 1) + (fans.count[c] == 1);
          const float distance = distance2(centroid[t], center);
          if (extra < best_extra || finished > best_finished ||
              (finished == best_finished && distance < best_distance)) {
            best = t;
            best_extra = extra;
            best_finished = finished;
            best_distance = distance;
          }
        }
      if (best == kNone) break;
      place(best);
      ++placed_count;
    }
    // Close, and seed the next meshlet around the closed one.
    const glm::vec3 center = sum / float(meshlets.open().triangle_count);
    const std::span<const std::uint32_t> front = meshlets.open_vertices();
    closed.assign(front.begin(), front.end());
    meshlets.close();
    sum = glm::vec3(0.0f);
    seed = kNone;
    std::uint32_t fewest = kNone;
    float nearest = std::numeric_limits<float>::max();
    for (const std::uint32_t v : closed)
      for (const std::uint32_t t : fans.of(v)) {
        const std::uint32_t around =
            rule == SeedRule::Corner ? fans.count[corner(t, 0)] + fans.count[corner(t, 1)] + fans.count[corner(t, 2)]
                                     : 0;
        const float distance = distance2(centroid[t], center);
        if (around < fewest || (around == fewest && distance < nearest)) {
          fewest = around;
          nearest = distance;
          seed = t;
        }
      }
    if (seed == kNone && placed_count < triangle_count) {
      while (placed[next_unplaced]) ++next_unplaced;
      seed = static_cast<std::uint32_t>(next_unplaced);
    }
  }
  return meshlets.finish();
}

}  // namespace

MeshletSet build_meshlets_greedy(std::span<const std::uint32_t> indices, std::span<const glm::vec3> positions,
                                 const MeshletLimits& limits) {
  validate_triangle_list(indices, positions.size());
  std::vector<glm::vec3> centroid(indices.size() / 3);
  for (std::size_t t = 0; t < centroid.size(); ++t)
    centroid[t] = (positions[indices[3 * t]] + positions[indices[3 * t + 1]] + positions[indices[3 * t + 2]]) / 3.0f;
  MeshletSet corner = grow_meshlets(indices, centroid, positions.size(), limits, SeedRule::Corner);
  MeshletSet nearest = grow_meshlets(indices, centroid, positions.size(), limits, SeedRule::Nearest);
  return nearest.vertices.size() < corner.vertices.size() ? std::move(nearest) : std::move(corner);
}

}  // namespace rastrace

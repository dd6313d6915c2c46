#include "reorder/overdraw_clusters.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "reorder/tipsy.h"

namespace rastrace {

namespace {

// A FIFO of k entries by time stamps: a vertex is cached while fewer than k vertices entered
// after it; flush() empties it in O(1).
class StampedFifo {
 public:
  StampedFifo(std::size_t vertex_count, std::uint32_t k) : stamp_(vertex_count, 0), k_(k), time_(k + 1) {}
  // Misses of one triangle (a repeated corner is looked up again and hits).
  std::uint32_t misses(const std::uint32_t* corners) {
    std::uint32_t misses = 0;
    for (int c = 0; c < 3; ++c) {
      if (time_ - stamp_[corners[c]] > k_) {
        stamp_[corners[c]] = time_++;
        ++misses;
      }
    }
    return misses;
  }
  void flush() { time_ += k_ + 1; }

 private:
  std::vector<std::uint32_t> stamp_;
  std::uint32_t k_;
  std::uint32_t time_;
};

}  // namespace

OverdrawClusters tipsy_overdraw_clusters(const Mesh& mesh, const ReorderParams& params) {
  if (!std::isfinite(params.overdraw_lambda) || params.overdraw_lambda <= 0)
    throw InputError("--lambda " + std::to_string(params.overdraw_lambda) +
                     ": expected a positive markup on Tipsy's ACMR (1.05 = 5%)");
  OverdrawClusters clusters;
  std::vector<std::uint32_t> path_starts;
  clusters.tipsy_faces = tipsify(mesh, params, &path_starts).face_order;
  const std::vector<std::uint32_t>& faces = clusters.tipsy_faces;
  const std::size_t face_count = faces.size();
  if (face_count == 0) return clusters;
  const std::uint32_t* idx = mesh.indices.data();
  const std::uint32_t k = std::clamp(params.cache_size, 1u, 1u << 24);

  // Tipsy's ACMR, and its hard boundaries: the dead ends after which the cache really holds
  // nothing of the new path (its first triangle misses every vertex). Tipsy often resumes next to
  // where it stopped, from the dead-end stack; cutting there would cost misses the paper's
  // argument ("discontinuities naturally cause the vertex cache to be flushed") does not cover.
  StampedFifo fifo(mesh.vertex_count(), k);
  std::vector<std::uint32_t> hard_starts;
  std::uint64_t misses = 0;
  std::size_t next_path = 0;
  for (std::uint32_t i = 0; i < face_count; ++i) {
    const std::uint32_t* corners = idx + 3 * std::size_t(faces[i]);
    const std::uint32_t face_misses = fifo.misses(corners);
    misses += face_misses;
    while (next_path < path_starts.size() && path_starts[next_path] < i) ++next_path;
    const bool path_start = next_path < path_starts.size() && path_starts[next_path] == i;
    const std::uint32_t distinct = 1 + (corners[1] != corners[0]) + (corners[2] != corners[0] && corners[2] != corners[1]);
    if (i == 0 || (path_start && face_misses == distinct)) hard_starts.push_back(i);
  }
  clusters.tipsy_acmr = double(misses) / double(face_count);
  clusters.threshold = params.overdraw_lambda * clusters.tipsy_acmr;

  // Soft boundaries inside each hard cluster: cut before the next triangle when the cluster's
  // ACMR so far, from a flushed cache, is below the threshold t. Returns the cluster starts and
  // the misses of the clustered order with every cluster counted from a flushed cache.
  hard_starts.push_back(std::uint32_t(face_count));
  const auto cut = [&](double t, std::vector<std::uint32_t>& starts) {
    starts.clear();
    std::uint64_t flushed_misses = 0;
    for (std::size_t p = 0; p + 1 < hard_starts.size(); ++p) {
      const std::uint32_t begin = hard_starts[p], end = hard_starts[p + 1];
      starts.push_back(begin);
      fifo.flush();
      std::uint64_t cluster_misses = 0, cluster_faces = 0;
      for (std::uint32_t i = begin; i < end; ++i) {
        const std::uint32_t face_misses = fifo.misses(idx + 3 * std::size_t(faces[i]));
        cluster_misses += face_misses;
        flushed_misses += face_misses;
        ++cluster_faces;
        if (i + 1 < end && double(cluster_misses) < t * double(cluster_faces)) {
          starts.push_back(i + 1);
          fifo.flush();
          cluster_misses = cluster_faces = 0;
        }
      }
    }
    return flushed_misses;
  };
  // Sander et al. cut at t = lambda and note that lambda is then a close lower bound of the
  // result's ACMR: each cluster ends just under it, and the tail of a path, never cut, lies
  // above. To make lambda a bound, the threshold is the largest t (bisection, 12 steps, so within
  // lambda / 4096) whose clusters, each counted from a flushed cache, miss at most lambda x
  // Tipsy's misses; the order's real ACMR is at most that (clusters rarely gain from the cache
  // the previous one leaves, and never lose to it in practice).
  const double budget = params.overdraw_lambda * double(misses);
  double low = 0.0, high = clusters.threshold;
  std::vector<std::uint32_t> trial;
  if (double(cut(high, trial)) <= budget) {
    low = high;
  } else {
    for (int step = 0; step < 12; ++step) {
      const double middle = 0.5 * (low + high);
      (double(cut(middle, trial)) <= budget ? low : high) = middle;
    }
  }
  clusters.threshold = low;
  cut(low, clusters.starts);

  // Area-weighted centroids and normals, in double (a cluster may hold thousands of faces).
  const std::size_t count = clusters.starts.size();
  clusters.centroids.resize(count);
  clusters.normals.resize(count);
  glm::dvec3 surface_sum(0.0), corner_sum(0.0);
  double surface_area = 0;
  for (std::size_t c = 0; c < count; ++c) {
    const std::size_t end = c + 1 < count ? clusters.starts[c + 1] : face_count;
    glm::dvec3 centroid_sum(0.0), cluster_corners(0.0), normal_sum(0.0);
    double area = 0;
    for (std::size_t i = clusters.starts[c]; i < end; ++i) {
      const std::uint32_t* corners = idx + 3 * std::size_t(faces[i]);
      const glm::dvec3 a(mesh.positions[corners[0]]), b(mesh.positions[corners[1]]), d(mesh.positions[corners[2]]);
      const glm::dvec3 normal = glm::cross(b - a, d - a);  // length: twice the area
      const double twice_area = glm::length(normal);
      centroid_sum += (a + b + d) * (twice_area / 3.0);
      cluster_corners += (a + b + d) / 3.0;
      normal_sum += normal;
      area += twice_area;
    }
    clusters.centroids[c] = area > 0 ? centroid_sum / area : cluster_corners / double(end - clusters.starts[c]);
    const double length = glm::length(normal_sum);
    clusters.normals[c] = length > 0 ? normal_sum / length : glm::dvec3(0.0);
    surface_sum += centroid_sum;
    corner_sum += cluster_corners;
    surface_area += area;
  }
  clusters.mesh_centroid = surface_area > 0 ? surface_sum / surface_area : corner_sum / double(face_count);
  return clusters;
}

Ordering ordering_of_clusters(const Mesh& mesh, const OverdrawClusters& clusters,
                              std::span<const std::uint32_t> cluster_order) {
  std::vector<std::uint32_t> face_order;
  face_order.reserve(clusters.tipsy_faces.size());
  for (const std::uint32_t c : cluster_order) {
    const std::size_t end = c + 1 < clusters.size() ? clusters.starts[c + 1] : clusters.tipsy_faces.size();
    face_order.insert(face_order.end(), clusters.tipsy_faces.begin() + clusters.starts[c],
                      clusters.tipsy_faces.begin() + std::ptrdiff_t(end));
  }
  return list_ordering(mesh, std::move(face_order));
}

std::vector<std::uint32_t> clusters_by_decreasing(std::span<const double> keys) {
  std::vector<std::uint32_t> order(keys.size());
  std::iota(order.begin(), order.end(), 0u);
  // A key that is not a number (a NaN position) sorts last, so the comparison stays a strict order.
  const auto key = [&](std::uint32_t c) { return std::isnan(keys[c]) ? -INFINITY : keys[c]; };
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return key(a) > key(b); });
  return order;
}

}  // namespace rastrace

// Front-to-back and back-to-front: the orders a user would try first for one known view. The
// clusters of tipsy-overdraw (overdraw_clusters.h, so the vertex cache pays the same) sorted by
// the depth of their area-weighted centroid along the view direction: nearest first gives the
// early depth test the most to reject in that view, farthest first the least (every later,
// nearer surface is shaded again). Clusters are not depth-separable, so even front-to-back
// leaves some overdraw; and the order is only good for views near the one given.
//
// Parameters: view_direction (where the camera looks), cache_size and overdraw_lambda as for
// tipsy-overdraw. An orthographic view: only the direction matters, not the eye's position.
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "reorder/ordering.h"
#include "reorder/overdraw_clusters.h"

namespace rastrace {

namespace {

// Depth grows away from the eye: nearest first is increasing depth.
Ordering sorted_along_view(const Mesh& mesh, const ReorderParams& params, bool nearest_first) {
  const glm::dvec3 look(params.view_direction);
  if (!(glm::length(look) > 0) || !std::isfinite(glm::length(look)))
    throw InputError("--view: the view direction must be a finite vector that is not zero");
  const OverdrawClusters clusters = tipsy_overdraw_clusters(mesh, params);
  std::vector<double> key(clusters.size());
  for (std::size_t c = 0; c < clusters.size(); ++c) {
    const double depth = glm::dot(clusters.centroids[c], look);
    key[c] = nearest_first ? -depth : depth;
  }
  return ordering_of_clusters(mesh, clusters, clusters_by_decreasing(key));
}

}  // namespace

Ordering reorder_front_to_back(const Mesh& mesh, const ReorderParams& params) {
  return sorted_along_view(mesh, params, true);
}

Ordering reorder_back_to_front(const Mesh& mesh, const ReorderParams& params) {
  return sorted_along_view(mesh, params, false);
}

}  // namespace rastrace

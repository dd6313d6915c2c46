// Tipsy with overdraw reduction ("tipsy-overdraw"): Sander, Nehab and Barczak, "Fast triangle
// reordering for vertex locality and reduced overdraw", SIGGRAPH 2007, sections 4 and 5.
//
// The clusters of fast linear clustering (overdraw_clusters.h) are drawn in decreasing order of
// their approximate occlusion potential O'(P, M) = (C(P) - C(M)) . N(P), C the area-weighted
// centroid, N(P) the patch's average normal: a patch far out on the model and facing away from
// it can hide much of the model from many directions and is drawn first; the insides of concave
// regions, which hide nothing, last. The exact potential (their equation 2) is an integral over
// pairs of surface points, O(t^2); this linear approximation gives a similar order.
//
// Parameters: cache_size (Tipsy's FIFO and the clustering's), overdraw_lambda (the soft-boundary
// markup on Tipsy's ACMR; larger: more, smaller clusters, lower overdraw, higher ACMR).
// Deterministic. meshoptimizer's meshopt_optimizeOverdraw implements the same paper on any
// vertex-cache order (its own hard boundaries: a triangle that misses all three vertices).
#include <vector>

#include <glm/geometric.hpp>

#include "reorder/ordering.h"
#include "reorder/overdraw_clusters.h"

namespace rastrace {

Ordering reorder_tipsy_overdraw(const Mesh& mesh, const ReorderParams& params) {
  const OverdrawClusters clusters = tipsy_overdraw_clusters(mesh, params);
  std::vector<double> potential(clusters.size());
  for (std::size_t c = 0; c < clusters.size(); ++c)
    potential[c] = glm::dot(clusters.centroids[c] - clusters.mesh_centroid, clusters.normals[c]);
  return ordering_of_clusters(mesh, clusters, clusters_by_decreasing(potential));
}

}  // namespace rastrace

// Fast linear clustering (Sander, Nehab, Barczak, "Fast triangle reordering for vertex locality
// and reduced overdraw", SIGGRAPH 2007, section 4) and the geometry the cluster sorts need.
//
// Tipsy's order is cut at its dead ends (hard boundaries: the path jumps, the cache is flushed)
// and, inside a path, before triangle i whenever M_i < lambda (soft boundaries), M_i being the
// ACMR of the current cluster so far from a flushed FIFO of params.cache_size entries (it starts
// at 3 and falls towards 0.5). Sander et al. choose lambda "a small fraction higher than the
// post-Tipsify vertex cache efficiency"; here lambda = params.overdraw_lambda x the Tipsy order's
// ACMR, so 1.05 is a 5% markup. Clusters are atoms: sorting them moves whole clusters. Hard
// boundaries are kept only where the cache really was flushed (the new path's first triangle
// misses all its vertices), and the threshold actually used is the largest at most lambda whose
// clusters, each from a flushed cache, miss at most lambda x Tipsy's misses: so lambda bounds
// the ACMR of any cluster order (up to the rare FIFO case where a cluster loses to the cache the
// previous one left), where the paper's rule makes it "a close lower bound".
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "reorder/ordering.h"

namespace rastrace {

struct OverdrawClusters {
  std::vector<std::uint32_t> tipsy_faces;  // Tipsy's face order
  std::vector<std::uint32_t> starts;       // position in tipsy_faces of each cluster's first face, ascending
  std::vector<glm::dvec3> centroids;       // area-weighted centroid of each cluster's surface
  std::vector<glm::dvec3> normals;         // unit average (area-weighted) normal; zero if it cancels out
  glm::dvec3 mesh_centroid{0.0};           // area-weighted centroid of the whole surface
  double tipsy_acmr = 0;                   // FIFO cache_size ACMR of Tipsy's order
  double threshold = 0;                    // the threshold used: at most overdraw_lambda * tipsy_acmr

  std::size_t size() const { return starts.size(); }
};

// Throws InputError (via Tipsy) for a bad index, and for overdraw_lambda not finite or <= 0.
OverdrawClusters tipsy_overdraw_clusters(const Mesh& mesh, const ReorderParams& params);

// The triangle list drawing the clusters in the given order (a permutation of 0..size-1).
Ordering ordering_of_clusters(const Mesh& mesh, const OverdrawClusters& clusters,
                              std::span<const std::uint32_t> cluster_order);

// Cluster indices sorted by decreasing key (ties keep the Tipsy order): the sorts of
// tipsy-overdraw, front-to-back and back-to-front differ only in the key.
std::vector<std::uint32_t> clusters_by_decreasing(std::span<const double> keys);

}  // namespace rastrace

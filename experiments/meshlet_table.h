// Meshlets built from an ordering's index stream, as `rastrace meshlets` prints them: one row per
// ordering and builder (rastrace's scan, greedy and spatial builders, and meshoptimizer's
// buildMeshlets and buildMeshletsScan as the peers "meshopt" and "meshopt-scan", run in the same
// process on the same triangle list) with the statistics of reorder/meshlets/meshlet_stats.h.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "cache_sim/live_bank_sink.h"
#include "core/table.h"
#include "reorder/meshlets/meshlet.h"
#include "scenes/mesh.h"

namespace rastrace {

struct MeshletTableSpec {
  std::string orders = "original";  // one ordering or "a,b,c"
  std::string builders = "all";     // "all" or a list of scan, greedy, spatial, meshopt, meshopt-scan
  MeshletLimits limits;
  VertexCacheSpec local_cache = vertex_cache_spec(VertexCachePolicy::Fifo, 8);  // the in-meshlet ACMR's cache
  std::uint64_t seed = 1;
  bool with_time = true;
  // Called with every set built (for -o), after its row is measured.
  std::function<void(const std::string& order, const std::string& builder, const MeshletSet& set)> on_built;
};

// The builder names, in table order.
const std::vector<std::string>& meshlet_builder_names();

// The triangles an ordering draws, as a list (strips unrolled, degenerate triangles dropped).
std::vector<std::uint32_t> ordered_triangle_list(const Mesh& mesh, const std::string& order, std::uint64_t seed);

// Runs one builder by name on a triangle list. Throws InputError for an unknown name or for a
// meshoptimizer peer on limits it cannot build (meshlet_peer.h).
MeshletSet build_meshlets(const std::string& builder, std::span<const std::uint32_t> triangles, const Mesh& mesh,
                          const MeshletLimits& limits);

// "all" runs the peers only where meshoptimizer can build the limits; named explicitly, a peer that
// cannot is an InputError.
Table meshlet_table(const Mesh& mesh, const std::string& mesh_spec, const MeshletTableSpec& spec);

}  // namespace rastrace

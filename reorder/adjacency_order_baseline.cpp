// The baseline ordering of adjacency primitives: an off-the-shelf triangle method (kcache, Lin and
// Yu 2006) applied to the cover faces, as Sander et al. 2008 compare against.
#include <numeric>

#include "core/error.h"
#include "reorder/adjacency_order.h"
#include "reorder/ordering.h"

namespace rastrace {

const char* to_string(AdjacencyOrder order) {
  switch (order) {
    case AdjacencyOrder::Careful: return "careful";
    case AdjacencyOrder::Fast: return "fast";
    case AdjacencyOrder::Baseline: return "baseline";
  }
  return "?";
}

AdjacencyOrder parse_adjacency_order(const std::string& text) {
  if (text == "careful") return AdjacencyOrder::Careful;
  if (text == "fast") return AdjacencyOrder::Fast;
  if (text == "baseline") return AdjacencyOrder::Baseline;
  throw InputError("unknown adjacency ordering '" + text + "': expected careful, fast or baseline");
}

std::vector<std::uint32_t> order_adjacency_baseline(const Mesh& mesh, const AdjacencyPrimitives& primitives,
                                                    unsigned cache_size) {
  Mesh covers;
  covers.name = mesh.name;
  covers.positions = mesh.positions;
  covers.indices.reserve(primitives.size() * 3);
  for (const std::uint32_t f : primitives.cover_face)
    covers.indices.insert(covers.indices.end(), mesh.indices.begin() + 3 * std::size_t{f},
                          mesh.indices.begin() + 3 * std::size_t{f} + 3);
  ReorderParams params;
  params.cache_size = cache_size;
  const Ordering ordering = find_reorder_algorithm("kcache").run(covers, params);
  return ordering.face_order;  // face k of `covers` is primitive k
}

std::vector<std::uint32_t> order_adjacency(AdjacencyOrder order, const Mesh& mesh,
                                           const AdjacencyPrimitives& primitives, unsigned cache_size) {
  switch (order) {
    case AdjacencyOrder::Careful:
      return order_adjacency_careful(primitives, static_cast<std::uint32_t>(mesh.vertex_count()), cache_size);
    case AdjacencyOrder::Fast:
      return order_adjacency_fast(primitives, static_cast<std::uint32_t>(mesh.vertex_count()), cache_size);
    case AdjacencyOrder::Baseline: return order_adjacency_baseline(mesh, primitives, cache_size);
  }
  return {};
}

}  // namespace rastrace

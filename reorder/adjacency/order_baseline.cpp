// The baseline orderings of adjacency primitives: an off-the-shelf triangle method (kcache, Lin and
// Yu 2006) applied to the cover faces (`baseline`) or to the whole mesh (`baseline-mesh`), as
// Sander et al. 2008 compare against. See reorder/adjacency/order.h.
#include <numeric>
#include <stdexcept>

#include "core/enum_names.h"
#include "reorder/adjacency/order.h"
#include "reorder/ordering.h"

namespace rastrace {

namespace {

constexpr EnumName<AdjacencyOrder> kOrders[] = {{AdjacencyOrder::Careful, "careful"},
                                                {AdjacencyOrder::Fast, "fast"},
                                                {AdjacencyOrder::Baseline, "baseline"},
                                                {AdjacencyOrder::BaselineMesh, "baseline-mesh"}};

}  // namespace

const char* to_string(AdjacencyOrder order) { return enum_to_string(order, kOrders); }

AdjacencyOrder parse_adjacency_order(const std::string& text) {
  return parse_enum(text, kOrders, "adjacency ordering");
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

std::vector<std::uint32_t> order_adjacency_baseline_mesh(const Mesh& mesh, const AdjacencyPrimitives& primitives,
                                                         unsigned cache_size) {
  // Every face belongs to exactly one primitive, as its cover face or as its assigned face.
  constexpr std::uint32_t kUnowned = 0xFFFFFFFFu;
  std::vector<std::uint32_t> owner(mesh.face_count(), kUnowned);
  for (std::uint32_t p = 0; p < primitives.size(); ++p) {
    if (primitives.cover_face[p] >= owner.size() ||
        (primitives.assigned_face[p] != kNoFace && primitives.assigned_face[p] >= owner.size()))
      throw std::invalid_argument("adjacency baseline-mesh ordering: primitive of a face outside the mesh");
    owner[primitives.cover_face[p]] = p;
    if (primitives.assigned_face[p] != kNoFace) owner[primitives.assigned_face[p]] = p;
  }
  ReorderParams params;
  params.cache_size = cache_size;
  const Ordering ordering = find_reorder_algorithm("kcache").run(mesh, params);
  std::vector<std::uint8_t> placed(primitives.size(), 0);
  std::vector<std::uint32_t> order;
  order.reserve(primitives.size());
  for (const std::uint32_t f : ordering.face_order) {
    const std::uint32_t p = owner[f];
    if (p == kUnowned || placed[p]) continue;  // its first face came earlier
    placed[p] = 1;
    order.push_back(p);
  }
  // Only a primitive set that leaves faces out (not one built by build_adjacency_primitives) can
  // have a primitive none of whose faces the mesh order reaches; it follows in index order.
  for (std::uint32_t p = 0; p < primitives.size(); ++p)
    if (!placed[p]) order.push_back(p);
  return order;
}

std::vector<std::uint32_t> order_adjacency(AdjacencyOrder order, const Mesh& mesh,
                                           const AdjacencyPrimitives& primitives, unsigned cache_size) {
  switch (order) {
    case AdjacencyOrder::Careful:
      return order_adjacency_careful(primitives, static_cast<std::uint32_t>(mesh.vertex_count()), cache_size);
    case AdjacencyOrder::Fast:
      return order_adjacency_fast(primitives, static_cast<std::uint32_t>(mesh.vertex_count()), cache_size);
    case AdjacencyOrder::Baseline:
      return order_adjacency_baseline(mesh, primitives, cache_size);
    case AdjacencyOrder::BaselineMesh:
      return order_adjacency_baseline_mesh(mesh, primitives, cache_size);
  }
  return {};
}

}  // namespace rastrace

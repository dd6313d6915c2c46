// A uniformly random face order: the worst case a cache-unaware exporter could produce. The
// shuffle of core/rng.h keeps the order identical on every platform for a given seed.
#include <numeric>

#include "core/rng.h"
#include "reorder/ordering.h"

namespace rastrace {

Ordering reorder_random(const Mesh& mesh, const ReorderParams& params) {
  std::vector<std::uint32_t> order(mesh.face_count());
  std::iota(order.begin(), order.end(), 0u);
  Rng rng(params.seed);
  shuffle(std::span(order), rng);
  return list_ordering(mesh, std::move(order));
}

}  // namespace rastrace

// The file's own face order: the baseline every table starts from.
#include <numeric>

#include "reorder/ordering.h"

namespace rastrace {

Ordering reorder_original(const Mesh& mesh, const ReorderParams& /*params*/) {
  std::vector<std::uint32_t> order(mesh.face_count());
  std::iota(order.begin(), order.end(), 0u);
  return list_ordering(mesh, std::move(order));
}

}  // namespace rastrace

// A uniformly random face order: the worst case a cache-unaware exporter could produce.
// std::shuffle's result depends on the library; a hand-rolled Fisher-Yates over splitmix64
// keeps the order identical on every platform for a given seed.
#include <numeric>

#include "reorder/ordering.h"

namespace rastrace {

namespace {

std::uint64_t splitmix64(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

}  // namespace

Ordering reorder_random(const Mesh& mesh, const ReorderParams& params) {
  std::vector<std::uint32_t> order(mesh.face_count());
  std::iota(order.begin(), order.end(), 0u);
  std::uint64_t state = params.seed;
  for (std::size_t i = order.size(); i > 1; --i) {
    const std::size_t j = splitmix64(state) % i;
    std::swap(order[i - 1], order[j]);
  }
  return list_ordering(mesh, std::move(order));
}

}  // namespace rastrace

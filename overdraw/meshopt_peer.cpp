#include "overdraw/meshopt_peer.h"

#include <meshoptimizer.h>

namespace rastrace {

static_assert(sizeof(glm::vec3) == 3 * sizeof(float), "positions are passed to meshoptimizer as packed floats");

OverdrawCounts meshopt_analyze_overdraw(std::span<const glm::vec3> positions,
                                        std::span<const std::uint32_t> triangle_list) {
  const meshopt_OverdrawStatistics statistics = meshopt_analyzeOverdraw(
      triangle_list.data(), triangle_list.size(), &positions.data()->x, positions.size(), sizeof(glm::vec3));
  return OverdrawCounts{statistics.pixels_shaded, statistics.pixels_covered};
}

std::vector<std::uint32_t> meshopt_optimize_overdraw(std::span<const glm::vec3> positions,
                                                     std::span<const std::uint32_t> triangle_list, float threshold) {
  std::vector<std::uint32_t> result(triangle_list.size());
  meshopt_optimizeOverdraw(result.data(), triangle_list.data(), triangle_list.size(), &positions.data()->x,
                           positions.size(), sizeof(glm::vec3), threshold);
  return result;
}

}  // namespace rastrace

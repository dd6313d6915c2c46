// Every ordering on the generated pathological meshes (tests/support/pathological_meshes.h):
// each finishes, within a generous bound that only a hang or a quadratic blow-up exceeds, and
// returns a permutation of the faces. bench/pathological.cpp measures the times against a
// well-formed mesh of the same face count.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <numeric>

#include <gtest/gtest.h>

#include "core/error.h"
#include "reorder/ordering.h"
#include "tests/support/pathological_meshes.h"

namespace rastrace {
namespace {

TEST(PathologicalMeshes, EveryOrderingFinishesQuicklyWithAPermutationOfTheFaces) {
  ReorderParams params;
  params.time_budget_seconds = 0.5;
  for (const auto& [name, mesh] : testing::pathological_meshes(3000)) {
    for (const ReorderAlgorithm& algorithm : reorder_algorithms()) {
      const auto start = std::chrono::steady_clock::now();
      Ordering ordering;
      try {
        ordering = algorithm.run(mesh, params);
      } catch (const InputError& e) {
        // Orderings made for one kind of mesh (grid) refuse the others, clearly: that is fine.
        EXPECT_NE(std::string(e.what()).find("grid"), std::string::npos) << algorithm.name << ": " << e.what();
        continue;
      }
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      // Generous: the grid takes milliseconds; a hang or O(F^2) on 3,000 faces takes far longer.
      EXPECT_LT(seconds, 20.0) << algorithm.name << " on " << name;
      if (seconds > 0.2) std::printf("%-14s %-22s %.3f s\n", name.c_str(), algorithm.name.c_str(), seconds);
      std::vector<std::uint32_t> order = ordering.face_order;
      std::sort(order.begin(), order.end());
      std::vector<std::uint32_t> all(mesh.face_count());
      std::iota(all.begin(), all.end(), 0u);
      EXPECT_EQ(order, all) << algorithm.name << " on " << name;
    }
  }
}

}  // namespace
}  // namespace rastrace

// The representations on the QEM builder's collapse sequences of real meshes: at sampled LoDs
// every method draws the builder's reference triangles (triangles_at_lod), and sliding window's
// relaxed order keeps the builder's last mesh with fewer levels.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "lod/progressive_mesh.h"
#include "lod/vipm_measure_methods.h"
#include "representation_checks.h"
#include "scenes/mesh_io.h"
#include "support/test_data.h"

namespace rastrace {
namespace {

std::vector<testing::Triple> builder_reference(const ProgressiveMesh& pm, std::size_t n,
                                               const std::vector<std::uint32_t>* to_original = nullptr) {
  std::vector<testing::Triple> out;
  for (auto t : triangles_at_lod(pm, n)) {
    if (to_original)
      for (std::uint32_t& v : t) v = (*to_original)[v];
    out.push_back(testing::canonical(t[0], t[1], t[2]));
  }
  std::sort(out.begin(), out.end());
  return out;
}

void expect_methods_match_builder(const std::string& file, std::uint32_t samples) {
  const Mesh mesh = load_mesh(testing::data_file(file));
  const ProgressiveMesh pm = build_progressive_mesh(mesh);
  const VipmMethods methods = build_vipm_methods(pm, reordered_mesh(mesh, pm));
  const auto last = static_cast<std::uint32_t>(pm.collapses.size());
  const ProgressiveMesh& relaxed = methods.sliding_window_order.pm;
  std::printf("%s: %u collapses, sliding-window levels %u in QEM order, %u relaxed (10%%)\n", file.c_str(), last,
              methods.sliding_window_strict_levels, methods.sliding_window_order.levels);
  EXPECT_LT(methods.sliding_window_order.levels, methods.sliding_window_strict_levels);
  EXPECT_EQ(builder_reference(relaxed, last, &relaxed.vertex_order), builder_reference(pm, last, &pm.vertex_order));
  std::vector<std::uint32_t> lods;
  for (std::uint32_t i = 0; i < samples; ++i)
    lods.push_back(static_cast<std::uint32_t>(std::uint64_t(last) * i / (samples - 1)));
  for (std::uint32_t n : lods) {
    const std::vector<testing::Triple> reference = builder_reference(pm, n);
    const std::vector<testing::Triple> relaxed_reference = builder_reference(relaxed, n);
    for (const auto& r : methods.representations) {
      r->set_lod(n);
      ASSERT_EQ(testing::drawn_triangles(*r), r->method() == "sliding-window" ? relaxed_reference : reference)
          << file << " " << r->method() << " at LoD " << n;
    }
  }
}

TEST(VipmBuilderSequences, FandiskDrawsTheBuildersTrianglesInEveryMethod) {
  expect_methods_match_builder("meshes/fandisk.off", 25);
}

TEST(VipmBuilderSequences, Bunny00DrawsTheBuildersTrianglesInEveryMethod) {
  expect_methods_match_builder("meshes/bunny00.off", 9);
}

}  // namespace
}  // namespace rastrace

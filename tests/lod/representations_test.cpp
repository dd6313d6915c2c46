// Every representation draws, at every LoD, the same non-degenerate triangles as vanilla VIPM on
// the same collapse sequence, whatever order the LoDs are visited in, and collapsing all the way
// down and splitting back restores the index lists bit for bit.
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "collapse_sequences.h"
#include "lod/mixed_mode.h"
#include "lod/skip_strips.h"
#include "lod/sliding_window.h"
#include "lod/vanilla.h"
#include "representation_checks.h"
#include "scenes/mesh_io.h"
#include "scenes/procedural.h"
#include "support/test_data.h"

namespace rastrace {
namespace {

using testing::drawn_triangles;
using testing::reference_triangles;

std::vector<std::unique_ptr<VipmRepresentation>> all_methods(const ProgressiveMesh& pm, const Mesh& vertices) {
  std::vector<std::unique_ptr<VipmRepresentation>> out;
  out.push_back(build_vanilla(pm));
  LevelParams strips;
  LevelParams lists;
  lists.primitive = PrimitiveType::TriangleList;
  lists.algorithm = "tipsy";
  out.push_back(build_skip_strips(pm, vertices, strips));
  out.push_back(build_skip_strips(pm, vertices, lists));
  out.push_back(build_mixed_mode(pm, vertices, strips));
  out.push_back(build_mixed_mode(pm, vertices, lists));
  out.push_back(build_sliding_window(pm, vertices));
  return out;
}

// Visits every `stride`-th LoD down, then back up, then a few jumps; each drawn set must match.
void expect_same_triangles(const ProgressiveMesh& pm, const Mesh& vertices, std::uint32_t stride) {
  const auto last = static_cast<std::uint32_t>(pm.collapses.size());
  std::vector<std::uint32_t> visits;
  for (std::uint32_t n = 0; n <= last; n += stride) visits.push_back(n);
  visits.push_back(last);
  for (std::uint32_t n = last + 1; n-- > 0;)
    if (n % stride == 0) visits.push_back(n);
  for (std::uint32_t n : {last / 2, 1u, last, last / 3, 0u, last - 1, 2 * last / 3}) visits.push_back(n);
  std::vector<std::vector<testing::Triple>> reference(last + 1);
  for (auto& r : all_methods(pm, vertices)) {
    for (std::uint32_t n : visits) {
      if (reference[n].empty()) reference[n] = reference_triangles(pm, n);
      r->set_lod(n);
      ASSERT_EQ(r->lod(), n);
      ASSERT_EQ(drawn_triangles(*r), reference[n]) << r->method() << " at LoD " << n;
    }
  }
}

TEST(VipmRepresentations, GridDrawsTheSameTrianglesAsVanillaAtEveryLod) {
  const Mesh grid = make_grid(16, 16);
  const testing::TestPm t = testing::test_progressive_mesh(grid, 400);
  ASSERT_GT(t.pm.collapses.size(), 200u);
  expect_same_triangles(t.pm, t.vertices, 1);
}

TEST(VipmRepresentations, TriceratopsDrawsTheSameTrianglesAsVanillaAtSampledLods) {
  const Mesh mesh = load_mesh(testing::data_file("meshes/triceratops.off"));
  const testing::TestPm t = testing::test_progressive_mesh(mesh, 2400);
  ASSERT_GT(t.pm.collapses.size(), 2000u);
  expect_same_triangles(t.pm, t.vertices, 97);
}

TEST(VipmRepresentations, CollapsingDownAndSplittingBackRestoresTheListsBitForBit) {
  const Mesh grid = make_grid(16, 16);
  const testing::TestPm t = testing::test_progressive_mesh(grid, 400);
  const auto last = static_cast<std::uint32_t>(t.pm.collapses.size());
  std::vector<std::uint32_t> original;
  for (const auto& tri : t.pm.triangles) original.insert(original.end(), tri.begin(), tri.end());
  auto vanilla = build_vanilla(t.pm);
  for (std::uint32_t n = 1; n <= last; ++n) vanilla->set_lod(n);
  for (std::uint32_t n = last; n-- > 0;) vanilla->set_lod(n);
  EXPECT_EQ(vanilla->instance_indices(), original);

  LevelParams lists;
  lists.primitive = PrimitiveType::TriangleList;
  lists.algorithm = "tipsy";
  for (auto& r : {build_skip_strips(t.pm, t.vertices, {}), build_skip_strips(t.pm, t.vertices, lists),
                  build_mixed_mode(t.pm, t.vertices, {}), build_mixed_mode(t.pm, t.vertices, lists)}) {
    ASSERT_GT(r->levels(), 2u) << r->method();
    for (std::uint32_t n = 1; n <= last; ++n) r->set_lod(n);
    for (std::uint32_t n = last; n-- > 0;) r->set_lod(n);
    EXPECT_EQ(r->instance_indices(), r->level_data().front().dynamic_start) << r->method();
    // Every level: entered from below through its collapsed copy, split back to its first LoD.
    for (std::uint32_t l = 0; l < r->levels(); ++l) {
      const EditedLevel& level = r->level_data()[l];
      if (level.collapses < 3) continue;
      r->set_lod(last);
      r->set_lod(level.first_lod + level.collapses - 1);
      EXPECT_EQ(r->level(), l);
      r->set_lod(level.first_lod);
      EXPECT_EQ(r->instance_indices(), level.dynamic_start) << r->method() << " level " << l;
    }
  }
}

TEST(VipmRepresentations, VanillaRecordsHaveForsythsLayoutBelow65536Vertices) {
  const Mesh grid = make_grid(16, 16);
  const testing::TestPm t = testing::test_progressive_mesh(grid, 100);
  auto vanilla = build_vanilla(t.pm);
  EXPECT_EQ(vanilla->index_bytes(), 2u);
  EXPECT_EQ(vanilla->layout(), "kept 16-bit, counts 8-bit, offsets 16-bit, 6-byte header");
  // 6-byte header + 2 bytes per changed index per record, and a 6-byte sentinel.
  std::uint64_t expected = 6;
  for (const CollapseRecord& c : t.pm.collapses) expected += 6 + 2 * c.changed_corners.size();
  EXPECT_EQ(vanilla->memory().record_bytes, expected);
  EXPECT_EQ(vanilla->memory().vertex_bytes, 289u * 32u);
  EXPECT_EQ(vanilla->memory().index_list_bytes, 512u * 3u * 2u);
  EXPECT_EQ(vanilla->memory().instance_bytes, 512u * 3u * 2u + EditedIndexLists::kInstanceStateBytes);
}

}  // namespace
}  // namespace rastrace

namespace rastrace {
namespace {

TEST(VipmRepresentations, From65536VerticesIndicesAndRecordsAre32Bit) {
  const testing::TestPm t = testing::test_progressive_mesh(make_grid(256, 256), 40);
  ASSERT_EQ(t.pm.vertex_order.size(), 257u * 257u);
  auto vanilla = build_vanilla(t.pm);
  EXPECT_EQ(vanilla->index_bytes(), 4u);
  EXPECT_EQ(vanilla->layout(), "kept 32-bit, counts 8-bit, offsets 32-bit, 8-byte header");
  std::uint64_t expected = 8;
  for (const CollapseRecord& c : t.pm.collapses) expected += 8 + 4 * c.changed_corners.size();
  EXPECT_EQ(vanilla->memory().record_bytes, expected);
  EXPECT_EQ(vanilla->memory().index_list_bytes, 2u * 256u * 256u * 3u * 4u);
  auto window = build_sliding_window(t.pm, t.vertices);
  EXPECT_EQ(window->record_bytes(), 12u);  // 131,072 triangles do not fit Forsyth's 16-bit count
  for (std::uint32_t n : {0u, 17u, 40u}) {
    vanilla->set_lod(n);
    window->set_lod(n);
    EXPECT_EQ(drawn_triangles(*window), drawn_triangles(*vanilla)) << n;
  }
}

}  // namespace
}  // namespace rastrace

#include <algorithm>
#include <numeric>

#include <gtest/gtest.h>

#include "reorder/texgroup.h"
#include "scenes/procedural.h"

namespace rastrace {
namespace {

Mesh four_colour_grid() {
  Mesh grid = make_grid(16, 16);
  Material material;
  material.name = "four-colour";
  material.texture_source.kind = TextureSource::Kind::FourColour;
  grid.materials = {material};
  return grid;
}

// Two grids side by side, one mesh: two UV charts of one texture.
Mesh two_part_mesh() {
  Mesh a = make_grid(4, 4), b = make_grid(4, 4);
  const auto offset = static_cast<std::uint32_t>(a.positions.size());
  for (auto p : b.positions) a.positions.push_back(p + glm::vec3(2.0f, 0.0f, 0.0f));
  a.uvs.insert(a.uvs.end(), b.uvs.begin(), b.uvs.end());
  a.normals.insert(a.normals.end(), b.normals.begin(), b.normals.end());
  // Interleave the parts' faces so that file order alternates between charts.
  std::vector<std::uint32_t> interleaved;
  for (std::size_t f = 0; f < b.face_count(); ++f) {
    interleaved.insert(interleaved.end(), a.indices.begin() + 3 * f, a.indices.begin() + 3 * f + 3);
    for (int i = 0; i < 3; ++i) interleaved.push_back(b.indices[3 * f + i] + offset);
  }
  a.indices = interleaved;
  a.grid.reset();
  Material material;
  material.texture_source.kind = TextureSource::Kind::Checker;
  a.materials = {material};
  return a;
}

TEST(TexGroup, FourColourGridSplitsIntoFourQuadrantsOf128Faces) {
  const TextureGroups groups = find_texture_groups(four_colour_grid(), "auto");
  ASSERT_EQ(groups.labels.size(), 4u);
  std::vector<int> sizes(4, 0);
  for (const std::uint32_t g : groups.group_of_face) ++sizes[g];
  EXPECT_EQ(sizes, (std::vector<int>{128, 128, 128, 128}));
}

TEST(TexGroup, GroupsChainThroughNeighbouringQuadrants) {
  // Quadrant 0 touches 1 and 2 along 9 vertices each (tie: lower id), then 1 touches 3.
  const TextureGroups groups = find_texture_groups(four_colour_grid(), "quadrant");
  EXPECT_EQ(groups.order, (std::vector<std::uint32_t>{0, 1, 3, 2}));
}

TEST(TexGroup, SeparatePartsAreSeparateCharts) {
  const TextureGroups groups = find_texture_groups(two_part_mesh(), "chart");
  ASSERT_EQ(groups.labels.size(), 2u);
  for (std::uint32_t f = 0; f < groups.group_of_face.size(); ++f) EXPECT_EQ(groups.group_of_face[f], f % 2);
  EXPECT_EQ(find_texture_groups(two_part_mesh(), "texture").labels.size(), 1u);
}

TEST(TexGroup, OrderIsAPermutationWithEachGroupContiguous) {
  for (const char* base : {"original", "strip", "tipsy"}) {
    for (const Mesh& mesh : {four_colour_grid(), two_part_mesh()}) {
      ReorderParams params;
      params.texgroup_base = base;
      const Ordering ordering = reorder_texgroup(mesh, params);
      std::vector<std::uint32_t> sorted = ordering.face_order;
      std::sort(sorted.begin(), sorted.end());
      std::vector<std::uint32_t> all(mesh.face_count());
      std::iota(all.begin(), all.end(), 0u);
      EXPECT_EQ(sorted, all) << base;

      const TextureGroups groups = find_texture_groups(mesh, params.texgroup_regions);
      std::size_t changes = 0;
      for (std::size_t i = 1; i < ordering.face_order.size(); ++i)
        changes += groups.group_of_face[ordering.face_order[i]] != groups.group_of_face[ordering.face_order[i - 1]];
      EXPECT_EQ(changes, groups.labels.size() - 1) << base;

      // The index stream draws exactly the faces, with their winding (rotations allowed).
      std::vector<std::array<std::uint32_t, 3>> drawn, expected;
      const auto canonical = [](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        std::array<std::uint32_t, 3> t{a, b, c};
        while (t[0] != std::min({a, b, c})) std::rotate(t.begin(), t.begin() + 1, t.end());
        return t;
      };
      for_each_triangle(ordering.indices, ordering.type, ordering.restart_index,
                        [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
                          if (a != b && b != c && a != c) drawn.push_back(canonical(a, b, c));
                        });
      for (std::size_t f = 0; f < mesh.face_count(); ++f)
        expected.push_back(canonical(mesh.indices[3 * f], mesh.indices[3 * f + 1], mesh.indices[3 * f + 2]));
      std::sort(drawn.begin(), drawn.end());
      std::sort(expected.begin(), expected.end());
      EXPECT_EQ(drawn, expected) << base;
    }
  }
}

TEST(TexGroup, UnknownRegionModeIsAnError) {
  EXPECT_THROW(find_texture_groups(four_colour_grid(), "octant"), std::exception);
}

}  // namespace
}  // namespace rastrace

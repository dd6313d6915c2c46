// The per-face miss colours of `rastrace vcache --miss-image`: the counts add up to the stream's
// misses, and the rendered image is red where a random order misses and mostly green and yellow
// under K-Cache-Reorder.
#include "experiments/miss_image.h"

#include <array>
#include <numeric>

#include <gtest/gtest.h>

#include "core/error.h"
#include "reorder/kcache.h"
#include "scenes/procedural.h"
#include "scenes/texture_io.h"
#include "tests/support/temp_dir.h"
#include "tests/support/test_meshes.h"

namespace rastrace {
namespace {

std::uint64_t total(const std::vector<std::uint8_t>& counts) {
  return std::accumulate(counts.begin(), counts.end(), std::uint64_t{0});
}
std::uint64_t misses(const Ordering& o, unsigned cache) {
  return simulate_vertex_stream(o.indices, o.type, VertexCachePolicy::Fifo, cache, o.restart_index).misses;
}

TEST(MissImage, OneQuadDrawnAsAListChargesThreeThenOne) {
  const Mesh grid = make_grid(1, 1);
  const Ordering order = list_ordering(grid, {1, 0});
  const std::vector<std::uint8_t> counts = face_miss_counts(grid, order, VertexCachePolicy::Fifo, 16);
  EXPECT_EQ(counts, (std::vector<std::uint8_t>{1, 3}));
}

TEST(MissImage, FaceCountsAddUpToTheStreamsMissesForListsAndStrips) {
  const Mesh& mesh = testing::cached_mesh("fandisk.off");
  ReorderParams params;
  for (const char* name : {"tipsy", "random", "greedy", "strip"}) {
    const Ordering ordering = find_reorder_algorithm(name).run(mesh, params);
    const std::vector<std::uint8_t> counts = face_miss_counts(mesh, ordering, VertexCachePolicy::Fifo, 16);
    ASSERT_EQ(counts.size(), mesh.face_count());
    EXPECT_EQ(total(counts), misses(ordering, 16)) << name;
  }
  // Greedy's strips on fandisk: 8,107 misses at FIFO 16 (ACMR 0.626).
  const Ordering greedy = reorder_greedy(mesh, params);
  EXPECT_EQ(total(face_miss_counts(mesh, greedy, VertexCachePolicy::Fifo, 16)), 8107u);
}

TEST(MissImage, ATriangleTheMeshDoesNotHaveIsAnError) {
  Mesh mesh;
  mesh.name = "one-triangle";
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  mesh.indices = {0, 1, 2};
  Ordering ordering = list_ordering(mesh, {0});
  EXPECT_EQ(face_miss_counts(mesh, ordering, VertexCachePolicy::Fifo, 4), (std::vector<std::uint8_t>{3}));
  ordering.indices = {1, 2, 3};
  EXPECT_THROW(face_miss_counts(mesh, ordering, VertexCachePolicy::Fifo, 4), InputError);
  ordering.indices = {0, 1, 2, 2, 0, 1};  // the one face drawn twice
  EXPECT_THROW(face_miss_counts(mesh, ordering, VertexCachePolicy::Fifo, 4), InputError);
}

// Share of the drawn pixels whose colour is closest to each of the four miss colours (the
// lighting scales a colour, so they are told apart by their channel ratios).
std::array<double, 4> colour_shares(const std::string& path) {
  const Image image = load_image(path);
  std::array<double, 4> shares{};
  double drawn = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.texel(x, y);
      if (p[0] == 255 && p[1] == 255 && p[2] == 255) continue;  // background
      const double r = p[0], g = p[1], b = p[2];
      const double sum = r + g + b;
      if (sum < 1) continue;
      int best = 0;
      double best_distance = 1e9;
      for (int c = 0; c < 4; ++c) {
        const double cs = kMissColours[c][0] + kMissColours[c][1] + kMissColours[c][2];
        const double dr = r / sum - kMissColours[c][0] / cs, dg = g / sum - kMissColours[c][1] / cs,
                     db = b / sum - kMissColours[c][2] / cs;
        const double distance = dr * dr + dg * dg + db * db;
        if (distance < best_distance) {
          best_distance = distance;
          best = c;
        }
      }
      shares[std::size_t(best)] += 1;
      drawn += 1;
    }
  for (double& share : shares) share /= drawn;
  return shares;
}

TEST(MissImage, RandomOrderIsRedAndKcacheIsGreenAndYellow) {
  const Mesh& mesh = testing::cached_mesh("fandisk.off");
  testing::TempDir dir;
  ReorderParams params;
  const std::string random_png = dir.file("random.png"), kcache_png = dir.file("kcache.png");
  MissImageSpec spec;
  spec.width = spec.height = 256;
  write_miss_image(mesh, face_miss_counts(mesh, reorder_random(mesh, params), VertexCachePolicy::Fifo, 16), random_png,
                   spec);
  write_miss_image(mesh, face_miss_counts(mesh, reorder_kcache(mesh, params), VertexCachePolicy::Fifo, 16), kcache_png,
                   spec);
  const std::array<double, 4> random = colour_shares(random_png), kcache = colour_shares(kcache_png);
  EXPECT_EQ(load_image(random_png).width, 256);
  EXPECT_GT(random[3], 0.9);
  EXPECT_LT(kcache[3], 0.1);
  EXPECT_GT(kcache[0] + kcache[1], 0.8);
}

TEST(MissImage, CountsOfTheWrongLengthAreAnError) {
  const Mesh grid = make_grid(1, 1);
  testing::TempDir dir;
  EXPECT_THROW(write_miss_image(grid, {0}, dir.file("x.png")), InputError);
}

}  // namespace
}  // namespace rastrace

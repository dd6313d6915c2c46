// `rastrace reproduce --paper hakura` (experiments/reproduce/reproduce_hakura.cpp): every row of
// the grid for each of the three scenes, the three Cs adding up to the 2-way rate, and the
// measured figures as they stand (a change to the renderer or the caches shows here).
#include <gtest/gtest.h>

#include "experiments/reproduce/reproduce.h"

namespace rastrace {
namespace {

double value(const TableCell& cell) {
  return std::holds_alternative<double>(cell.value) ? std::get<double>(cell.value)
                                                    : double(std::get<std::int64_t>(cell.value));
}

TEST(ReproduceHakura, TheGridForThreeScenesWithTheThreeCsAddingUp) {
  const std::vector<ReproducedFigure> rows = reproduce_hakura();
  ASSERT_EQ(rows.size(), 30u);
  for (std::size_t scene = 0; scene < 3; ++scene) {
    const ReproducedFigure* r = &rows[scene * 10];
    for (int i = 0; i < 10; ++i) ASSERT_FALSE(std::holds_alternative<std::monostate>(r[i].ours.value)) << r[i].figure;
    // compulsory + capacity + conflict = the 2-way 32 KB rate (blocked + tiled).
    EXPECT_NEAR(value(r[0].ours) + value(r[1].ours) + value(r[2].ours), value(r[7].ours), 1e-9) << r[0].our_mesh;
    // Blocking never hurts at scanline on the bunny and the spider.
    if (scene < 2) {
      EXPECT_LT(value(r[5].ours), value(r[4].ours)) << r[0].our_mesh;
    }
  }
  EXPECT_EQ(rows[8].figure.rfind("working-set knee", 0), 0u);
  EXPECT_EQ(value(rows[8].ours), 256.0);   // the bunny: no knee below 256 KB
  EXPECT_EQ(value(rows[18].ours), 64.0);   // the spider
  EXPECT_EQ(value(rows[28].ours), 64.0);   // the grid
  EXPECT_NEAR(value(rows[19].ours), 8.041, 5e-4);  // the spider's bandwidth reduction, inside 3-15x
  EXPECT_NEAR(value(rows[29].ours), 5.019, 5e-4);  // the grid's
  EXPECT_NEAR(value(rows[9].ours), 0.410, 5e-4);   // the bunny's: below 1, outside their range
}

// The working-set knee per storage format and anisotropy (EXT's probes) on the same scenes at
// 512x384, as measured: compression shrinks the knee, anisotropy grows it.
TEST(ReproduceHakuraCompressed, KneesPerFormatAndAnisotropyAsMeasured) {
  const std::vector<ReproducedFigure> rows = reproduce_hakura_compressed();
  ASSERT_EQ(rows.size(), 27u);  // 3 scenes x 3 anisotropies x 3 formats
  const auto knee = [&](std::size_t scene, std::size_t aniso, std::size_t format) {
    return value(rows[scene * 9 + aniso * 3 + format].ours);
  };
  EXPECT_EQ(knee(0, 0, 0), 256.0);  // bunny, RGBA8, isotropic
  EXPECT_EQ(knee(0, 0, 1), 64.0);   // bunny, BC1
  EXPECT_EQ(knee(1, 0, 0), 32.0);   // spider, RGBA8, isotropic
  EXPECT_EQ(knee(1, 1, 0), 128.0);  // spider, RGBA8, 4x
  EXPECT_EQ(knee(2, 0, 0), 64.0);   // grid, RGBA8
  EXPECT_EQ(knee(2, 0, 1), 8.0);    // grid, BC1: within their 16 KB
  EXPECT_NE(rows[2 * 9 + 1].note.find("within their 16 KB bound"), std::string::npos);
}

}  // namespace
}  // namespace rastrace

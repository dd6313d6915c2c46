// The compressed-texture study (experiments/compressed_study.h): one render per anisotropy and
// ordering swept as every format, the same texel reads for every format, fewer bytes for BC1 than
// RGBA8, more reads with anisotropy, and the knee as reproduce_hakura defines it.
#include <gtest/gtest.h>

#include "experiments/compressed_study.h"

namespace rastrace {
namespace {

CompressedStudy small_study() {
  CompressedStudy study;
  study.scenes = {"builtin:grid"};
  study.orders = {"original"};
  study.anisotropy = {1, 4};
  study.formats = {"rgba8", "bc1"};
  study.sizes = {1024, 16384};
  study.frame_size = "128x96";
  return study;
}

const CompressedStudyRow& row(const std::vector<CompressedStudyRow>& rows, unsigned aniso, const std::string& format,
                              std::uint64_t size) {
  for (const CompressedStudyRow& r : rows)
    if (r.anisotropy == aniso && r.format == format && r.size_bytes == size) return r;
  throw std::runtime_error("no row");
}

TEST(CompressedStudy, EveryFormatReplaysTheSameReadsAndBc1FetchesFewerBytes) {
  const std::vector<CompressedStudyRow> rows = run_compressed_study(small_study());
  ASSERT_EQ(rows.size(), 8u);
  for (const unsigned aniso : {1u, 4u})
    for (const std::uint64_t size : {1024u, 16384u}) {
      const CompressedStudyRow& rgba = row(rows, aniso, "rgba8", size);
      const CompressedStudyRow& bc1 = row(rows, aniso, "bc1", size);
      EXPECT_EQ(rgba.accesses, bc1.accesses);
      EXPECT_LT(bc1.misses * 4, rgba.misses) << aniso << " " << size;
      EXPECT_NEAR(bc1.bytes_per_fragment, double(bc1.misses) * 64.0 / double(bc1.fragments), 1e-9);
    }
  // Four probes along the grid's receding axis read more texels than one trilinear sample.
  EXPECT_GT(row(rows, 4, "rgba8", 1024).accesses, row(rows, 1, "rgba8", 1024).accesses * 5 / 4);
  const Table table = compressed_study_table(small_study(), rows);
  EXPECT_EQ(table.kind, "compressed_texture_study");
  EXPECT_EQ(table.rows.size(), 8u);
}

TEST(CompressedStudy, TheKneeIsTheSmallestSizeWithinTenPercentOfTheLargest) {
  std::vector<CompressedStudyRow> rows;
  const double ratios[] = {0.5, 0.2, 0.105, 0.1};
  std::uint64_t size = 1024;
  for (const double r : ratios) {
    CompressedStudyRow x;
    x.scene = "s";
    x.order = "o";
    x.anisotropy = 1;
    x.format = "bc1";
    x.size_bytes = size;
    x.miss_ratio = r;
    rows.push_back(x);
    size *= 2;
  }
  EXPECT_EQ(working_set_knee(rows, "s", "o", 1, "bc1"), 4096u);
  EXPECT_EQ(working_set_knee(rows, "s", "o", 4, "bc1"), 0u);
}

}  // namespace
}  // namespace rastrace

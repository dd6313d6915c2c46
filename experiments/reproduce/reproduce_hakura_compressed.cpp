// Hakura and Gupta, "The design and analysis of a cache architecture for texture mapping", ISCA
// 1997: their working-set claim (at most 16 KB in every scene, uncompressed RGBA textures,
// isotropic trilinear filtering; docs/REFERENCE.md) checked where it was made and on today's texture
// traffic: the knee of the miss-ratio curve per scene for RGBA8, BC1 and BC7 storage at 1x, 4x and
// 16x anisotropy (experiments/compressed_study.h), in the file's triangle order.
#include "experiments/compressed_study.h"
#include "experiments/reproduce/reproduce.h"

namespace rastrace {

std::vector<ReproducedFigure> reproduce_hakura_compressed() {
  CompressedStudy study;
  study.orders = {"original"};
  const std::vector<CompressedStudyRow> rows = run_compressed_study(study);
  std::vector<ReproducedFigure> out;
  for (const std::string& scene : study.scenes)
    for (const unsigned aniso : study.anisotropy)
      for (const std::string& format : study.formats) {
        const std::uint64_t knee = working_set_knee(rows, scene, "original", aniso, format) / 1024;
        const bool theirs = format == "rgba8" && aniso == 1;
        std::string note = theirs ? "their setting (uncompressed, isotropic): " : "beyond their setting: ";
        note += knee <= 16 ? "within their 16 KB bound" : "beyond their 16 KB bound";
        out.push_back({"Hakura and Gupta 1997 (compressed, anisotropic)",
                       "working-set knee, KB: " + format + ", aniso " + std::to_string(aniso) +
                           " (64 B lines, 4-way LRU, block4, within 10% of the 256 KB miss ratio)",
                       "their scenes (uncompressed, isotropic)", scene + " at " + study.frame_size,
                       std::int64_t{16}, static_cast<std::int64_t>(knee), note});
      }
  return out;
}

}  // namespace rastrace

// Texture traffic of today's GPUs: how much block compression and anisotropic filtering change the
// texture cache's misses and bytes, beside what the triangle ordering changes. Each scene is
// rendered once per (anisotropy, ordering), and its one texel trace is swept as RGBA8, BC1 and BC7
// (a texel trace records logical texels, so the format is a replay parameter: the same trace,
// three memory images). Rows give the miss ratio and the texture bytes fetched per fragment at
// each cache size.
//
// Hakura and Gupta, "The design and analysis of a cache architecture for texture mapping", ISCA
// 1997, found the working set of uncompressed, isotropically filtered textures to be at most 16 KB
// in every scene they drew. working_set_knee() measures the same knee (the smallest cache within
// 10% of the largest cache's miss ratio, as `reproduce --paper hakura` does) per format and
// anisotropy, so the claim can be checked where it was made and beyond it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/table.h"

namespace rastrace {

struct CompressedStudy {
  std::vector<std::string> scenes{"builtin:bunny", "builtin:spider", "builtin:grid"};
  std::vector<std::string> orders{"original", "tipsy", "morton"};
  std::vector<unsigned> anisotropy{1, 4, 16};
  std::vector<std::string> formats{"rgba8", "bc1", "bc7"};
  // 1 KiB to 64 KiB, and 128 and 256 KiB so the knee is measured as reproduce_hakura measures it.
  std::vector<std::uint64_t> sizes{1024, 2048, 4096, 8192, 16384, 32768, 65536, 131072, 262144};
  std::string frame_size = "512x384";  // every scene at this size, so scenes compare per fragment
  std::string raster = "tiled8";       // Hakura and Gupta's best traversal
  std::uint32_t line_bytes = 64;
  std::uint32_t assoc = 4;  // LRU
  std::string layout = "block4";  // 4x4 units: texels for RGBA8, blocks for BC1/BC7
  // The hardware rule (N trilinear probes along the major axis, raster/anisotropic_probes.h), not
  // llvmpipe's ellipse, whose maximum does not bound the footprint.
  std::string aniso_rule = "probes";
};

struct CompressedStudyRow {
  std::string scene;
  std::string order;
  unsigned anisotropy = 1;
  std::string format;
  std::uint64_t size_bytes = 0;
  std::uint64_t fragments = 0;
  std::uint64_t accesses = 0;  // texel reads
  std::uint64_t misses = 0;
  double miss_ratio = 0;
  double bytes_per_fragment = 0;  // bytes fetched from memory per fragment rasterized (covered pixel
                                  // of a triangle, before the depth test)
};

// Renders and sweeps every combination. Throws InputError for a scene that fails to load or has no
// texture, an unknown ordering or format.
std::vector<CompressedStudyRow> run_compressed_study(const CompressedStudy& study);

// Kind "compressed_texture_study": scene, order, aniso, format, size_bytes, fragments, accesses,
// misses, miss_ratio, bytes_per_fragment; the parameters state the cache and the frame.
Table compressed_study_table(const CompressedStudy& study, const std::vector<CompressedStudyRow>& rows);

// The smallest size whose miss ratio is within 10% of the largest size's, for one scene, order,
// anisotropy and format (0 when the rows hold none).
std::uint64_t working_set_knee(const std::vector<CompressedStudyRow>& rows, const std::string& scene,
                               const std::string& order, unsigned anisotropy, const std::string& format);

// Bytes per fragment against cache size, a line per format and anisotropy, for one scene and
// order (PNG or SVG by extension, through gnuplot).
void write_compressed_study_plot(const std::string& path, const std::vector<CompressedStudyRow>& rows,
                                 const std::string& scene, const std::string& order);

}  // namespace rastrace

// GL-style mip chains (glGenerateMipmap semantics): each level max(1, floor(w/2)) x
// max(1, floor(h/2)), down to 1x1, box-filtered. The box filter is the exact area average of the
// source rectangle a destination texel covers, which is the 2x2 average for even sizes and, for an
// odd size 2n+1 -> n, splits the straddling texel between its two neighbours by overlap.
#include <array>
#include <string>

#include "core/error.h"
#include "scenes/texture_io.h"

namespace rastrace {

namespace {

// Source texels and their overlap weights (in units of 1/destination size) for one destination
// texel along one axis. A destination texel covers at most 3 source texels' width, so 4 entries.
struct Footprint {
  std::array<int, 4> index{};
  std::array<std::uint64_t, 4> weight{};
  int count = 0;
};

std::vector<Footprint> footprints(int source, int destination) {
  std::vector<Footprint> result(static_cast<std::size_t>(destination));
  const auto s = static_cast<std::uint64_t>(source), d = static_cast<std::uint64_t>(destination);
  for (std::uint64_t x = 0; x < d; ++x) {
    // Destination texel x covers [x*s, (x+1)*s) in units where a source texel is d wide.
    const std::uint64_t begin = x * s, end = (x + 1) * s;
    Footprint& f = result[x];
    for (std::uint64_t i = begin / d; i * d < end && i < s; ++i) {
      const std::uint64_t lo = std::max(begin, i * d), hi = std::min(end, (i + 1) * d);
      f.index[static_cast<std::size_t>(f.count)] = static_cast<int>(i);
      f.weight[static_cast<std::size_t>(f.count)] = hi - lo;
      ++f.count;
    }
  }
  return result;
}

Image downsample(const Image& source) {
  Image next;
  next.width = std::max(1, source.width / 2);
  next.height = std::max(1, source.height / 2);
  next.rgba.resize(static_cast<std::size_t>(next.width) * static_cast<std::size_t>(next.height) * 4);
  const std::vector<Footprint> fx = footprints(source.width, next.width);
  const std::vector<Footprint> fy = footprints(source.height, next.height);
  const std::uint64_t total = static_cast<std::uint64_t>(source.width) * static_cast<std::uint64_t>(source.height);
  std::uint8_t* out = next.rgba.data();
  for (int y = 0; y < next.height; ++y) {
    const Footprint& row = fy[static_cast<std::size_t>(y)];
    for (int x = 0; x < next.width; ++x) {
      const Footprint& column = fx[static_cast<std::size_t>(x)];
      std::uint64_t sum[4] = {0, 0, 0, 0};
      for (int j = 0; j < row.count; ++j)
        for (int i = 0; i < column.count; ++i) {
          const std::uint64_t w = row.weight[static_cast<std::size_t>(j)] * column.weight[static_cast<std::size_t>(i)];
          const std::uint8_t* texel =
              source.texel(column.index[static_cast<std::size_t>(i)], row.index[static_cast<std::size_t>(j)]);
          for (int c = 0; c < 4; ++c) sum[c] += w * texel[c];
        }
      for (int c = 0; c < 4; ++c) *out++ = static_cast<std::uint8_t>((sum[c] + total / 2) / total);
    }
  }
  return next;
}

}  // namespace

std::vector<Image> build_mip_chain(Image base) {
  if (base.width < 1 || base.height < 1 ||
      base.rgba.size() != static_cast<std::size_t>(base.width) * static_cast<std::size_t>(base.height) * 4)
    throw InputError("mip chain: image of " + std::to_string(base.width) + "x" + std::to_string(base.height) +
                     " with " + std::to_string(base.rgba.size()) +
                     " bytes: expected at least 1x1 and 4 bytes per texel");
  std::vector<Image> levels;
  levels.push_back(std::move(base));
  while (levels.back().width > 1 || levels.back().height > 1) levels.push_back(downsample(levels.back()));
  return levels;
}

}  // namespace rastrace

#include "raster/hilbert_order.h"

#include <algorithm>
#include <utility>

namespace rastrace {

std::uint64_t hilbert_index(std::uint32_t x, std::uint32_t y, unsigned bits) {
  // Walk the quadrants from the largest down; at each level rotate / reflect the remaining
  // coordinates into the sub-curve's frame.
  std::uint64_t d = 0;
  for (std::uint32_t s = bits ? (1u << (bits - 1)) : 0; s > 0; s >>= 1) {
    const std::uint32_t rx = (x & s) ? 1 : 0;
    const std::uint32_t ry = (y & s) ? 1 : 0;
    d += std::uint64_t{s} * s * ((3 * rx) ^ ry);
    if (ry == 0) {
      if (rx == 1) {
        x = s - 1 - (x & (s - 1));
        y = s - 1 - (y & (s - 1));
      }
      std::swap(x, y);
    }
    x &= s - 1;
    y &= s - 1;
  }
  return d;
}

unsigned hilbert_bits(std::uint32_t columns, std::uint32_t rows) {
  unsigned bits = 0;
  while ((std::uint64_t{1} << bits) < std::max(columns, rows)) ++bits;
  return bits;
}

void hilbert_tiles(std::uint32_t tx0, std::uint32_t ty0, std::uint32_t tx1, std::uint32_t ty1, unsigned bits,
                   std::vector<std::uint64_t>& out) {
  out.clear();
  std::vector<std::pair<std::uint64_t, std::uint64_t>> keyed;
  keyed.reserve(std::size_t{tx1 - tx0 + 1} * (ty1 - ty0 + 1));
  for (std::uint32_t ty = ty0; ty <= ty1; ++ty)
    for (std::uint32_t tx = tx0; tx <= tx1; ++tx)
      keyed.emplace_back(hilbert_index(tx, ty, bits), (std::uint64_t{ty} << 32) | tx);
  std::sort(keyed.begin(), keyed.end());
  out.reserve(keyed.size());
  for (const auto& k : keyed) out.push_back(k.second);
}

}  // namespace rastrace

#include "cache_sim/warp_fifo.h"

#include <algorithm>
#include <string>

#include "core/error.h"

namespace rastrace {

WarpFifo::WarpFifo(unsigned entries, unsigned warp, unsigned primgroup)
    : entries_(entries), warp_(warp), primgroup_(primgroup), clock_(entries + 1) {
  if (entries == 0 || entries > (1u << 20))
    throw InputError("vertex cache of " + std::to_string(entries) + " entries: expected 1..1048576");
  if (warp == 1 || warp == 2)
    throw InputError("warp=" + std::to_string(warp) + ": a warp must hold a triangle's 3 vertices (0 = no warp limit)");
}

void WarpFifo::rebase_clock() {
  // Shift every stamp down so the 32-bit clock never wraps; residency is unchanged, since only
  // differences to the clock within entries + 1 matter. Stamps too old to matter become 1.
  const std::uint32_t shift = clock_ - 2 * (entries_ + 1);
  for (std::uint32_t& stamp : stamps_)
    if (stamp != 0) stamp = stamp > shift ? stamp - shift : 1;
  clock_ -= shift;
}

void WarpFifo::primitive(const std::uint32_t* vertices, unsigned count) {
  if (clock_ > 0xF0000000u) [[unlikely]]
    rebase_clock();
  unsigned absent = 0;
  for (unsigned i = 0; i < count; ++i) {
    const std::uint32_t v = vertices[i];
    if (v >= stamps_.size()) stamps_.resize(std::max<std::size_t>(std::size_t{v} + 1, stamps_.size() * 2), 0);
    absent += !cached(v);
  }
  if ((primgroup_ && primgroup_offset_ == primgroup_) || (warp_ && warp_offset_ + absent > warp_)) {
    warps_ += warp_offset_ > 0;
    warp_offset_ = primgroup_offset_ = 0;
    clock_ += entries_ + 1;
  }
  for (unsigned i = 0; i < count; ++i) {
    const std::uint32_t v = vertices[i];
    if (!cached(v)) {
      stamps_[v] = clock_++;
      ++misses_;
      ++warp_offset_;
    }
  }
  ++primgroup_offset_;
}

void WarpFifo::flush() {
  warps_ += warp_offset_ > 0;
  warp_offset_ = primgroup_offset_ = 0;
  clock_ += entries_ + 1;
}

}  // namespace rastrace

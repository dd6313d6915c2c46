// Vertex transforms counted the way NVIDIA Mesh Tools' VertexCache (nvmesh, 2006) counts them: the
// simulator behind Castano's "Optimal Grid Rendering" tables (2009).
//
// That simulator is a true FIFO, but it does not count misses. Per triangle it counts the indices
// not in the cache before the triangle, a repeated index once per occurrence, and charges one
// transform for each entry that many insertions would evict; the vertices left in the cache are
// charged at the end. The two counts differ in two cases:
// - A triangle repeats a missing index while the cache is full: one transform too many. The
//   degenerate triangles (x, x, x + 1) that prefetch a grid column are such triangles. This is why
//   Castano prints 307 at FIFO 12 (ACMR 0.600), and 325 (ATVR 1.125) for the grid optimized for 8
//   and run on 16. A strict FIFO gives 306 and 323 for the same index streams.
// - A triangle's own cached vertex is evicted by an earlier index of the same triangle: its second
//   load is not charged, one transform too few. Small caches and poor orders do this.
// Use it to reproduce published tables; use simulate_vertex_stream for the true miss count.
#pragma once

#include <cstdint>
#include <span>

#include "traces/events.h"

namespace rastrace {

// Transforms charged for the stream on a FIFO of `entries` (>= 1; InputError otherwise).
// Strips are turned into the list of their drawn triangles first (degenerates dropped), as the
// nvmesh simulator only took lists (NvTriStrip's lists-only output). A list looks every vertex of
// every triangle up, where a strip looks each index up once, so a strip order can cost far more
// here than as a strip (Hoppe's local order of the 16x16 grid at FIFO 16: 432 against 299).
std::uint64_t eviction_charged_transforms(std::span<const std::uint32_t> indices, PrimitiveType type, unsigned entries,
                                          RestartIndex restart_index = kNoRestart);

}  // namespace rastrace

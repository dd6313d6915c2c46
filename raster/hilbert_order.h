// Hilbert-curve order of screen tiles, the traversal the texture-cache literature proposes for
// locality (consecutive tiles always share an edge, unlike row-major tiles at the end of a row).
// The curve is global to the screen: tile (tx, ty) has the index of the order-`bits` Hilbert curve
// over a 2^bits x 2^bits grid of tiles (bits large enough for the screen), so two triangles
// sharing tiles visit them in the same relative order.
#pragma once

#include <cstdint>
#include <vector>

namespace rastrace {

// Distance along the Hilbert curve of side 2^bits from (0, 0) to (x, y) (x, y < 2^bits); the curve
// starts at (0, 0) and ends at (2^bits - 1, 0).
std::uint64_t hilbert_index(std::uint32_t x, std::uint32_t y, unsigned bits);

// The smallest bits with 2^bits >= both tile counts.
unsigned hilbert_bits(std::uint32_t columns, std::uint32_t rows);

// Tiles [tx0, tx1] x [ty0, ty1] (inclusive) in Hilbert order, each packed as (ty << 32) | tx.
// `out` is reused (cleared first), so a caller that keeps it allocates only when it grows.
void hilbert_tiles(std::uint32_t tx0, std::uint32_t ty0, std::uint32_t tx1, std::uint32_t ty1, unsigned bits,
                   std::vector<std::uint64_t>& out);

}  // namespace rastrace

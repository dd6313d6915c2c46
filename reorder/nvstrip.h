// NvTriStrip: the stripifier of NVIDIA's public NvTriStrip library (2002-2004), the "NVTriStrip"
// baseline of Castano's "Optimal Grid Rendering" (2009) and of many vertex-cache papers.
#pragma once

#include "reorder/ordering.h"

namespace rastrace {

// The `nvstrip` algorithm: NvTriStrip's stripifier, cache-aware only through the length of its
// strips and the order of their pieces (our `strip` is the fewest-vertices stripifier instead).
//  1. Rounds of experiments until every face is in a strip. A round takes up to 10 start faces
//     (the first ever: the face with the most boundary edges; then faces found by jumping through
//     the face list in tenths) and, for each, its three edges in both directions: 60 experiments.
//     An experiment grows a strip forward and backward from its start (swapping where the next
//     face but one would be a dead end and the turn leads on; backward growth stops before a face
//     whose vertices are all in the strip), then the next strip from an unused face around the
//     start edge's second vertex, and so on: a sweep of parallel strips. The experiment with the
//     most faces per strip is kept; the others are undone.
//  2. Strips are cut into pieces of K - 6 faces (the library's CACHE_INEFFICIENCY; a remainder of
//     1-3 faces stays on the last piece), and the pieces ordered greedily against a simulated
//     FIFO of K - 6 entries: first the piece with the fewest neighbours per face, then always the
//     piece whose faces have the most cached vertices per face.
//  3. Pieces are sent as one strip stream with a restart between pieces (the library's restart
//     mode; stitching with degenerates sends the same vertices). Degenerate faces, which the
//     library drops, are drawn last, each on its own.
// Departures from the library, none of which changes which faces make a piece: ties between
// pieces go to the first in build order (the library also prefers, among equals, one whose winding
// suits a degenerate stitch); the swap triangles are not counted as faces when pieces are scored.
// Parameters: cache_size (K; the pieces are K - 6 faces, at least 1; above 1024 ordered as 1024).
// Deterministic. A strip stream (TriangleStrip with restart). About 0.1 s of CPU on bunny00
// (75,408 faces). FIFO ACMR ordered for and run on K = 12 / 16 / 20: 16x16 grid 0.838 / 0.750 /
// 0.777 (Castano's list count: 0.842 / 0.760 / 0.781, his NVTriStrip row 0.875 / 0.775 / 0.818),
// bunny00 0.855 / 0.771 / 0.741; about 0.69-0.86 on real meshes from K = 32 down to 12.
Ordering reorder_nvstrip(const Mesh& mesh, const ReorderParams& params);

}  // namespace rastrace

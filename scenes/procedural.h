// Meshes generated in code: the regular grids of Castano's article, spheres, planes.
#pragma once

#include "scenes/mesh.h"

namespace rastrace {

// A W x H quad grid in the unit square (z = 0), laid out as in Castano's article: vertex (x, y)
// has index (W+1)*y + x; quad (x, y) gives triangles (a, b, c) and (c, b, d) with a = (x, y),
// b = (x, y+1), c = (x+1, y), d = (x+1, y+1); quads in scanline order. UVs span [0, 1].
// With y up these triangles wind clockwise seen from +z: the article's layout, kept exactly.
Mesh make_grid(int width, int height);

}  // namespace rastrace

// Meshes generated in code: the regular grids of Castano's article, spheres, planes, and
// projected UVs for meshes that come without them.
#pragma once

#include "scenes/mesh.h"

namespace rastrace {

// A W x H quad grid in the unit square (z = 0), laid out as in Castano's article: vertex (x, y)
// has index (W+1)*y + x; quad (x, y) gives triangles (a, b, c) and (c, b, d) with a = (x, y),
// b = (x, y+1), c = (x+1, y), d = (x+1, y+1); quads in scanline order. UVs span [0, 1].
// With y up these triangles wind clockwise seen from +z: the article's layout, kept exactly.
Mesh make_grid(int width, int height);

// A unit sphere: an icosahedron (12 vertices, 20 faces) whose triangles are split into 4,
// `subdivisions` times, new vertices pushed to the sphere; vertices shared (an edge midpoint is
// made once). 10 * 4^s + 2 vertices, 20 * 4^s faces; counter-clockwise seen from outside;
// normals = positions; spherical UVs (see project_uvs_spherical). 0 <= subdivisions <= 8.
Mesh make_icosphere(int subdivisions);

// A textured square plane: `segments` x `segments` quads spanning [-1, 1] in x and z at y = 0,
// facing +y (counter-clockwise seen from above), normals +y, UVs [0, repeat] (u along +x, v along
// +z), one material with a checker texture. segments >= 1, repeat > 0.
Mesh make_plane(int segments = 1, float repeat = 1.0f);

// Replaces the mesh's UVs with a projection for meshes that have none. Spherical: about the
// bounding-box centre, u = longitude (atan2(x, z) / 2pi + 0.5), v = latitude (0 at +y, 1 at -y).
void project_uvs_spherical(Mesh& mesh);
// Planar along an axis (0 = x, 1 = y, 2 = z): the other two coordinates, normalised to the
// bounding box, become (u, v): axis z -> (x, y), axis x -> (z, y), axis y -> (x, z); v runs
// top-down (v = 0 at the largest coordinate) so the image appears upright.
void project_uvs_planar(Mesh& mesh, int axis);

}  // namespace rastrace

// The scenes of the OSMesa cross-check, built in code (no golden images): each is drawn by
// rastrace and by OSMesa (softpipe and llvmpipe) in the same test.
#pragma once

#include <string>

#include "scenes/scene.h"

namespace rastrace::testing {

// 4x4 quads of flat colours whose vertices (and so every edge) pass through pixel centres,
// plus a skewed triangle pair sharing a diagonal through centres. Untextured.
Scene flat_triangles_scene();
// 200 triangles around one vertex on a pixel centre, rim vertices on the 1/256-pixel grid.
Scene fan_scene();
// A checkered floor that starts behind the camera: the near plane cuts it.
Scene near_clip_scene();
// A large checkered plane seen at about 4 degrees: trilinear minification over many mip levels.
Scene grazing_plane_scene();
// bunny00 with a checker texture (spherical UVs) under a perspective camera.
Scene bunny_checker_scene(int width, int height);

}  // namespace rastrace::testing

// bunny00 with spherical UVs and one procedural checker texture: the textured real mesh of the
// rendering tests (live simulation against replay, the OSMesa cross-check). The caller sets the camera.
#pragma once

#include <string>

#include "scenes/procedural.h"
#include "scenes/scene.h"
#include "scenes/texture_io.h"
#include "support/test_meshes.h"

namespace rastrace::testing {

// A width x height frame; the checker is texture_size texels square with checks x checks squares,
// mipmapped.
inline Scene textured_bunny(int width, int height, int texture_size, int checks) {
  Scene scene;
  scene.name = "bunny00 checker";
  scene.width = width;
  scene.height = height;
  Texture checker;
  checker.name = "checker";
  checker.levels = build_mip_chain(make_checker(texture_size, checks));
  scene.textures.push_back(checker);
  SceneObject bunny;
  bunny.mesh = cached_mesh("bunny00.off");
  project_uvs_spherical(bunny.mesh);
  Material material;
  material.name = "checker";
  material.texture = 0;
  bunny.mesh.materials = {material};
  bunny.mesh.face_material.clear();
  scene.objects.push_back(bunny);
  return scene;
}

}  // namespace rastrace::testing

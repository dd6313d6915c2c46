// JSON scenes (scenes/scene_io.cpp): the document, the objects, cameras, materials, procedural
// meshes and textures. The data folder is pointed at the scratch folder, so a scene names only
// what the fuzzer wrote (m.off, a small mesh with UVs, is there to be referenced).
#include <cstdlib>

#include "fuzz/fuzz_target.h"
#include "scenes/scene_io.h"

RASTRACE_FUZZ_TARGET(scene) {
  static const bool prepared = [] {
    setenv("RASTRACE_DATA", rastrace::fuzz::scratch_folder().c_str(), 1);
    rastrace::fuzz::write_input("m.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n");
    return true;
  }();
  (void)prepared;
  const std::string path = rastrace::fuzz::write_input("input.json", data, size);
  rastrace::fuzz::expect_clean([&] { rastrace::load_scene(path); });
}

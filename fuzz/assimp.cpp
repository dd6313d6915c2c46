// The assimp-backed loader (load_with_assimp, scenes/assimp_io.cpp), for every format rastrace
// does not read itself. The first byte chooses the file extension (assimp picks its importer by
// extension and content); the rest is the file. assimp itself is not instrumented: coverage
// guides the fuzzer only through rastrace's side (the scene conversion, the checks, the errors).
#include <array>

#include "fuzz/fuzz_target.h"
#include "scenes/mesh_io.h"

RASTRACE_FUZZ_TARGET(assimp) {
  static constexpr std::array<const char*, 12> extensions = {".gltf", ".glb", ".dae", ".3ds", ".ase", ".stl",
                                                             ".x",    ".ac",  ".md2", ".lwo", ".ms3d", ".3mf"};
  if (size == 0) return;
  const std::string path =
      rastrace::fuzz::write_input(std::string("input") + extensions[data[0] % extensions.size()], data + 1, size - 1);
  rastrace::fuzz::expect_clean([&] { rastrace::load_with_assimp(path); });
}

// PLY meshes (scenes/ply_io.cpp): ascii, binary_little_endian and binary_big_endian bodies; the
// header chooses, so one target covers all three.
#include "fuzz/fuzz_target.h"
#include "scenes/mesh_io.h"

RASTRACE_FUZZ_TARGET(ply) {
  const std::string path = rastrace::fuzz::write_input("input.ply", data, size);
  rastrace::fuzz::expect_clean([&] { rastrace::load_ply(path); });
}

// OFF meshes (scenes/off_io.cpp): OFF, COFF, NOFF, STOFF headers, polygons of any size.
#include "fuzz/fuzz_target.h"
#include "scenes/mesh_io.h"

RASTRACE_FUZZ_TARGET(off) {
  const std::string path = rastrace::fuzz::write_input("input.off", data, size);
  rastrace::fuzz::expect_clean([&] { rastrace::load_off(path); });
}

// Wavefront OBJ with its MTL (scenes/obj_io.cpp). The input is the OBJ text, optionally followed
// by a line "%%MTL%%" and the text of the material library, written beside it as m.mtl (seeds
// say `mtllib m.mtl`); a texture t.png exists beside both, so map_Kd can resolve.
#include <algorithm>
#include <string_view>

#include "fuzz/fuzz_target.h"
#include "scenes/mesh_io.h"

RASTRACE_FUZZ_TARGET(obj) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  constexpr std::string_view separator = "\n%%MTL%%\n";
  const std::size_t split = input.find(separator);
  const std::string_view obj = input.substr(0, split);
  const std::string_view mtl = split == std::string_view::npos ? std::string_view{} : input.substr(split + separator.size());
  static const bool texture_written = (rastrace::fuzz::write_input("t.png", std::string{}), true);
  (void)texture_written;
  rastrace::fuzz::write_input("m.mtl", std::string(mtl));
  const std::string path = rastrace::fuzz::write_input("input.obj", std::string(obj));
  rastrace::fuzz::expect_clean([&] { rastrace::load_obj(path); });
}

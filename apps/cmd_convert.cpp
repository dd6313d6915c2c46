// `rastrace convert IN OUT [--ascii]`: rewrite a mesh as OFF, PLY or OBJ, keeping vertex and face
// order exactly (positions printed bit-exact).
#include <filesystem>
#include <iostream>
#include <string>

#include "apps/commands.h"
#include "scenes/mesh_io.h"

namespace rastrace {

void add_convert_command(CLI::App& app) {
  CLI::App* command = app.add_subcommand("convert", "Convert a mesh to OFF, PLY or OBJ, keeping vertex and face order");
  auto input = std::make_shared<std::string>();
  auto output = std::make_shared<std::string>();
  auto ascii = std::make_shared<bool>(false);
  command->add_option("input", *input, "Mesh file (.off .ply .obj .gltf .dae ...)")->required();
  command->add_option("output", *output, "Output file: .off, .ply (binary unless --ascii) or .obj (+ .mtl)")
      ->required();
  command->add_flag("--ascii", *ascii, "Write PLY as ASCII instead of binary little-endian");
  command->footer(
      "Examples:\n"
      "  rastrace convert data/meshes/fandisk.off fandisk.ply\n"
      "  rastrace convert data/assimp/OBJ/spider.obj spider.ply --ascii");
  command->callback([input, output, ascii] {
    std::string extension = std::filesystem::path(*output).extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (*ascii && extension != ".ply") throw CLI::ValidationError("--ascii", "applies to .ply output only");
    const Mesh mesh = load_mesh(*input);
    MeshWriteOptions options;
    options.ascii = *ascii;
    save_mesh(mesh, *output, options);
    std::cout << "wrote " << *output << ": " << mesh.vertex_count() << " vertices, " << mesh.face_count() << " faces\n";
  });
}

}  // namespace rastrace

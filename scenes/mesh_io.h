// Reading and writing meshes while keeping the file's own vertex sharing, vertex order and face
// order, so a reordered mesh can be handed to another tool and read back unchanged.
//
// Formats (chosen by extension, case-insensitive):
//   .off                 OFF (also COFF/NOFF/STOFF headers; colours and extra columns ignored)
//   .ply                 PLY: ascii, binary_little_endian, binary_big_endian; vertex x y z,
//                        optional nx ny nz and s t / u v / texture_u texture_v; face
//                        vertex_indices / vertex_index lists of any size
//   .obj                 Wavefront OBJ + MTL: a vertex is a distinct (v, vt, vn) triple in order
//                        of first appearance; negative indices; usemtl gives per-face materials;
//                        map_Kd resolved relative to the MTL file
//   anything else        through assimp (glTF, COLLADA, 3DS, ...), with
//                        aiProcess_JoinIdenticalVertices | aiProcess_Triangulate; the scene
//                        graph's transforms baked in; embedded images kept in TextureSource::embedded
// Polygons are fan-triangulated in file order: (v0 v1 v2), (v0 v2 v3), ...
// Every malformed input throws InputError naming the file, the line (text) or byte offset
// (binary), and what was expected: "bunny.ply:1234: face index 40012 >= vertex count 34835".
#pragma once

#include <string>

#include "scenes/mesh.h"

namespace rastrace {

// Loads any supported mesh file (dispatch on the extension).
Mesh load_mesh(const std::string& path);

struct MeshWriteOptions {
  bool ascii = false;  // PLY only: ASCII instead of binary_little_endian
};

// Writes .off, .ply or .obj (by extension) through an atomic file: positions are printed with the
// shortest decimal that reads back bit-exact; vertex order and face order are kept exactly. OBJ
// also writes vt/vn when the mesh has UVs/normals and an .mtl beside it when it has materials.
void save_mesh(const Mesh& mesh, const std::string& path, const MeshWriteOptions& options = {});

// The individual formats, for callers that know what they hold.
Mesh load_off(const std::string& path);
Mesh load_ply(const std::string& path);
Mesh load_obj(const std::string& path);
Mesh load_with_assimp(const std::string& path);
void save_off(const Mesh& mesh, const std::string& path);
void save_ply(const Mesh& mesh, const std::string& path, bool ascii);
void save_obj(const Mesh& mesh, const std::string& path);

}  // namespace rastrace

// Every malformed input ends as exit code 1 with a message naming the file, the place (line or
// byte offset, JSON path) and what was expected; never a crash (this suite also runs under ASan).
// The fixtures are written by the test into a temporary folder.
#include <algorithm>
#include <cstring>
#include <filesystem>
#include <functional>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/support/run_rastrace.h"
#include "tests/support/temp_dir.h"
#include "tests/support/test_data.h"

namespace rastrace {
namespace {

using ::testing::HasSubstr;
using testing::run_rastrace;
using testing::TempDir;

// Binary PLY with 4 vertices (float xyz) and the given faces (uchar count, int indices).
std::string binary_ply(bool big_endian, const std::vector<std::vector<std::int32_t>>& faces,
                       std::size_t extra_bytes = 0) {
  std::string out = std::string("ply\nformat ") + (big_endian ? "binary_big_endian" : "binary_little_endian") +
                    " 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\nelement face " +
                    std::to_string(faces.size()) + "\nproperty list uchar int vertex_indices\nend_header\n";
  const auto put = [&out, big_endian](const void* p, std::size_t n) {
    std::string bytes(static_cast<const char*>(p), n);
    if (big_endian) std::reverse(bytes.begin(), bytes.end());
    out += bytes;
  };
  for (int v = 0; v < 4; ++v)
    for (int c = 0; c < 3; ++c) {
      const float value = static_cast<float>(v * 3 + c);
      put(&value, 4);
    }
  for (const auto& face : faces) {
    const auto n = static_cast<std::uint8_t>(face.size());
    put(&n, 1);
    for (const std::int32_t i : face) put(&i, 4);
  }
  return out + std::string(extra_bytes, '\0');
}

struct Malformed {
  const char* name;  // test name
  const char* file;  // file name in the temporary folder
  std::function<std::string()> contents;
  std::vector<std::string> expected;  // substrings of the error message
  std::function<void(const TempDir&)> setup = nullptr;
};

std::string text(const char* s) { return s; }

const std::vector<Malformed>& cases() {
  static const std::vector<Malformed> all = {
      {"OffTruncated",
       "truncated.off",
       [] { return text("OFF\n4 2 0\n0 0 0\n1 0 0\n"); },
       {"truncated.off:4: ", "file ends after 2 of 4 vertices"}},
      {"OffFaceIndexOutOfRange",
       "index.off",
       [] { return text("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"); },
       {"index.off:6: face index 7 >= vertex count 3"}},
      {"OffNanCoordinate",
       "nan.off",
       [] { return text("OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n"); },
       {"nan.off:4: vertex 1: coordinate 'nan' is not finite"}},
      {"OffInfiniteCoordinate",
       "inf.off",
       [] { return text("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1e39 0\n3 0 1 2\n"); },
       {"inf.off:5: vertex 2: coordinate '1e39' is not finite"}},
      {"OffWrongHeader",
       "header.off",
       [] { return text("OFX\n3 1 0\n"); },
       {"header.off:1: expected an OFF header", "found 'OFX'"}},
      {"OffWrongCounts",
       "counts.off",
       [] { return text("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 2 1 0\n"); },
       {"counts.off:7: unexpected data after the last of 1 faces", "wrong counts"}},
      {"OffEmpty", "empty.off", [] { return text(""); }, {"empty.off:1: empty file: expected an OFF header"}},
      {"OffTextForANumber",
       "word.off",
       [] { return text("OFF\n1 0 0\n0 zero 0\n"); },
       {"word.off:3: vertex 0: expected a coordinate, found 'zero'"}},
      {"OffFaceWithTwoVertices",
       "edge.off",
       [] { return text("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n"); },
       {"edge.off:6: face 0: expected the number of its vertices (at least 3), found '2'"}},
      {"PlyBadPropertyType",
       "type.ply",
       [] { return text("ply\nformat ascii 1.0\nelement vertex 1\nproperty flaot x\nend_header\n1\n"); },
       {"type.ply:4: bad PLY property: expected a type", "found 'flaot'"}},
      {"PlyTruncatedBinary",
       "cut.ply",
       [] {
         const std::string full = binary_ply(false, {{0, 1, 2}});
         return full.substr(0, full.size() - 6);
       },
       {"cut.ply: byte ", "file ends early (truncated?): expected 4 bytes for vertex_indices"}},
      {"PlyMissingX",
       "nox.ply",
       [] {
         return text("ply\nformat ascii 1.0\nelement vertex 1\nproperty float y\nproperty float z\nend_header\n1 2\n");
       },
       {"nox.ply:3: vertex element has no property x"}},
      {"PlyAsciiFaceIndexOutOfRange",
       "index.ply",
       [] {
         return text(
             "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
             "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 9\n");
       },
       {"index.ply:13: face index 9 >= vertex count 3"}},
      {"PlyBigEndianFaceIndexOutOfRange",
       "big.ply",
       [] {
         return binary_ply(true, {{0, 1, 2}, {3, 2, 5}});
       },
       {"big.ply: byte ", "face index 5 >= vertex count 4"}},
      {"PlyUnknownFormat",
       "format.ply",
       [] { return text("ply\nformat binary_middle_endian 1.0\nend_header\n"); },
       {"format.ply:2: expected format ascii, binary_little_endian or binary_big_endian"}},
      {"PlyWrongMagic",
       "magic.ply",
       [] { return text("plyx\nformat ascii 1.0\n"); },
       {"magic.ply:1: expected the PLY magic line 'ply'"}},
      {"PlyWrongCountsLeaveTrailingBytes",
       "extra.ply",
       [] {
         return binary_ply(false, {{0, 1, 2}}, 17);
       },
       {"extra.ply: byte ", "17 bytes after the last element"}},
      {"PlyFloatIndexList",
       "floatlist.ply",
       [] {
         return text(
             "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\nproperty float z\n"
             "element face 0\nproperty list uchar float vertex_indices\nend_header\n");
       },
       {"floatlist.ply:7: bad PLY property: vertex_indices must be a list of an integer type"}},
      {"PlyNoEndHeader",
       "noend.ply",
       [] { return text("ply\nformat ascii 1.0\nelement vertex 1\n"); },
       {"noend.ply:3: file ends inside the header: expected 'end_header'"}},
      {"ObjFaceIndexOutOfRange",
       "index.obj",
       [] { return text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 5\n"); },
       {"index.obj:4: vertex index 5 out of range: 3 vertices defined so far"}},
      {"ObjIndexZero",
       "zero.obj",
       [] { return text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n"); },
       {"zero.obj:4: vertex index 0: OBJ indices start at 1"}},
      {"ObjNanVertex",
       "nan.obj",
       [] { return text("v 0 0 0\nv 1 -nan 0\n"); },
       {"nan.obj:2: 'v' value '-nan' is not finite"}},
      {"ObjMissingMtl",
       "nomtl.obj",
       [] { return text("mtllib nowhere.mtl\nv 0 0 0\n"); },
       {"nomtl.obj:1: mtllib: material library", "nowhere.mtl not found"}},
      {"ObjMissingTexture",
       "notex.obj",
       [] { return text("mtllib lib.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n"); },
       {"lib.mtl:3: map_Kd 'gone.png': texture file", "gone.png not found"},
       [](const TempDir& dir) { dir.write("lib.mtl", "newmtl a\nKd 1 1 1\nmap_Kd gone.png\n"); }},
      {"ObjUnknownMaterial",
       "usemtl.obj",
       [] { return text("mtllib lib.mtl\nv 0 0 0\nusemtl b\n"); },
       {"usemtl.obj:3: usemtl 'b': no such material in the mtllib files"},
       [](const TempDir& dir) { dir.write("lib.mtl", "newmtl a\nKd 1 1 1\n"); }},
      {"UnknownFormat",
       "mesh.xyz",
       [] { return text("1 2 3\n"); },
       {"mesh.xyz: unknown mesh format '.xyz': expected .off, .ply, .obj"}},
      {"MissingFile", "missing.off", nullptr, {"missing.off: no such file"}},
      {"DirectoryInsteadOfFile",
       "folder.ply",
       nullptr,
       {"folder.ply: is a directory, expected a file"},
       [](const TempDir& dir) { std::filesystem::create_directory(dir.file("folder.ply")); }},
      {"JsonSyntaxError",
       "syntax.json",
       [] { return text("{\n  \"objects\": [\n    { \"mesh\": \"a.off\" }\n    { \"mesh\": \"b.off\" }\n  ]\n}\n"); },
       {"syntax.json:4: column 5: invalid JSON", "expected ']'"}},
      {"JsonWrongShape",
       "shape.json",
       [] { return text(R"({"objects": [{"mesh": {"procedural": "grid"}, "transform": {"scale": "big"}}]})"); },
       {"shape.json: objects[0].transform.scale: expected an array of 3 numbers, found \"big\""}},
      {"JsonMissingTexture",
       "tex.json",
       [] { return text(R"({"objects": [{"mesh": {"procedural": "plane"}, "material": {"texture": "none.png"}}]})"); },
       {"tex.json: objects[0].material.texture: expected an existing file; \"none.png\" found neither in"}},
      {"CorruptTextureImage",
       "image.json",
       [] { return text(R"({"objects": [{"mesh": {"procedural": "plane"}, "material": {"texture": "bad.png"}}]})"); },
       {"bad.png: byte 8: truncated PNG: expected a chunk header"},
       [](const TempDir& dir) { dir.write("bad.png", std::string("\x89PNG\r\n\x1a\n", 8) + "truncated"); }},
      {"BrokenGltfThroughAssimp",
       "broken.gltf",
       [] { return text("{ \"asset\": { \"version\": \"2.0\" }, \"meshes\": [ { \"primitives\": 7 } ] }"); },
       {"broken.gltf: assimp cannot read it"}},
  };
  return all;
}

class MalformedInput : public ::testing::TestWithParam<std::size_t> {};

TEST_P(MalformedInput, ExitsWithCode1AndSaysWhereAndWhat) {
  const Malformed& m = cases()[GetParam()];
  TempDir dir;
  if (m.setup) m.setup(dir);
  const std::string path = m.contents ? dir.write(m.file, m.contents()) : dir.file(m.file);
  const auto result = run_rastrace({"info", path});
  EXPECT_EQ(result.exit_code, 1) << result.err;
  EXPECT_TRUE(result.out.empty()) << result.out;
  // (libpng may print its own line first; rastrace's message follows.)
  EXPECT_THAT(result.err, HasSubstr("rastrace: "));
  for (const std::string& expected : m.expected) EXPECT_THAT(result.err, HasSubstr(expected));
  EXPECT_THAT(result.err, ::testing::Not(HasSubstr("Sanitizer")));
}

INSTANTIATE_TEST_SUITE_P(Files, MalformedInput, ::testing::Range<std::size_t>(0, cases().size()),
                         [](const ::testing::TestParamInfo<std::size_t>& info) {
                           return std::string(cases()[info.param].name);
                         });

TEST(MalformedInput, UnknownBuiltinSceneExitsWithCode1) {
  const auto result = run_rastrace({"info", "builtin:teapot"});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_THAT(
      result.err,
      HasSubstr("builtin:teapot: no such built-in scene; expected builtin:grid, builtin:bunny or builtin:spider"));
}

TEST(MalformedInput, ConvertRefusesBadInputsAndWritesNothing) {
  TempDir dir;
  for (const std::size_t i : {0u, 10u, 19u}) {  // truncated OFF, truncated binary PLY, OBJ index out of range
    const Malformed& m = cases()[i];
    const std::string path = dir.write(m.file, m.contents());
    const auto result = run_rastrace({"convert", path, dir.file("converted.off")});
    EXPECT_EQ(result.exit_code, 1) << m.name;
    EXPECT_THAT(result.err, HasSubstr(m.expected[0])) << m.name;
    EXPECT_FALSE(std::filesystem::exists(dir.file("converted.off"))) << m.name;
  }
}

TEST(MalformedInput, AtLeastFifteenDistinctFiles) { EXPECT_GE(cases().size(), 15u); }

}  // namespace
}  // namespace rastrace

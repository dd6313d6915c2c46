// Generated mesh and scene files whose headers declare huge counts of records that cost the file
// no bytes or almost none: a PLY element without properties, lists of length 0, an OFF header of
// two billion vertices and nothing after it, a scene asking for the largest procedural meshes and
// textures. Each format's record shapes are crossed with every count of hostile_counts(), from
// just past a stated limit to 2^63 - 1. A loader must answer each in a moment with an InputError
// naming the file, or with a mesh it actually read (tests/scenes/header_counts_test.cpp); a loop
// that trusts the count instead runs for minutes or for ever (a 185-byte PLY file ran past 20 s).
// The trace formats' cases are in tests/traces/header_counts_test.cpp.
#pragma once

#include <bit>
#include <cstdint>
#include <cstring>
#include <ostream>
#include <string>
#include <vector>

namespace rastrace::testing {

// One generated file: a test name (letters, digits, '_'), the file name it is written under (the
// extension picks the loader) and its bytes.
struct HostileFile {
  std::string name;
  std::string file_name;
  std::string bytes;
};

// GoogleTest prints a test's parameter beside its name (and ctest lists it): the name, not the
// struct's bytes.
inline void PrintTo(const HostileFile& file, std::ostream* out) { *out << file.name; }

// Count magnitudes: just past 2^16 (the bound on records of no bytes), a million, 2^31, four
// billion, 2^32 - 1 and 2^63 - 1. Small enough for the loaders' integer types, or just beyond them.
inline const std::vector<std::uint64_t>& hostile_counts() {
  static const std::vector<std::uint64_t> counts = {65537,      1000000,    2147483648ull,
                                                    4000000000, 4294967295, 9223372036854775807ull};
  return counts;
}

namespace hostile_detail {

// PLY data values in the file's encoding: ASCII tokens or binary of either byte order.
class PlyData {
 public:
  explicit PlyData(int format) : format_(format) {}  // 0 ascii, 1 little endian, 2 big endian
  PlyData& f32(float v) { return put(v, std::to_string(v)); }
  PlyData& i32(std::int32_t v) { return put(v, std::to_string(v)); }
  PlyData& u8(std::uint8_t v) { return put(v, std::to_string(v)); }
  PlyData& u32(std::uint32_t v) { return put(v, std::to_string(v)); }
  PlyData& end_record() {
    if (format_ == 0) bytes_ += '\n';
    return *this;
  }
  const std::string& bytes() const { return bytes_; }

 private:
  template <typename T>
  PlyData& put(T value, const std::string& text) {
    if (format_ == 0) {
      bytes_ += text + ' ';
      return *this;
    }
    char raw[sizeof(T)];
    std::memcpy(raw, &value, sizeof(T));
    const bool big = format_ == 2;
    if (big != (std::endian::native == std::endian::big))
      for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(raw[i], raw[sizeof(T) - 1 - i]);
    bytes_.append(raw, sizeof(T));
    return *this;
  }
  int format_;
  std::string bytes_;
};

inline const char* const kPlyFormats[3] = {"ascii", "binary_little_endian", "binary_big_endian"};
inline const char* const kPlyFormatNames[3] = {"ascii", "binary_le", "binary_be"};

inline const char* kTriangleVertices = "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n";

inline void triangle_vertices(PlyData& d) {
  d.f32(0).f32(0).f32(0).end_record().f32(1).f32(0).f32(0).end_record().f32(0).f32(1).f32(0).end_record();
}

inline void one_face(PlyData& d) { d.u8(3).i32(0).i32(1).i32(2).end_record(); }

inline std::string ply_file(int format, const std::string& elements, const std::string& data) {
  return std::string("ply\nformat ") + kPlyFormats[format] + " 1.0\ncomment generated hostile header\n" + elements +
         "end_header\n" + data;
}

}  // namespace hostile_detail

// PLY in the three encodings, seven record shapes:
//   empty_element        element e N without properties after the vertices (0 bytes a record)
//   empty_element_first  the same before the vertices
//   vertex_count         element vertex N of uchar x y z, 3 vertices present (3 bytes a record)
//   face_count           element face N, one face present
//   zero_length_lists    element edge N of 'property list uchar int vertex_indices', lists of length 0
//   list_length          one face whose index list claims N entries (count type uint), 3 present
//   skipped_list_length  an element the loader skips, its one list claiming N uchar entries
inline std::vector<HostileFile> hostile_ply_files() {
  using namespace hostile_detail;
  std::vector<HostileFile> out;
  for (int format = 0; format < 3; ++format)
    for (const std::uint64_t n : hostile_counts()) {
      const std::string count = std::to_string(n);
      const auto u32_count = static_cast<std::uint32_t>(n > 0xffffffffull ? 0xffffffffull : n);
      const auto add = [&](const std::string& shape, const std::string& elements, const PlyData& data) {
        const std::string name = std::string("ply_") + kPlyFormatNames[format] + "_" + shape + "_" + count;
        out.push_back({name, name + ".ply", ply_file(format, elements, data.bytes())});
      };
      const std::string face1 = "element face 1\nproperty list uchar int vertex_indices\n";
      {
        PlyData d(format);
        triangle_vertices(d);
        one_face(d);
        add("empty_element", kTriangleVertices + ("element e " + count + "\n") + face1, d);
        add("empty_element_first", "element e " + count + "\n" + kTriangleVertices + face1, d);
      }
      {
        PlyData d(format);
        for (int v = 0; v < 3; ++v) d.u8(0).u8(static_cast<std::uint8_t>(v)).u8(1).end_record();
        add("vertex_count", "element vertex " + count + "\nproperty uchar x\nproperty uchar y\nproperty uchar z\n", d);
      }
      {
        PlyData d(format);
        triangle_vertices(d);
        one_face(d);
        add("face_count", kTriangleVertices + ("element face " + count + "\nproperty list uchar int vertex_indices\n"),
            d);
      }
      {
        PlyData d(format);
        triangle_vertices(d);
        for (int e = 0; e < 4; ++e) d.u8(0).end_record();
        add("zero_length_lists",
            kTriangleVertices + ("element edge " + count + "\nproperty list uchar int vertex_indices\n"), d);
      }
      {
        PlyData d(format);
        triangle_vertices(d);
        d.u32(u32_count).i32(0).i32(1).i32(2).end_record();
        add("list_length", kTriangleVertices + std::string("element face 1\nproperty list uint int vertex_indices\n"),
            d);
      }
      {
        PlyData d(format);
        triangle_vertices(d);
        d.u32(u32_count).u8(0).u8(0).u8(0).end_record();
        add("skipped_list_length",
            kTriangleVertices + std::string("element extra 1\nproperty list uint uchar values\n"), d);
      }
    }
  return out;
}

// OFF, six shapes:
//   counts_only          'OFF\nN 0 0\n' and nothing more (the user's case)
//   counts_on_keyword    'OFF N N 0' on one line
//   face_count           3 vertices, N faces, one present
//   face_corners         one face claiming N corners, 3 present
//   stcnoff              'STCNOFF' (normals, colours, texture coordinates), N vertices, one present
//   comments             the counts, then comment and blank lines only
inline std::vector<HostileFile> hostile_off_files() {
  std::vector<HostileFile> out;
  const std::string triangle = "0 0 0\n1 0 0\n0 1 0\n";
  for (const std::uint64_t n : hostile_counts()) {
    const std::string c = std::to_string(n);
    const auto add = [&](const std::string& shape, const std::string& bytes) {
      out.push_back({"off_" + shape + "_" + c, "off_" + shape + "_" + c + ".off", bytes});
    };
    add("counts_only", "OFF\n" + c + " 0 0\n");
    add("counts_on_keyword", "OFF " + c + " " + c + " 0\n");
    add("face_count", "OFF\n3 " + c + " 0\n" + triangle + "3 0 1 2\n");
    add("face_corners", "OFF\n3 1 0\n" + triangle + c + " 0 1 2\n");
    add("stcnoff", "STCNOFF\n" + c + " 0 0\n0 0 0 0 0 1 0.5 0.5 0.5 1 0 0\n");
    add("comments", "OFF\n# generated\n" + c + " " + c + " 0\n#\n\n# nothing else\n");
  }
  return out;
}

// OBJ has no header counts; its indices are counts of a kind (1-based, or negative from the end):
//   vertex_index         a face whose third index is N (or -N)
//   texcoord_index       a face whose first corner's texture coordinate index is N
//   normal_index         a face whose first corner's normal index is N
//   corners              one polygon of min(N, 65537) corners on three vertices (fan-triangulated)
inline std::vector<HostileFile> hostile_obj_files() {
  std::vector<HostileFile> out;
  const std::string triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\n";
  for (const std::uint64_t n : hostile_counts()) {
    const std::string c = std::to_string(n);
    const auto add = [&](const std::string& shape, const std::string& bytes) {
      out.push_back({"obj_" + shape + "_" + c, "obj_" + shape + "_" + c + ".obj", bytes});
    };
    add("vertex_index", triangle + "f 1 2 " + c + "\n");
    add("negative_vertex_index", triangle + "f 1 2 -" + c + "\n");
    add("texcoord_index", triangle + "f 1/" + c + " 2/1 3/1\n");
    add("normal_index", triangle + "f 1//" + c + " 2//1 3//1\n");
    std::string polygon = triangle + "f";
    const std::uint64_t corners = n < 65537 ? n : 65537;
    for (std::uint64_t i = 0; i < corners; ++i) polygon += i % 3 == 0 ? " 1" : i % 3 == 1 ? " 2" : " 3";
    add("corners", polygon + "\n");
  }
  return out;
}

// JSON scenes whose sizes come from the file: procedural grids and planes of N segments, spheres
// of N subdivisions, textures of N texels square, 16 grids of min(N, 4096) squared (each side
// within range, their sum beyond the memory limit), a keyframe at frame N, a viewport N wide.
inline std::vector<HostileFile> hostile_scene_files() {
  std::vector<HostileFile> out;
  for (const std::uint64_t n : hostile_counts()) {
    const std::string c = std::to_string(n);
    const auto add = [&](const std::string& shape, const std::string& objects, const std::string& extra = "") {
      out.push_back({"scene_" + shape + "_" + c, "scene_" + shape + "_" + c + ".json",
                     "{\"objects\": [" + objects + "]" + extra + "}\n"});
    };
    add("grid", "{\"mesh\": {\"procedural\": \"grid\", \"width\": " + c + ", \"height\": " + c + "}}");
    add("plane", "{\"mesh\": {\"procedural\": \"plane\", \"segments\": " + c + "}}");
    add("icosphere", "{\"mesh\": {\"procedural\": \"icosphere\", \"subdivisions\": " + c + "}}");
    add("texture",
        "{\"mesh\": {\"procedural\": \"plane\"}, \"material\": {\"texture\": {\"procedural\": \"checker\", \"size\": " +
            c + ", \"checks\": " + c + "}}}");
    const std::string side = std::to_string(n < 4096 ? n : 4096);
    std::string grids;
    for (int i = 0; i < 16; ++i)
      grids += std::string(i ? ", " : "") + "{\"mesh\": {\"procedural\": \"grid\", \"width\": " + side +
               ", \"height\": " + side + "}}";
    add("many_grids", grids);
    const std::string key = "{\"eye\": [0, 0, 3], \"target\": [0, 0, 0], \"frame\": ";
    add("keyframe", "{\"mesh\": {\"procedural\": \"plane\"}}",
        ", \"camera_path\": {\"keyframes\": [" + key + "0}, " + key + c + "}]}");
    add("viewport", "{\"mesh\": {\"procedural\": \"plane\"}}",
        ", \"viewport\": {\"width\": " + c + ", \"height\": " + c + "}");
  }
  return out;
}

}  // namespace rastrace::testing

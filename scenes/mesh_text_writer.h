// The text the mesh writers share: vertex lines, triangle lines and the atomic write of the whole
// file. OFF, ASCII PLY and OBJ print a vertex attribute the same way (components separated by one
// space, each the shortest decimal that reads back bit-exact), so one formatter keeps the three
// formats byte-compatible: a mesh converted OFF -> PLY -> OBJ -> OFF comes back byte for byte.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace rastrace {

// Appends the components separated by single spaces: "x y" / "x y z", no line break.
void append_components(std::string& out, const glm::vec2& value);
void append_components(std::string& out, const glm::vec3& value);

// One line per value: `keyword` (e.g. "v ", or "" for OFF), its components, '\n'.
void append_attribute_lines(std::string& out, std::string_view keyword, const std::vector<glm::vec2>& values);
void append_attribute_lines(std::string& out, std::string_view keyword, const std::vector<glm::vec3>& values);

// One line "3 i0 i1 i2" per triangle, 0-based, as OFF and ASCII PLY write faces.
void append_triangle_lines(std::string& out, const std::vector<std::uint32_t>& indices);

// Writes `contents` as the whole file at `path`, atomically (binary: bytes as they are).
void write_whole_file(const std::filesystem::path& path, std::string_view contents);

}  // namespace rastrace

#include "scenes/mesh_text_writer.h"

#include "core/atomic_file.h"
#include "scenes/text_parse.h"

namespace rastrace {

namespace {

template <typename Vec>
void append_lines(std::string& out, std::string_view keyword, const std::vector<Vec>& values) {
  for (const Vec& value : values) {
    out += keyword;
    append_components(out, value);
    out += '\n';
  }
}

}  // namespace

void append_components(std::string& out, const glm::vec2& value) {
  append_number(out, value.x);
  out += ' ';
  append_number(out, value.y);
}

void append_components(std::string& out, const glm::vec3& value) {
  append_components(out, glm::vec2(value.x, value.y));
  out += ' ';
  append_number(out, value.z);
}

void append_attribute_lines(std::string& out, std::string_view keyword, const std::vector<glm::vec2>& values) {
  append_lines(out, keyword, values);
}

void append_attribute_lines(std::string& out, std::string_view keyword, const std::vector<glm::vec3>& values) {
  append_lines(out, keyword, values);
}

void append_triangle_lines(std::string& out, const std::vector<std::uint32_t>& indices) {
  for (std::size_t i = 0; i + 2 < indices.size(); i += 3) {
    out += "3 ";
    append_number(out, indices[i]);
    out += ' ';
    append_number(out, indices[i + 1]);
    out += ' ';
    append_number(out, indices[i + 2]);
    out += '\n';
  }
}

void write_whole_file(const std::filesystem::path& path, std::string_view contents) {
  write_file_atomically(path, [&](std::ostream& stream) {
    stream.write(contents.data(), static_cast<std::streamsize>(contents.size()));
  });
}

}  // namespace rastrace

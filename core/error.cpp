#include "core/error.h"

namespace rastrace {

void throw_at_line(const std::string& file, std::uint64_t line, const std::string& message) {
  throw InputError(file + ":" + std::to_string(line) + ": " + message);
}

void throw_at_byte(const std::string& file, std::uint64_t offset, const std::string& message) {
  throw InputError(file + ": byte " + std::to_string(offset) + ": " + message);
}

void throw_in_file(const std::string& file, const std::string& message) { throw InputError(file + ": " + message); }

}  // namespace rastrace

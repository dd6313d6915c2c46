// Errors that reach the user. Every error about input names the file, the place in it
// (line, byte offset, record, chunk...) and what was expected:
//   bunny.ply:1234: face index 40012 >= vertex count 34835
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace rastrace {

// Bad input: a malformed file, an out-of-range value, an impossible parameter.
// The command line turns it into exit code 1.
class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

// "file:line: message"
[[noreturn]] void throw_at_line(const std::string& file, std::uint64_t line, const std::string& message);
// "file: byte N: message"
[[noreturn]] void throw_at_byte(const std::string& file, std::uint64_t offset, const std::string& message);
// "file: message"
[[noreturn]] void throw_in_file(const std::string& file, const std::string& message);

}  // namespace rastrace

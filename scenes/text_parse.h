// Fast text scanning and printing for the mesh formats: a whole file in memory, lines counted for
// error messages, numbers parsed with std::from_chars (no iostreams on the hot path) and printed
// with std::to_chars (shortest decimal that reads back bit-exact).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace rastrace {

// The whole file as bytes. InputError "path: no such file" / "is a directory" / "cannot read".
std::string read_whole_file(const std::string& path);

// Walks a text file line by line; line numbers start at 1. '\r\n' and '\r' line ends accepted.
class TextLines {
 public:
  TextLines(std::string path, std::string_view text) : path_(std::move(path)), text_(text) {}

  // The next line without its line break; false at the end of the text.
  bool next(std::string_view& line);
  std::uint64_t line_number() const { return line_; }
  // Byte offset of the start of the next line.
  std::size_t offset() const { return position_; }
  const std::string& path() const { return path_; }
  // "path:line: message" as InputError, at the current line.
  [[noreturn]] void fail(const std::string& message) const;

 private:
  std::string path_;
  std::string_view text_;
  std::size_t position_ = 0;
  std::uint64_t line_ = 0;
};

// Splits off the next whitespace-separated token of `rest` (empty when none is left).
std::string_view next_token(std::string_view& rest);
// `rest` without leading and trailing whitespace.
std::string_view trim(std::string_view rest);

// Whole-token parses; false if the token is not exactly one number of that type.
bool parse_number(std::string_view token, float& value);
bool parse_number(std::string_view token, double& value);
bool parse_number(std::string_view token, std::int64_t& value);

// For error messages: the token quoted and shortened ("'abc'", "end of line" when empty).
std::string describe_token(std::string_view token);

// Appends the shortest decimal that std::from_chars reads back as exactly `value`.
void append_number(std::string& out, float value);
void append_number(std::string& out, std::uint64_t value);
inline void append_number(std::string& out, std::uint32_t value) { append_number(out, std::uint64_t{value}); }

}  // namespace rastrace

#include "scenes/text_parse.h"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <system_error>
#include <type_traits>

#include "core/error.h"
#include "core/input_guard.h"

namespace rastrace {

std::string read_whole_file(const std::string& path) {
  require_regular_file(path);  // a FIFO or /dev/zero would block or never end
  std::ifstream in(path, std::ios::binary);
  if (!in) throw_in_file(path, "cannot open for reading (permission denied?)");
  std::string data;
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size < 0) throw_in_file(path, "cannot read (not a regular file?)");
  data.resize(static_cast<std::size_t>(size));
  in.seekg(0, std::ios::beg);
  in.read(data.data(), size);
  if (in.gcount() != size) throw_in_file(path, "cannot read: short read");
  return data;
}

bool TextLines::next(std::string_view& line) {
  if (position_ >= text_.size()) return false;
  std::size_t end = position_;
  while (end < text_.size() && text_[end] != '\n' && text_[end] != '\r') ++end;
  line = text_.substr(position_, end - position_);
  if (end < text_.size()) {
    if (text_[end] == '\r' && end + 1 < text_.size() && text_[end + 1] == '\n') ++end;
    ++end;
  }
  position_ = end;
  ++line_;
  return true;
}

void TextLines::fail(const std::string& message) const { throw_at_line(path_, line_ == 0 ? 1 : line_, message); }

namespace {
bool is_space(char c) { return c == ' ' || c == '\t' || c == '\f' || c == '\v' || c == '\r' || c == '\n'; }
}  // namespace

std::string_view next_token(std::string_view& rest) {
  std::size_t begin = 0;
  while (begin < rest.size() && is_space(rest[begin])) ++begin;
  std::size_t end = begin;
  while (end < rest.size() && !is_space(rest[end])) ++end;
  const std::string_view token = rest.substr(begin, end - begin);
  rest.remove_prefix(end);
  return token;
}

std::string_view trim(std::string_view rest) {
  while (!rest.empty() && is_space(rest.front())) rest.remove_prefix(1);
  while (!rest.empty() && is_space(rest.back())) rest.remove_suffix(1);
  return rest;
}

namespace {
template <typename T>
bool parse_whole(std::string_view token, T& value) {
  if (token.empty()) return false;
  const char* first = token.data();
  const char* last = first + token.size();
  if (*first == '+') ++first;  // from_chars rejects a leading '+', which files do use
  if (first == last) return false;
  const auto [end, error] = std::from_chars(first, last, value);
  if (error == std::errc::result_out_of_range && end == last) {
    // Too small (or too large) for T: round through a wider type, giving 0 (or infinity, which
    // the loaders then reject as not finite).
    if constexpr (std::is_same_v<T, float>) {
      double wide = 0.0;
      if (!parse_whole(token, wide)) return false;
      // Beyond float range the conversion is undefined: give the infinity it rounds to.
      constexpr float kInfinity = std::numeric_limits<float>::infinity();
      value = std::fabs(wide) > std::numeric_limits<float>::max() ? (wide > 0 ? kInfinity : -kInfinity)
                                                                  : static_cast<float>(wide);
      return true;
    } else if constexpr (std::is_same_v<T, double>) {
      long double wide = 0.0L;
      if (!parse_whole(token, wide)) return false;
      constexpr double kInfinity = std::numeric_limits<double>::infinity();
      value = std::fabs(wide) > std::numeric_limits<double>::max() ? (wide > 0 ? kInfinity : -kInfinity)
                                                                   : static_cast<double>(wide);
      return true;
    }
  }
  return error == std::errc() && end == last;
}
}  // namespace

bool parse_number(std::string_view token, float& value) { return parse_whole(token, value); }
bool parse_number(std::string_view token, double& value) { return parse_whole(token, value); }
bool parse_number(std::string_view token, std::int64_t& value) { return parse_whole(token, value); }

std::string describe_token(std::string_view token) {
  if (token.empty()) return "end of line";
  if (token.size() > 40) return "'" + std::string(token.substr(0, 40)) + "...'";
  std::string out = "'";
  for (const char c : token)
    out += (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126) ? '?' : c;
  return out + "'";
}

void append_number(std::string& out, float value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

void append_number(std::string& out, std::uint64_t value) {
  char buffer[24];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

}  // namespace rastrace

#include "core/units.h"

#include <algorithm>
#include <cctype>
#include <limits>

#include "core/error.h"
#include "core/input_guard.h"

namespace rastrace {
namespace {

[[noreturn]] void bad(const std::string& what, const std::string& text, const std::string& expected) {
  throw InputError(what + ": '" + excerpt(text) + "': expected " + expected);
}

std::uint64_t parse_digits(const std::string& digits, const std::string& what, const std::string& text,
                           const std::string& expected) {
  if (digits.empty() || digits.size() > 19) bad(what, text, expected);
  std::uint64_t value = 0;
  for (const char c : digits) {
    if (!std::isdigit(static_cast<unsigned char>(c))) bad(what, text, expected);
    value = value * 10 + static_cast<std::uint64_t>(c - '0');
  }
  return value;
}

bool is_power_of_two(std::uint64_t v) { return v != 0 && (v & (v - 1)) == 0; }

template <typename ParseOne>
std::vector<std::uint64_t> parse_list(const std::string& text, const std::string& what, ParseOne parse_one) {
  std::vector<std::uint64_t> values;
  for (const std::string& item : split_list(text, what)) {
    const std::size_t dots = item.find("..");
    if (dots == std::string::npos) {
      values.push_back(parse_one(item));
      continue;
    }
    const std::uint64_t first = parse_one(item.substr(0, dots));
    const std::uint64_t last = parse_one(item.substr(dots + 2));
    if (!is_power_of_two(first) || !is_power_of_two(last))
      bad(what, item, "a range between two powers of two (e.g. 1KiB..64KiB)");
    if (first > last) bad(what, item, "a range whose first value is not above its last");
    for (std::uint64_t v = first; v <= last; v *= 2) {
      values.push_back(v);
      if (v > std::numeric_limits<std::uint64_t>::max() / 2) break;
    }
  }
  std::vector<std::uint64_t> unique;
  for (const std::uint64_t v : values)
    if (std::find(unique.begin(), unique.end(), v) == unique.end()) unique.push_back(v);
  return unique;
}

}  // namespace

std::vector<std::string> split_list(const std::string& text, const std::string& what) {
  std::vector<std::string> items;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    while (!item.empty() && std::isspace(static_cast<unsigned char>(item.front()))) item.erase(item.begin());
    while (!item.empty() && std::isspace(static_cast<unsigned char>(item.back()))) item.pop_back();
    if (item.empty()) bad(what, text, "a comma-separated list without empty items");
    items.push_back(item);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return items;
}

std::uint64_t parse_byte_size(const std::string& text, const std::string& what) {
  static const char* expected = "a byte size such as 64B, 16KiB, 1MiB, 2GiB or 4096";
  std::size_t end = 0;
  while (end < text.size() && std::isdigit(static_cast<unsigned char>(text[end]))) ++end;
  const std::uint64_t number = parse_digits(text.substr(0, end), what, text, expected);
  const std::string unit = text.substr(end);
  int shift = 0;
  if (unit.empty() || unit == "B")
    shift = 0;
  else if (unit == "KiB")
    shift = 10;
  else if (unit == "MiB")
    shift = 20;
  else if (unit == "GiB")
    shift = 30;
  else
    bad(what, text, expected);
  if (number == 0) bad(what, text, "a size above 0 bytes");
  if (number > (std::numeric_limits<std::uint64_t>::max() >> shift)) bad(what, text, "a size below 2^64 bytes");
  return number << shift;
}

std::vector<std::uint64_t> parse_byte_size_list(const std::string& text, const std::string& what) {
  return parse_list(text, what, [&](const std::string& item) { return parse_byte_size(item, what); });
}

std::uint64_t parse_count(const std::string& text, const std::string& what) {
  return parse_digits(text, what, text, "a whole number such as 16");
}

std::vector<std::uint64_t> parse_count_list(const std::string& text, const std::string& what) {
  return parse_list(text, what, [&](const std::string& item) { return parse_count(item, what); });
}

std::string format_byte_size(std::uint64_t bytes) {
  static const char* units[] = {"B", "KiB", "MiB", "GiB"};
  int unit = 0;
  while (unit < 3 && bytes != 0 && bytes % 1024 == 0) {
    bytes /= 1024;
    ++unit;
  }
  return std::to_string(bytes) + units[unit];
}

}  // namespace rastrace

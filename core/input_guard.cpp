#include "core/input_guard.h"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <limits>
#include <system_error>

#include "core/error.h"

namespace rastrace {

std::string excerpt(std::string_view text, std::size_t max_chars) {
  std::string out;
  const std::size_t n = text.size() < max_chars ? text.size() : max_chars;
  out.reserve(n + 3);
  for (std::size_t i = 0; i < n; ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    out += (c < 32 || c > 126) ? '?' : static_cast<char>(c);
  }
  if (text.size() > max_chars) out += "...";
  return out;
}

void require_regular_file(const std::string& path) {
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (!std::filesystem::exists(status)) throw_in_file(path, "no such file");
  if (std::filesystem::is_directory(status)) throw_in_file(path, "is a directory, expected a file");
  if (!std::filesystem::is_regular_file(status))
    throw_in_file(path, "is not a regular file (a device, FIFO or socket), expected a file");
}

std::uint64_t allocation_limit_bytes() {
  if (const char* text = std::getenv("RASTRACE_MEMORY_LIMIT"); text && *text) {
    char* end = nullptr;
    const unsigned long long value = std::strtoull(text, &end, 10);
    if (end && *end == '\0' && value > 0) return value;
  }
  const long pages = ::sysconf(_SC_PHYS_PAGES);
  const long page_bytes = ::sysconf(_SC_PAGESIZE);
  if (pages <= 0 || page_bytes <= 0) return std::uint64_t{1} << 40;
  // Half the machine: one table sized by input must leave room for everything else.
  return static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(page_bytes) / 2;
}

std::uint64_t checked_bytes(std::uint64_t count, std::uint64_t element_bytes, const std::string& what) {
  const std::uint64_t limit = allocation_limit_bytes();
  const bool overflows = element_bytes != 0 && count > std::numeric_limits<std::uint64_t>::max() / element_bytes;
  const std::string asked = overflows ? std::string("more than 2^64") : std::to_string(count * element_bytes);
  if (overflows || count * element_bytes > limit)
    throw InputError(what + ": needs " + asked + " bytes (" + std::to_string(count) + " x " +
                     std::to_string(element_bytes) + "), more than the limit of " + std::to_string(limit) +
                     " bytes (half the physical memory, or RASTRACE_MEMORY_LIMIT)");
  return count * element_bytes;
}

void check_empty_records(std::uint64_t count, const std::string& where, const std::string& what) {
  if (count > kMaxEmptyRecords)
    throw InputError(where + ": " + std::to_string(count) + " " + what + " of no bytes each: expected at most " +
                     std::to_string(kMaxEmptyRecords) +
                     " (records that carry no data, yet each is a pass of the reader)");
}

}  // namespace rastrace

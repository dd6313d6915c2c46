// Sizes, counts and their lists and power-of-two ranges (core/units.cpp), as --size, --line,
// --assoc and --entries take them.
#include <string>

#include "core/units.h"
#include "fuzz/fuzz_target.h"

RASTRACE_FUZZ_TARGET(size_list) {
  using namespace rastrace;
  const std::string text(reinterpret_cast<const char*>(data), size);
  fuzz::expect_clean([&] {
    for (const std::uint64_t bytes : parse_byte_size_list(text, "--size")) format_byte_size(bytes);
  });
  fuzz::expect_clean([&] { parse_count_list(text, "--assoc"); });
  fuzz::expect_clean([&] { parse_byte_size(text, "--line"); });
  fuzz::expect_clean([&] { parse_count(text, "--entries"); });
  fuzz::expect_clean([&] { split_list(text, "--orderings"); });
}

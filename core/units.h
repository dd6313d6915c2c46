// Byte sizes and parameter lists as users type them on the command line:
//   "64B", "16KiB", "1MiB", "2GiB", "4096"          one size in bytes (binary prefixes only)
//   "1KiB..64KiB"                                  every power of two from 1 KiB to 64 KiB
//   "1KiB,4KiB,16KiB..64KiB"                       comma lists, ranges allowed inside
//   "1,2,4..16"                                    plain counts (associativities, entries)
// Malformed text throws InputError naming the option and what was expected.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace rastrace {

// "16KiB" -> 16384. `what` names the option in errors ("--size").
std::uint64_t parse_byte_size(const std::string& text, const std::string& what = "size");
// Lists and power-of-two ranges of sizes, in the order written, duplicates removed.
std::vector<std::uint64_t> parse_byte_size_list(const std::string& text, const std::string& what = "size");
// A count (no unit), e.g. "16".
std::uint64_t parse_count(const std::string& text, const std::string& what = "count");
// Lists and power-of-two ranges of counts: "1,2,4..16" -> 1 2 4 8 16.
std::vector<std::uint64_t> parse_count_list(const std::string& text, const std::string& what = "count");
// Splits "a,b,c" into its items (empty items are an error).
std::vector<std::string> split_list(const std::string& text, const std::string& what = "list");

// 16384 -> "16KiB", 64 -> "64B", 1536 -> "1536B": the largest binary unit that divides exactly.
std::string format_byte_size(std::uint64_t bytes);

}  // namespace rastrace

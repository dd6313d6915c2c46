// Guards for input that reaches errors and allocations:
//   excerpt()               quotes user input in an error without echoing all of it
//   require_regular_file()  refuses devices, FIFOs and sockets before a reader blocks or reads forever
//   checked_bytes()         the one check for an allocation whose size comes from input
//   check_empty_records()   the bound on a declared count of records that take no bytes
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace rastrace {

// At most `max_chars` characters of `text`, then "..." when it was longer; control and non-ASCII
// bytes print as '?'. An error about a 10 MB token stays one short line.
std::string excerpt(std::string_view text, std::size_t max_chars = 40);

// Throws InputError "path: no such file" / "is a directory" / "is not a regular file (a device,
// FIFO or socket)" unless `path` names a regular file (symbolic links followed).
void require_regular_file(const std::string& path);

// count * element_bytes, checked before allocating: throws InputError "<what>: needs N bytes
// (count x element_bytes), more than the limit of L bytes" when the product overflows or exceeds
// the limit: half the machine's physical memory, or RASTRACE_MEMORY_LIMIT (bytes) when set.
std::uint64_t checked_bytes(std::uint64_t count, std::uint64_t element_bytes, const std::string& what);
// The limit checked_bytes() applies.
std::uint64_t allocation_limit_bytes();

// A loop over a count that a file declares must consume input on every pass (then the file's end
// stops it) or be bounded before it runs. Records of no bytes at all (a PLY element without
// properties) consume nothing, so a header may declare at most kMaxEmptyRecords of them:
// check_empty_records() throws InputError "<where>: N <what> of no bytes each: expected at most
// 65536 ..." otherwise; `where` names the file and the place ("m.ply:7: element 'e'").
inline constexpr std::uint64_t kMaxEmptyRecords = std::uint64_t{1} << 16;
void check_empty_records(std::uint64_t count, const std::string& where, const std::string& what);

// Grows a table indexed by ids read from input (vertex indices...) so that `index` fits, at least
// doubling it, after checked_bytes(): a stray index near 2^32 is a clear error, not bad_alloc.
template <typename T>
void grow_to_cover(std::vector<T>& table, std::uint64_t index, const std::string& what, const T& fill = T{}) {
  if (index < table.size()) return;
  const std::uint64_t doubled = static_cast<std::uint64_t>(table.size()) * 2;
  const std::uint64_t size = index + 1 > doubled ? index + 1 : doubled;
  checked_bytes(size, sizeof(T), what + " (index " + std::to_string(index) + ")");
  table.resize(static_cast<std::size_t>(size), fill);
}

}  // namespace rastrace

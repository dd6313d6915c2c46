// Guards for input that reaches errors and allocations:
//   excerpt()               quotes user input in an error without echoing all of it
//   require_regular_file()  refuses devices, FIFOs and sockets before a reader blocks or reads forever
//   checked_bytes()         the one check for an allocation whose size comes from input
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace rastrace {

// At most `max_chars` characters of `text`, then "..." when it was longer; control and non-ASCII
// bytes print as '?'. An error about a 10 MB token stays one short line.
std::string excerpt(std::string_view text, std::size_t max_chars = 40);

// Throws InputError "path: no such file" / "is a directory" / "is not a regular file (a device,
// FIFO or socket)" unless `path` names a regular file (symbolic links followed).
void require_regular_file(const std::string& path);

// count * element_bytes, checked before allocating: throws InputError "<what>: needs N bytes
// (count x element_bytes), more than the limit of L bytes" when the product overflows or exceeds
// the limit: the machine's physical memory, or RASTRACE_MEMORY_LIMIT (bytes) when set.
std::uint64_t checked_bytes(std::uint64_t count, std::uint64_t element_bytes, const std::string& what);
// The limit checked_bytes() applies.
std::uint64_t allocation_limit_bytes();

}  // namespace rastrace

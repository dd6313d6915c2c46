// CRC32C (Castagnoli), the checksum of every trace chunk: SSE4.2 instructions when the CPU has
// them, a table otherwise (same result). crc32c("123456789") = 0xE3069283.
#pragma once

#include <cstddef>
#include <cstdint>

namespace rastrace {

// Continues a CRC: crc32c(b, crc32c(a)) == crc32c(a + b). Start with 0.
std::uint32_t crc32c(const void* data, std::size_t size, std::uint32_t crc = 0);

}  // namespace rastrace

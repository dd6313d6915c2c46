// Our traces in other simulators' formats: the byte addresses a rastrace trace's texel (or vertex)
// records stand for under a memory layout, written as
//   extended din   Dinero IV's default input format: one access per line, "label address size"
//                  with label 0 (read), address and size in hexadecimal (size = texel bytes, or
//                  the vertex stride); `rastrace replay`/`sweep` read it back (text_formats.h)
//   libCacheSim    its oracleGeneral binary format: 24-byte little-endian records
//                  {u32 time, u64 object id, u32 object size, i64 next access}, one per access,
//                  the object a cache block (id = address / block bytes, size = block bytes, so
//                  libCacheSim's byte-sized fully associative caches count blocks), time the
//                  access number, next access the number of the next access to the same object
//                  or -1 (what its Belady policy reads)
// Texel addresses come from a TextureLayout (texture_layout.h), as replay computes them; vertex
// fetches of draw d are at (d << 40) + vertex * stride, as LiveBankSink computes them. So a sweep
// of the exported din equals the sweep of the trace, cache for cache.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "cache_sim/texture_layout.h"

namespace rastrace {

struct AddressExportSpec {
  bool vertices = false;  // vertex fetches instead of texel accesses
  LayoutSpec layout;      // texel accesses
  std::uint32_t stride = 32;  // vertex fetches: bytes per vertex
};

// Every address of `trace` (any format replay reads), in trace order. Throws InputError on a
// trace without records of the asked kind or with texels outside its textures.
std::vector<std::uint64_t> trace_addresses(const std::string& trace, const AddressExportSpec& spec);
// The bytes one access asks for: texel bytes or the stride.
std::uint32_t access_bytes(const AddressExportSpec& spec);

void write_extended_din(const std::vector<std::uint64_t>& addresses, std::uint32_t size, std::ostream& out);
// block_bytes: a power of two (InputError otherwise).
void write_libcachesim(const std::vector<std::uint64_t>& addresses, std::uint32_t block_bytes, std::ostream& out);

// One oracleGeneral record, as read back (tests and users checking a file).
struct LibCacheSimRecord {
  std::uint32_t time = 0;
  std::uint64_t object = 0;
  std::uint32_t size = 0;
  std::int64_t next_access = -1;
  bool operator==(const LibCacheSimRecord&) const = default;
};
// Throws InputError naming the file when its size is not a whole number of records.
std::vector<LibCacheSimRecord> read_libcachesim(const std::string& path);

}  // namespace rastrace

// One trace chunk's records behind a valid checksum (traces/chunk_codec.cpp through
// TraceReader::read_chunk). The input is
//   u8 kind (1 vertex, 2 texel, 3 address, 4 framebuffer; taken modulo 4) | u8 flags (bit 7 set:
//   a version 2 file, where run columns are refused; clear: today's version) |
//   u32 record count (little endian) | the encoded records (before zstd)
// and the harness wraps it in a well-formed file: metadata, the zstd frame of the records, the
// chunk header with its CRC32C, a one-entry index and the footer, so every input reaches the
// decoders exactly as a file whose checksums are sound would.
#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include <zstd.h>

#include "core/error.h"
#include "fuzz/fuzz_target.h"
#include "traces/crc32c.h"
#include "traces/texel_lanes.h"
#include "traces/trace_format.h"
#include "traces/trace_metadata.h"
#include "traces/trace_reader.h"

namespace {

// `bytes` bytes of `value`, least significant first (the container is little endian).
std::string le(std::uint64_t value, int bytes) {
  std::string out;
  for (int i = 0; i < bytes; ++i) out += static_cast<char>(value >> (8 * i));
  return out;
}

}  // namespace

RASTRACE_FUZZ_TARGET(trace_chunk) {
  using namespace rastrace;
  if (size < 6) return;
  const std::uint8_t kind = static_cast<std::uint8_t>(data[0] % 4 + 1);
  const bool old_version = (data[1] & 0x80) != 0;
  const std::uint8_t flags = data[1] & 0x7F;
  std::uint32_t records;
  std::memcpy(&records, data + 2, 4);
  // At most 2^18 records (4x the writer's default chunk): the decoders' work is linear in the
  // count, but a chunk of 2^20 equal records is 16 MiB of texels to fill per decoding, which under
  // ASan on a loaded machine passes libFuzzer's 5 s (a 721,568-record chunk took 5.7 s wall, 1.7 s
  // CPU; fuzz/regressions/trace_chunk/texel-721k-records-slow). Counts up to the format's limit
  // and beyond it are the unit tests' and the trace_reader target's (its chunk index).
  records = std::min<std::uint32_t>(records, 1u << 18);
  const std::uint8_t* raw = data + 6;
  const std::size_t raw_bytes = size - 6;

  std::string file(kTraceMagic, 8);
  file += le(old_version ? kSingleFrameTraceVersion : kTraceVersion, 4);
  const std::string json = metadata_to_json(TraceMetadata{});
  file += le(static_cast<std::uint32_t>(json.size()), 4);
  file += json;
  file += le(crc32c(json.data(), json.size()), 4);

  std::string payload(ZSTD_compressBound(raw_bytes), '\0');
  const std::size_t stored = ZSTD_compress(payload.data(), payload.size(), raw, raw_bytes, 1);
  if (ZSTD_isError(stored)) return;
  payload.resize(stored);
  const std::uint64_t chunk_offset = file.size();
  std::string header;
  header += le(kChunkTag, 4);
  header += le(kind, 1);
  header += le(flags, 1);
  header += le(0, 2);
  header += le(records, 4);
  header += le(static_cast<std::uint32_t>(stored), 4);
  header += le(static_cast<std::uint32_t>(raw_bytes), 4);
  header += le(0, 8);  // first record
  header += le(crc32c(payload.data(), payload.size(), crc32c(header.data(), header.size())), 4);
  file += header;
  file += payload;

  const std::uint64_t index_offset = file.size();
  std::string index;
  index += le(kIndexTag, 4);
  index += le(0, 4);
  index += le(1, 8);
  index += le(chunk_offset, 8);
  index += le(0, 8);
  index += le(records, 4);
  index += le(kind, 1);
  index.append(3, '\0');
  file += index;
  file += le(index_offset, 8);
  file += le(crc32c(index.data(), index.size()), 4);
  file += le(0, 4);
  file.append(kTraceEndMagic, 8);

  const std::string path = fuzz::write_input("chunk.rtrace", file);
  if (kind != static_cast<std::uint8_t>(RecordKind::Texel)) {
    fuzz::expect_clean([&] {
      TraceReader reader(path);
      reader.set_read_ahead(false);
      reader.read_chunk(0);
    });
    return;
  }
  // Texels: decoding the addresses alone (ReplayKinds::texel_details = false) fails cleanly or not
  // at all, and wherever the full decoding succeeds it succeeds with the same addresses. One
  // reader for both when the first succeeds, so the second decoding reuses its buffer; after a
  // failure a fresh reader, so that no state of the failure can hide a success.
  std::optional<TraceReader> reader;
  std::vector<TexelAccess> addresses;
  bool addresses_decoded = false;
  fuzz::expect_clean([&] {
    reader.emplace(path);
    reader->set_read_ahead(false);
    ReplayKinds kinds;
    kinds.texel_details = false;
    reader->set_read_ahead_kinds(kinds);
    addresses = reader->read_chunk(0).texels;
    addresses_decoded = true;
  });
  fuzz::expect_clean([&] {
    if (!addresses_decoded) reader.emplace(path);
    reader->set_read_ahead(false);
    reader->set_read_ahead_kinds(ReplayKinds{});
    const std::vector<TexelAccess>& full = reader->read_chunk(0).texels;
    if (!addresses_decoded || full.size() != addresses.size()) std::abort();
    for (std::size_t i = 0; i < full.size(); ++i) {
      const TexelAccess &a = addresses[i], &f = full[i];
      if (a.texture != f.texture || a.level != f.level || a.x != f.x || a.y != f.y || a.pixel_x != 0 ||
          a.pixel_y != 0 || a.triangle != 0)
        std::abort();
    }
  });
  // The decoder's SIMD kernels (traces/texel_lanes.h) and their portable paths, taken on machines
  // without AVX2: the same records or the same error.
  std::string error[2];
  std::vector<TexelAccess> decoded[2];
  for (int portable = 0; portable < 2; ++portable) {
    use_texel_lane_simd(portable == 0);
    try {
      TraceReader one(path);
      one.set_read_ahead(false);
      decoded[portable] = one.read_chunk(0).texels;
    } catch (const InputError& e) {
      error[portable] = e.what();
    }
  }
  use_texel_lane_simd(true);
  if (error[0] != error[1] || decoded[0].size() != decoded[1].size()) std::abort();
  for (std::size_t i = 0; i < decoded[0].size(); ++i) {
    const TexelAccess &a = decoded[0][i], &b = decoded[1][i];
    if (a.texture != b.texture || a.level != b.level || a.x != b.x || a.y != b.y || a.pixel_x != b.pixel_x ||
        a.pixel_y != b.pixel_y || a.triangle != b.triangle)
      std::abort();
  }
}

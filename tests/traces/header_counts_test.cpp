// .rtrace files whose chunks declare counts of records that cost no bytes: address chunks whose
// two columns are zero-width (every record equal), so a chunk of any count is 18 raw bytes. The
// stated limit is kMaxChunkRecords a chunk; a count past it is an InputError naming the file and
// the index entry, and chunks within it replay in a moment (docs/RELIABILITY.md, "Work bounded by
// the input").
#include <chrono>
#include <cstdint>
#include <string>

#include <gtest/gtest.h>
#include <zstd.h>

#include "core/error.h"
#include "support/temp_dir.h"
#include "traces/crc32c.h"
#include "traces/sink.h"
#include "traces/trace_format.h"
#include "traces/trace_metadata.h"
#include "traces/trace_reader.h"

namespace rastrace {
namespace {

std::string le(std::uint64_t value, int bytes) {
  std::string out;
  for (int i = 0; i < bytes; ++i) out += static_cast<char>(value >> (8 * i));
  return out;
}

// A finished trace of `chunks` address chunks of `records` equal records each (both columns of
// width 0: one value, no deltas), every checksum sound.
std::string zero_cost_trace(std::uint32_t records, int chunks) {
  std::string file(kTraceMagic, 8);
  file += le(kTraceVersion, 4);
  const std::string json = metadata_to_json(TraceMetadata{});
  file += le(json.size(), 4) + json + le(crc32c(json.data(), json.size()), 4);
  const std::string raw = le(0, 1) + le(0x1000, 8) + le(0, 1) + le(0, 8);  // address 0x1000, label 0
  std::string payload(ZSTD_compressBound(raw.size()), '\0');
  payload.resize(ZSTD_compress(payload.data(), payload.size(), raw.data(), raw.size(), 1));
  std::string index = le(kIndexTag, 4) + le(0, 4) + le(static_cast<std::uint64_t>(chunks), 8);
  for (int c = 0; c < chunks; ++c) {
    const std::uint64_t first = std::uint64_t{records} * static_cast<std::uint64_t>(c);
    index += le(file.size(), 8) + le(first, 8) + le(records, 4) + le(3, 1) + std::string(3, '\0');
    std::string header = le(kChunkTag, 4) + le(3, 1) + le(0, 1) + le(0, 2) + le(records, 4) + le(payload.size(), 4) +
                         le(raw.size(), 4) + le(first, 8);
    header += le(crc32c(payload.data(), payload.size(), crc32c(header.data(), header.size())), 4);
    file += header + payload;
  }
  const std::uint64_t index_offset = file.size();
  file += index + le(index_offset, 8) + le(crc32c(index.data(), index.size()), 4) + le(0, 4);
  file.append(kTraceEndMagic, 8);
  return file;
}

struct CountingSink : EventSink {
  std::uint64_t addresses = 0;
  void address_accesses(std::span<const AddressAccess> a) override { addresses += a.size(); }
};

TEST(TraceHeaderCounts, ChunksOfZeroCostRecordsWithinTheLimitReplayInAMoment) {
  testing::TempDir dir;
  const std::string file = zero_cost_trace(kMaxChunkRecords, 4);
  const std::string path = dir.write("zero.rtrace", file);
  const auto start = std::chrono::steady_clock::now();
  TraceReader reader(path);
  CountingSink sink;
  replay_trace(reader, sink);
  EXPECT_EQ(sink.addresses, 4u * kMaxChunkRecords);
  EXPECT_LT(file.size(), 512u);  // 4 Mi records in under 512 bytes: the limit is the bound
  // 0.1-0.3 s in Release; generous for sanitizers and a loaded machine, far under a loop that
  // trusted a count of 2^32 records.
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 20.0);
}

TEST(TraceHeaderCounts, ACountPastTheChunkLimitIsAnErrorNamingTheFileAndTheIndexEntry) {
  testing::TempDir dir;
  for (const std::uint32_t records : {kMaxChunkRecords + 1, 0x80000000u, 0xFFFFFFFFu}) {
    const std::string path = dir.write("over.rtrace", zero_cost_trace(records, 1));
    try {
      TraceReader reader(path);
      ADD_FAILURE() << records << " records: accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("chunk index entry 0 is invalid"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace rastrace

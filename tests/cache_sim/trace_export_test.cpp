// Trace interchange: a rendered trace exported as Dinero IV extended din sweeps identically when
// read back; its libCacheSim oracleGeneral export holds the same block stream with correct next
// accesses; extended din import checks its size field.
#include <fstream>
#include <string>
#include <unordered_map>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cache_sim/byte_cache.h"
#include "cache_sim/trace_export.h"
#include "core/error.h"
#include "support/run_rastrace.h"
#include "support/temp_dir.h"
#include "traces/text_formats.h"

namespace rastrace {
namespace {

using ::testing::HasSubstr;

std::string rendered_bunny(const testing::TempDir& dir) {
  const std::string trace = dir.file("bunny.rtrace");
  const testing::CommandRun r = testing::run_rastrace(
      {"render", "builtin:bunny", "--size", "192x192", "-o", dir.file("bunny.png"), "--trace", trace});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return trace;
}

nlohmann::json sweep(const std::vector<std::string>& arguments) {
  const testing::CommandRun r = testing::run_rastrace(arguments);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return nlohmann::json::parse(r.out);
}

TEST(TraceExport, ExtendedDinOfATextureTraceSweepsIdenticallyToTheTrace) {
  const testing::TempDir dir;
  const std::string trace = rendered_bunny(dir);
  const testing::CommandRun convert =
      testing::run_rastrace({"trace", "convert", trace, dir.file("bunny.din"), "--layout", "block4"});
  ASSERT_EQ(convert.exit_code, 0) << convert.err;
  const std::string caches = "size=1KiB..16KiB,line=32B/64B,assoc=1/4/full,policy=fifo/lru/opt";
  const nlohmann::json ours = sweep({"sweep", trace, "--cache", caches + ",layout=block4", "--format", "json"});
  const nlohmann::json theirs = sweep({"sweep", dir.file("bunny.din"), "--cache", caches, "--format", "json"});
  ASSERT_EQ(ours.size(), 5u * 2 * 3 * 3);
  ASSERT_EQ(theirs.size(), ours.size());
  for (std::size_t i = 0; i < ours.size(); ++i) {
    for (const char* key : {"size_bytes", "line_bytes", "assoc", "policy", "accesses", "misses", "bytes_fetched",
                            "compulsory", "capacity", "conflict"})
      EXPECT_EQ(ours[i].at(key), theirs[i].at(key)) << "row " << i << " " << key;
  }
  EXPECT_GT(ours[0].at("accesses").get<std::uint64_t>(), 50000u);
  // Every line is "0 address size" with the texel size.
  std::ifstream din(dir.file("bunny.din"));
  std::string first;
  std::getline(din, first);
  EXPECT_THAT(first, ::testing::MatchesRegex("0 [0-9a-f]+ 4"));
}

TEST(TraceExport, LibCacheSimRecordsCarryTheBlockStreamAndItsNextAccesses) {
  const testing::TempDir dir;
  const std::string trace = rendered_bunny(dir);
  const std::string out = dir.file("bunny.oracleGeneral.bin");
  const testing::CommandRun convert =
      testing::run_rastrace({"trace", "convert", trace, out, "--layout", "morton", "--block", "64B"});
  ASSERT_EQ(convert.exit_code, 0) << convert.err;
  AddressExportSpec spec;
  spec.layout = parse_layout("morton");
  const std::vector<std::uint64_t> addresses = trace_addresses(trace, spec);
  const std::vector<LibCacheSimRecord> records = read_libcachesim(out);
  ASSERT_EQ(records.size(), addresses.size());
  std::unordered_map<std::uint64_t, std::size_t> last;  // block -> its latest access so far
  for (std::size_t i = 0; i < records.size(); ++i) {
    ASSERT_EQ(records[i].time, i);
    ASSERT_EQ(records[i].object, addresses[i] / 64);
    ASSERT_EQ(records[i].size, 64u);
    if (const auto found = last.find(records[i].object); found != last.end()) {
      ASSERT_EQ(records[found->second].next_access, static_cast<std::int64_t>(i));
    }
    last[records[i].object] = i;
  }
  for (const auto& [block, at] : last) EXPECT_EQ(records[at].next_access, -1) << block;

  // A fully associative LRU cache over the objects is the texel sweep's row.
  CacheConfig config;
  config.size_bytes = 8192;
  config.line_bytes = 64;
  config.assoc = 0;
  ByteCache objects(config);
  for (const LibCacheSimRecord& r : records) objects.access_line(r.object);
  const nlohmann::json row = sweep({"sweep", trace, "--cache", "size=8KiB,line=64B,assoc=full,policy=lru,layout=morton",
                                    "--format", "json"});
  EXPECT_EQ(row[0].at("misses").get<std::uint64_t>(), objects.misses());
}

TEST(TraceExport, ExtendedDinImportChecksTheSizeField) {
  const testing::TempDir dir;
  const std::string din = dir.file("ext.din");
  {
    std::ofstream out(din);
    out << "0 1000 4\n1 2000 40\n2 3000\n";
  }
  struct Count final : EventSink {
    std::vector<AddressAccess> seen;
    void address_accesses(std::span<const AddressAccess> a) override { seen.insert(seen.end(), a.begin(), a.end()); }
  } count;
  EXPECT_EQ(import_din(din, count), 3u);
  EXPECT_EQ(count.seen[1].address, 0x2000u);
  EXPECT_EQ(count.seen[1].label, 1);
  {
    std::ofstream out(din);
    out << "0 1000 4\n0 1040 0\n";
  }
  try {
    import_din(din, count);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_THAT(std::string(e.what()), HasSubstr("ext.din:2: size 0"));
  }
  {
    std::ofstream out(din);
    out << "0 1000 4 extra\n";
  }
  EXPECT_THROW(import_din(din, count), InputError);
  EXPECT_THROW(read_libcachesim(din), InputError);  // 16 bytes: not a whole record
}

}  // namespace
}  // namespace rastrace

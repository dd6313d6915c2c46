#include "cache_sim/trace_export.h"

#include <bit>
#include <cstdio>
#include <fstream>
#include <ostream>
#include <unordered_map>

#include "core/error.h"
#include "traces/replay_file.h"

namespace rastrace {

namespace {

// Collects the addresses of one kind of record.
class AddressCollector final : public EventSink {
 public:
  AddressCollector(const AddressExportSpec& spec, const TextureLevels& textures)
      : spec_(spec), layout_(spec.layout, textures) {}

  void begin_draw(const DrawInfo& draw) override { draw_ = draw.draw; }
  void vertex_fetches(std::span<const VertexFetch> fetches) override {
    if (!spec_.vertices) return;
    const std::uint64_t base = std::uint64_t{draw_} << 40;
    for (const VertexFetch& f : fetches) addresses.push_back(base + std::uint64_t{f.vertex} * spec_.stride);
  }
  void texel_accesses(std::span<const TexelAccess> accesses) override {
    if (spec_.vertices) return;
    for (const TexelAccess& t : accesses) {
      if (!layout_.contains(t.texture, t.level, t.x, t.y))
        throw InputError("texel access (texture " + std::to_string(t.texture) + ", level " + std::to_string(t.level) +
                         ", x " + std::to_string(t.x) + ", y " + std::to_string(t.y) +
                         ") lies outside the textures the trace metadata lists");
      addresses.push_back(layout_.address(t.texture, t.level, t.x, t.y));
    }
  }
  void address_accesses(std::span<const AddressAccess> accesses) override {
    for (const AddressAccess& a : accesses) addresses.push_back(a.address);
  }

  std::vector<std::uint64_t> addresses;

 private:
  AddressExportSpec spec_;
  TextureLayout layout_;
  std::uint32_t draw_ = 0;
};

void put_le(std::string& out, std::uint64_t value, int bytes) {
  for (int i = 0; i < bytes; ++i) out.push_back(static_cast<char>((value >> (8 * i)) & 0xFF));
}

std::uint64_t get_le(const unsigned char* in, int bytes) {
  std::uint64_t v = 0;
  for (int i = 0; i < bytes; ++i) v |= std::uint64_t{in[i]} << (8 * i);
  return v;
}

constexpr std::size_t kRecordBytes = 24;

}  // namespace

std::vector<std::uint64_t> trace_addresses(const std::string& trace, const AddressExportSpec& spec) {
  const TraceSummary summary = summarize_trace(trace);
  if (spec.vertices && spec.stride == 0) throw InputError("vertex stride 0: expected at least 1 byte per vertex");
  AddressCollector collector(spec, summary.metadata.textures);
  ReplayKinds kinds;
  kinds.framebuffer = false;
  kinds.vertices = spec.vertices;
  kinds.texels = !spec.vertices;
  replay_file(trace, collector, kinds);
  if (collector.addresses.empty())
    throw_in_file(trace, std::string("no ") + (spec.vertices ? "vertex fetches" : "texel or address records") +
                             " to export");
  return std::move(collector.addresses);
}

std::uint32_t access_bytes(const AddressExportSpec& spec) {
  if (spec.vertices) return spec.stride;
  // A compressed layout's address is a block's first byte: the access is the whole block.
  if (spec.layout.format && is_compressed(*spec.layout.format)) return block_shape(*spec.layout.format).bytes;
  return spec.layout.texel_bytes;
}

void write_extended_din(const std::vector<std::uint64_t>& addresses, std::uint32_t size, std::ostream& out) {
  char line[64];
  for (const std::uint64_t a : addresses) {
    const int n = std::snprintf(line, sizeof line, "0 %llx %x\n", static_cast<unsigned long long>(a), size);
    out.write(line, n);
  }
}

void write_libcachesim(const std::vector<std::uint64_t>& addresses, std::uint32_t block_bytes, std::ostream& out) {
  if (block_bytes == 0 || !std::has_single_bit(block_bytes))
    throw InputError("libCacheSim export: block " + std::to_string(block_bytes) + " bytes: expected a power of two");
  const int shift = std::countr_zero(block_bytes);
  // Next use of each access's block: one backward pass.
  std::vector<std::int64_t> next(addresses.size(), -1);
  std::unordered_map<std::uint64_t, std::int64_t> later;
  later.reserve(addresses.size() / 4 + 16);
  for (std::size_t i = addresses.size(); i-- > 0;) {
    const std::uint64_t block = addresses[i] >> shift;
    const auto found = later.find(block);
    if (found != later.end()) next[i] = found->second;
    later[block] = static_cast<std::int64_t>(i);
  }
  std::string buffer;
  buffer.reserve(kRecordBytes * 4096);
  for (std::size_t i = 0; i < addresses.size(); ++i) {
    put_le(buffer, static_cast<std::uint32_t>(i), 4);
    put_le(buffer, addresses[i] >> shift, 8);
    put_le(buffer, block_bytes, 4);
    put_le(buffer, static_cast<std::uint64_t>(next[i]), 8);
    if (buffer.size() >= kRecordBytes * 4096) {
      out.write(buffer.data(), static_cast<std::streamsize>(buffer.size()));
      buffer.clear();
    }
  }
  out.write(buffer.data(), static_cast<std::streamsize>(buffer.size()));
}

std::vector<LibCacheSimRecord> read_libcachesim(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw_in_file(path, "cannot open for reading");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.size() % kRecordBytes != 0)
    throw_in_file(path, std::to_string(bytes.size()) + " bytes: expected a whole number of 24-byte oracleGeneral records");
  std::vector<LibCacheSimRecord> out(bytes.size() / kRecordBytes);
  const auto* p = reinterpret_cast<const unsigned char*>(bytes.data());
  for (std::size_t i = 0; i < out.size(); ++i, p += kRecordBytes) {
    out[i].time = static_cast<std::uint32_t>(get_le(p, 4));
    out[i].object = get_le(p + 4, 8);
    out[i].size = static_cast<std::uint32_t>(get_le(p + 12, 4));
    out[i].next_access = static_cast<std::int64_t>(get_le(p + 16, 8));
  }
  return out;
}

}  // namespace rastrace

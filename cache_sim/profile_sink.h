// LruProfileSink: the one-pass LRU profiles (lru_profile.h) of one address stream of a trace, as
// the byte caches of a LiveBankSink see it: texel accesses mapped to bytes by a texture layout,
// vertex fetches as vertex-buffer bytes (draw d's vertex v at (d << 40) + v * stride), or raw
// addresses. Every access feeds the fully associative stack profile (misses of every capacity at
// once) and, when `sets` is given, the set-associative profile (every associativity 1..max_ways
// of that many sets). Statistics are valid after finish().
// With `units` > 1 the texel stream is split among texture units by screen tile, as
// CacheHierarchy deals it out to its L1s (unit_of_pixel), and every unit has its own profiles:
// the sums are the misses of a hierarchy's first level at every size (or associativity) at once,
// since each L1 sees only its unit's accesses. Vertex and address streams carry no pixel and
// are refused with units > 1.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "cache_sim/lru_profile.h"
#include "cache_sim/sweep.h"
#include "cache_sim/texture_layout.h"
#include "traces/sink.h"

namespace rastrace {

struct LruProfileSpec {
  SweepSource source = SweepSource::Texel;
  std::uint32_t line_bytes = 64;  // a power of two
  LayoutSpec layout;              // texel source
  std::uint32_t stride = 32;      // vertex source: bytes per vertex
  std::uint64_t sets = 0;         // 0: no set-associative profile
  std::uint32_t max_ways = 16;
  std::uint32_t units = 1;  // texel source: L1 copies the stream is dealt out to
  std::uint32_t tile = 16;  // pixels: side of the screen tiles dealt out to the units
};

class LruProfileSink final : public EventSink {
 public:
  // Throws InputError on a line size that is not a power of two, a stride of 0, sets with
  // max_ways outside 1..1024, units outside 1..1024, a tile of 0, or units > 1 for a stream
  // other than texels. `textures`: every texture's level sizes (the trace metadata's).
  LruProfileSink(const LruProfileSpec& spec, TextureLevels textures);

  void begin_draw(const DrawInfo& draw) override { draw_ = draw.draw; }
  void vertex_fetches(std::span<const VertexFetch> fetches) override;
  void texel_accesses(std::span<const TexelAccess> accesses) override;
  void address_accesses(std::span<const AddressAccess> accesses) override;
  void end_draw() override {}
  void finish() override {}

  // Sums over the units.
  std::uint64_t accesses() const;
  std::uint64_t compulsory() const;
  // [d]: re-references at stack distance d.
  std::vector<std::uint64_t> histogram() const;
  // Misses of fully associative LRU caches of `lines` lines, one per unit.
  std::uint64_t misses(std::uint64_t lines) const;
  bool has_set_associative() const { return !set_assoc_.empty(); }
  // Misses of LRU caches of spec.sets sets and `ways` ways (1..max_ways), one per unit.
  std::uint64_t set_misses(std::uint32_t ways) const;

 private:
  void feed(std::uint64_t address, std::uint32_t unit = 0) {
    const std::uint64_t line = address >> line_shift_;
    stack_[unit].access(line);
    if (!set_assoc_.empty()) set_assoc_[unit].access(line);
  }

  LruProfileSpec spec_;
  std::uint32_t line_shift_ = 6;
  std::optional<TextureLayout> layout_;
  std::size_t texture_count_ = 0;
  std::uint32_t draw_ = 0;
  std::vector<LruStackProfile> stack_;        // one per unit
  std::vector<SetAssocLruProfile> set_assoc_;  // one per unit, empty without sets
};

}  // namespace rastrace

// LruProfileSink: the one-pass LRU profiles (lru_profile.h) of one address stream of a trace, as
// the byte caches of a LiveBankSink see it: texel accesses mapped to bytes by a texture layout,
// vertex fetches as vertex-buffer bytes (draw d's vertex v at (d << 40) + v * stride), or raw
// addresses. Every access feeds the fully associative stack profile (misses of every capacity at
// once) and, when `sets` is given, the set-associative profile (every associativity 1..max_ways
// of that many sets). Statistics are valid after finish().
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
};

class LruProfileSink final : public EventSink {
 public:
  // Throws InputError on a line size that is not a power of two, a stride of 0, or sets with
  // max_ways outside 1..1024. `textures`: every texture's level sizes (the trace metadata's).
  LruProfileSink(const LruProfileSpec& spec, TextureLevels textures);

  void begin_draw(const DrawInfo& draw) override { draw_ = draw.draw; }
  void vertex_fetches(std::span<const VertexFetch> fetches) override;
  void texel_accesses(std::span<const TexelAccess> accesses) override;
  void address_accesses(std::span<const AddressAccess> accesses) override;
  void end_draw() override {}
  void finish() override {}

  const LruStackProfile& stack() const { return stack_; }
  // Null without `sets`.
  const SetAssocLruProfile* set_associative() const { return set_assoc_ ? &*set_assoc_ : nullptr; }

 private:
  void feed(std::uint64_t address) {
    const std::uint64_t line = address >> line_shift_;
    stack_.access(line);
    if (set_assoc_) set_assoc_->access(line);
  }

  LruProfileSpec spec_;
  std::uint32_t line_shift_ = 6;
  std::optional<TextureLayout> layout_;
  std::size_t texture_count_ = 0;
  std::uint32_t draw_ = 0;
  LruStackProfile stack_;
  std::optional<SetAssocLruProfile> set_assoc_;
};

}  // namespace rastrace

#include "cache_sim/profile_sink.h"

#include <bit>
#include <string>

#include "core/error.h"

namespace rastrace {

LruProfileSink::LruProfileSink(const LruProfileSpec& spec, TextureLevels textures)
    : spec_(spec), texture_count_(textures.size()) {
  if (spec.line_bytes == 0 || !std::has_single_bit(spec.line_bytes))
    throw InputError("line " + std::to_string(spec.line_bytes) + " B: expected a power of two");
  line_shift_ = static_cast<std::uint32_t>(std::countr_zero(spec.line_bytes));
  if (spec.source == SweepSource::VertexBuffer && spec.stride == 0)
    throw InputError("vertex buffer stride 0: expected at least 1 byte per vertex");
  if (spec.sets) {
    if (spec.max_ways == 0 || spec.max_ways > 1024)
      throw InputError("max_ways " + std::to_string(spec.max_ways) + ": expected 1..1024");
    set_assoc_.emplace(spec.sets, spec.max_ways);
  }
  if (spec.source == SweepSource::Texel) layout_.emplace(spec.layout, textures);
}

void LruProfileSink::vertex_fetches(std::span<const VertexFetch> fetches) {
  if (spec_.source != SweepSource::VertexBuffer) return;
  const std::uint64_t base = std::uint64_t{draw_} << 40;
  for (const VertexFetch& f : fetches) feed(base + std::uint64_t{f.vertex} * spec_.stride);
}

void LruProfileSink::texel_accesses(std::span<const TexelAccess> accesses) {
  if (spec_.source != SweepSource::Texel) return;
  for (const TexelAccess& t : accesses) {
    if (!layout_->contains(t.texture, t.level, t.x, t.y)) [[unlikely]]
      throw InputError("texel access (texture " + std::to_string(t.texture) + ", level " + std::to_string(t.level) +
                       ", x " + std::to_string(t.x) + ", y " + std::to_string(t.y) +
                       ") lies outside the " + std::to_string(texture_count_) +
                       " texture(s) whose level sizes the trace metadata lists");
    feed(layout_->address(t.texture, t.level, t.x, t.y));
  }
}

void LruProfileSink::address_accesses(std::span<const AddressAccess> accesses) {
  if (spec_.source != SweepSource::Address) return;
  for (const AddressAccess& a : accesses) feed(a.address);
}

}  // namespace rastrace

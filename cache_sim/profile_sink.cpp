#include "cache_sim/profile_sink.h"

#include <bit>
#include <string>

#include "cache_sim/cache_hierarchy.h"
#include "core/error.h"

namespace rastrace {

LruProfileSink::LruProfileSink(const LruProfileSpec& spec, TextureLevels textures)
    : spec_(spec), texture_count_(textures.size()) {
  if (spec.line_bytes == 0 || !std::has_single_bit(spec.line_bytes))
    throw InputError("line " + std::to_string(spec.line_bytes) + " B: expected a power of two");
  line_shift_ = static_cast<std::uint32_t>(std::countr_zero(spec.line_bytes));
  if (spec.source == SweepSource::VertexBuffer && spec.stride == 0)
    throw InputError("vertex buffer stride 0: expected at least 1 byte per vertex");
  if (spec.units == 0 || spec.units > 1024)
    throw InputError("units " + std::to_string(spec.units) + ": expected 1..1024 texture units");
  if (spec.tile == 0) throw InputError("tile 0: expected a screen tile of at least 1 pixel");
  if (spec.units > 1 && spec.source != SweepSource::Texel)
    throw InputError("units " + std::to_string(spec.units) + " with the " + to_string(spec.source) +
                     " stream: only texel accesses carry the pixel that picks a unit");
  stack_.resize(spec.units);
  if (spec.sets) {
    if (spec.max_ways == 0 || spec.max_ways > 1024)
      throw InputError("max_ways " + std::to_string(spec.max_ways) + ": expected 1..1024");
    for (std::uint32_t u = 0; u < spec.units; ++u) set_assoc_.emplace_back(spec.sets, spec.max_ways);
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
    feed(layout_->address(t.texture, t.level, t.x, t.y),
         spec_.units == 1 ? 0 : CacheHierarchy::unit_of_pixel(t.pixel_x, t.pixel_y, spec_.tile, spec_.units));
  }
}

void LruProfileSink::address_accesses(std::span<const AddressAccess> accesses) {
  if (spec_.source != SweepSource::Address) return;
  for (const AddressAccess& a : accesses) feed(a.address);
}

std::uint64_t LruProfileSink::accesses() const {
  std::uint64_t n = 0;
  for (const LruStackProfile& s : stack_) n += s.accesses();
  return n;
}

std::uint64_t LruProfileSink::compulsory() const {
  std::uint64_t n = 0;
  for (const LruStackProfile& s : stack_) n += s.compulsory();
  return n;
}

std::vector<std::uint64_t> LruProfileSink::histogram() const {
  std::vector<std::uint64_t> sum;
  for (const LruStackProfile& s : stack_) {
    const std::vector<std::uint64_t>& h = s.histogram();
    if (h.size() > sum.size()) sum.resize(h.size(), 0);
    for (std::size_t d = 0; d < h.size(); ++d) sum[d] += h[d];
  }
  return sum;
}

std::uint64_t LruProfileSink::misses(std::uint64_t lines) const {
  std::uint64_t n = 0;
  for (const LruStackProfile& s : stack_) n += s.misses(lines);
  return n;
}

std::uint64_t LruProfileSink::set_misses(std::uint32_t ways) const {
  std::uint64_t n = 0;
  for (const SetAssocLruProfile& s : set_assoc_) n += s.misses(ways);
  return n;
}

}  // namespace rastrace

// HierarchySink: an EventSink that runs texel accesses (or a foreign trace's byte addresses)
// through cache hierarchies (cache_hierarchy.h), for `rastrace replay --level ...` and for
// sectored caches named with `--cache ...,sector=32B` (a one-level hierarchy).
//   texel accesses     mapped to bytes by each hierarchy's texture layout; the L1 unit is the
//                      one owning the fragment's screen tile (CacheHierarchy::unit_of_pixel)
//   address accesses   (din) go to unit 0: they carry no pixel
// Vertex and framebuffer events are ignored. Texel accesses outside the textures are InputErrors
// naming the record.
#pragma once

#include <cstdint>
#include <vector>

#include "cache_sim/cache_hierarchy.h"
#include "cache_sim/texture_layout.h"
#include "traces/sink.h"

namespace rastrace {

struct HierarchySpec {
  HierarchyConfig hierarchy;  // element_bytes is set from the layout's texel size
  LayoutSpec layout;          // how texels become bytes (texel accesses only)
};

class HierarchySink final : public EventSink {
 public:
  // Throws InputError on an invalid hierarchy or layout.
  HierarchySink(const std::vector<HierarchySpec>& specs, const TextureLevels& textures);

  void texel_accesses(std::span<const TexelAccess> accesses) override;
  void address_accesses(std::span<const AddressAccess> accesses) override;

  std::size_t size() const { return hierarchies_.size(); }
  const CacheHierarchy& hierarchy(std::size_t i) const { return hierarchies_[i]; }
  std::uint64_t texel_records() const { return texel_records_; }

 private:
  std::vector<CacheHierarchy> hierarchies_;
  std::vector<TextureLayout> layouts_;
  std::uint64_t texel_records_ = 0;
};

}  // namespace rastrace

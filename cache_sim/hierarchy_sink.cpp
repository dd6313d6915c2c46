#include "cache_sim/hierarchy_sink.h"

#include "core/error.h"

namespace rastrace {

HierarchySink::HierarchySink(const std::vector<HierarchySpec>& specs, const TextureLevels& textures) {
  hierarchies_.reserve(specs.size());
  for (const HierarchySpec& spec : specs) {
    HierarchyConfig config = spec.hierarchy;
    config.element_bytes = spec.layout.texel_bytes;
    hierarchies_.emplace_back(std::move(config));
    layouts_.emplace_back(spec.layout, textures);
    // Decoded addresses scale compressed ones by the format's ratio: two ratios would overlap
    // textures in the decoded space.
    const TextureLayout& layout = layouts_.back();
    for (std::uint32_t t = 1; spec.hierarchy.decoded_l1 && t < textures.size(); ++t)
      if (layout.decode_shift(t) != layout.decode_shift(0))
        throw InputError(std::string("--decoded-l1: the trace's textures are stored as ") +
                         to_string(layout.format(0)) + " and " + to_string(layout.format(t)) +
                         ", which decode at different ratios: name one format for all with the L1's format=");
  }
}

void HierarchySink::texel_accesses(std::span<const TexelAccess> accesses) {
  texel_records_ += accesses.size();
  for (std::size_t h = 0; h < hierarchies_.size(); ++h) {
    CacheHierarchy& hierarchy = hierarchies_[h];
    const TextureLayout& layout = layouts_[h];
    const bool decoded = hierarchy.config().decoded_l1;
    for (const TexelAccess& t : accesses) {
      if (!layout.contains(t.texture, t.level, t.x, t.y)) [[unlikely]]
        throw InputError("texel access (texture " + std::to_string(t.texture) + ", level " + std::to_string(t.level) +
                         ", x " + std::to_string(t.x) + ", y " + std::to_string(t.y) + ", triangle " +
                         std::to_string(t.triangle) + ") lies outside the textures whose level sizes the trace " +
                         "metadata lists");
      const std::uint32_t unit = hierarchy.unit_of_pixel(t.pixel_x, t.pixel_y);
      if (decoded)
        hierarchy.access(layout.decoded_address(t.texture, t.level, t.x, t.y), unit, layout.decode_shift(t.texture));
      else
        hierarchy.access(layout.address(t.texture, t.level, t.x, t.y), unit);
    }
  }
}

void HierarchySink::address_accesses(std::span<const AddressAccess> accesses) {
  for (CacheHierarchy& hierarchy : hierarchies_)
    for (const AddressAccess& a : accesses) hierarchy.access(a.address, 0);
}

}  // namespace rastrace

#include "cache_sim/texture_layout.h"

#include <algorithm>
#include <bit>

#include "core/error.h"

namespace rastrace {

LayoutSpec parse_layout(const std::string& text) {
  // "block4:bc1" is a layout with its storage format, as layout_name() prints it.
  const std::size_t colon = text.find(':');
  const std::string name = text.substr(0, colon);
  LayoutSpec spec;
  if (colon != std::string::npos)
    spec.format = parse_texture_format(std::string_view(text).substr(colon + 1), "texture layout '" + text + "' format");
  if (name == "linear") {
    spec.kind = LayoutKind::Linear;
  } else if (name == "morton") {
    spec.kind = LayoutKind::Morton;
  } else if (name == "block2" || name == "block4" || name == "block8" || name == "block16") {
    spec.kind = LayoutKind::Block;
    spec.block = static_cast<std::uint32_t>(std::stoul(name.substr(5)));
  } else {
    throw InputError("unknown texture layout '" + name +
                     "': expected linear, block2, block4, block8, block16 or morton");
  }
  return spec;
}

std::string layout_name(const LayoutSpec& spec) {
  const std::string format = spec.format ? std::string(":") + to_string(*spec.format) : "";
  switch (spec.kind) {
    case LayoutKind::Linear:
      return "linear" + format;
    case LayoutKind::Block:
      return "block" + std::to_string(spec.block) + format;
    default:
      return "morton" + format;
  }
}

std::vector<LevelSize> mip_chain_sizes(std::uint32_t width, std::uint32_t height) {
  std::vector<LevelSize> levels;
  if (width == 0 || height == 0) return levels;
  while (true) {
    levels.push_back({width, height});
    if (width == 1 && height == 1) break;
    width = std::max(1u, width / 2);
    height = std::max(1u, height / 2);
  }
  return levels;
}

TextureLayout::TextureLayout(const LayoutSpec& spec, const TextureLevels& textures) : spec_(spec) {
  if (!std::has_single_bit(spec.texel_bytes) || spec.texel_bytes > 16)
    throw InputError("texel size " + std::to_string(spec.texel_bytes) + " bytes: expected 1, 2, 4, 8 or 16");
  if (!std::has_single_bit(spec.alignment) || spec.alignment < spec.texel_bytes)
    throw InputError("level alignment " + std::to_string(spec.alignment) +
                     " bytes: expected a power of two of at least the texel size");
  if (spec.kind == LayoutKind::Block && (spec.block < 2 || spec.block > 16 || !std::has_single_bit(spec.block)))
    throw InputError("block size " + std::to_string(spec.block) + ": expected 2, 4, 8 or 16");
  texel_shift_ = static_cast<std::uint32_t>(std::countr_zero(spec.texel_bytes));
  block_shift_ = spec.kind == LayoutKind::Block ? static_cast<std::uint32_t>(std::countr_zero(spec.block)) : 0;

  std::uint64_t next = 0;
  for (std::size_t t = 0; t < textures.size(); ++t) {
    first_level_.push_back(static_cast<std::uint32_t>(levels_.size()));
    for (std::size_t i = 0; i < textures[t].size(); ++i) {
      const LevelSize size = textures[t][i];
      if (size.width == 0 || size.height == 0)
        throw InputError("texture " + std::to_string(t) + " level " + std::to_string(i) + " has size " +
                         std::to_string(size.width) + "x" + std::to_string(size.height) + ": expected at least 1x1");
      Level level;
      level.width = size.width;
      level.height = size.height;
      level.format = spec.format.value_or(size.format);
      const BlockShape shape = block_shape(level.format);
      if (is_compressed(level.format)) {
        if (spec.alignment < shape.bytes)
          throw InputError("level alignment " + std::to_string(spec.alignment) + " bytes: a " +
                           to_string(level.format) + " texture needs at least its " + std::to_string(shape.bytes) +
                           "-byte blocks");
        level.unit_shift_x = static_cast<std::uint32_t>(std::countr_zero(shape.width));
        level.unit_shift_y = static_cast<std::uint32_t>(std::countr_zero(shape.height));
        level.unit_bytes_shift = static_cast<std::uint32_t>(std::countr_zero(shape.bytes));
        const std::uint64_t decoded = std::uint64_t{shape.width} * shape.height * spec.texel_bytes;
        level.decode_shift = static_cast<std::uint32_t>(std::countr_zero(decoded) - std::countr_zero(shape.bytes));
      } else {
        level.unit_bytes_shift = texel_shift_;
      }
      // The grid of units the layout orders: texels, or blocks with partial edge blocks counted whole.
      const std::uint32_t units_w = ((size.width - 1) >> level.unit_shift_x) + 1;
      const std::uint32_t units_h = ((size.height - 1) >> level.unit_shift_y) + 1;
      level.units_per_row = units_w;
      std::uint64_t units = 0;
      switch (spec.kind) {
        case LayoutKind::Linear:
          units = std::uint64_t{units_w} * units_h;
          break;
        case LayoutKind::Block: {
          level.blocks_per_row = (units_w + spec.block - 1) >> block_shift_;
          const std::uint64_t rows = (units_h + spec.block - 1) >> block_shift_;
          units = (rows * level.blocks_per_row) << (2 * block_shift_);
          break;
        }
        default: {
          const std::uint32_t wb = static_cast<std::uint32_t>(std::bit_width(std::bit_ceil(units_w)) - 1);
          const std::uint32_t hb = static_cast<std::uint32_t>(std::bit_width(std::bit_ceil(units_h)) - 1);
          level.square_bits = std::min(wb, hb);
          units = std::uint64_t{1} << (wb + hb);
          break;
        }
      }
      next = (next + spec.alignment - 1) & ~(spec.alignment - 1);
      level.base = next;
      next += units << level.unit_bytes_shift;
      levels_.push_back(level);
    }
  }
  first_level_.push_back(static_cast<std::uint32_t>(levels_.size()));
  total_bytes_ = next;
}

}  // namespace rastrace

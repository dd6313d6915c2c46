// The event stream: the seam between the renderer and the cache simulator (DESIGN.md).
// Events carry logical ids (vertex ids, texel coordinates), never byte addresses: memory
// layouts are applied at replay.
#pragma once

#include <cstdint>

#include "core/index_stream.h"

namespace rastrace {

// Starts a draw call; its vertex fetches follow.
struct DrawInfo {
  std::uint32_t draw = 0;  // draw number within the frame
  PrimitiveType type = PrimitiveType::TriangleList;
  RestartIndex restart_index = kNoRestart;  // TriangleStrip only: the primitive-restart index, if any
};

// One index of the index stream, in submission order. A strip's restart index is not a fetch:
// it appears as primitive_start on the next fetch.
struct VertexFetch {
  std::uint32_t vertex = 0;
  // Set on the first index of each primitive: every triangle of a list, every strip, every
  // 6-index adjacency primitive. Lets a replay rebuild the primitives (and skip degenerates).
  bool primitive_start = false;
};

// One texel read by the sampler. 16 bytes: a trilinear frame records millions of reads, and with
// 32-bit texture numbers and coordinates (24 bytes) tracing the grazing plane to memory was
// bound by writing them. Texture numbers and texel coordinates are therefore below 65536: the
// renderer accepts at most kMaxTracedTextures textures, each at most kMaxTextureSide
// (scenes/texture.h) texels a side, and the trace reader rejects larger values.
inline constexpr std::uint32_t kMaxTracedTextures = 65536;
struct TexelAccess {
  std::uint16_t texture = 0;
  std::uint8_t level = 0;  // one padding byte follows, written 0 by the recorder and decoder
  std::uint16_t x = 0;     // texel column, 0 at the left
  std::uint16_t y = 0;     // texel row, 0 at the top of the image
  std::uint16_t pixel_x = 0;
  std::uint16_t pixel_y = 0;
  std::uint32_t triangle = 0;  // the drawn triangle's number within the frame
};

// A framebuffer access by the fragments of one 2x2 quad. Logical, like texels: pixel coordinates,
// never byte addresses; the depth and colour buffer layouts are applied at replay.
enum class FramebufferOp : std::uint8_t {
  DepthRead = 0,    // the depth test reads the stored depths
  DepthWrite = 1,   // the fragments that passed write their depths
  ColourWrite = 2,  // and their colours
};
inline constexpr std::uint8_t kFramebufferOps = 3;

struct FramebufferAccess {
  std::uint16_t x = 0;  // the quad's top-left pixel (even coordinates)
  std::uint16_t y = 0;
  FramebufferOp op = FramebufferOp::DepthRead;
  std::uint8_t mask = 0;       // the pixels concerned: bit 0 (x, y), 1 (x+1, y), 2 (x, y+1), 3 (x+1, y+1)
  std::uint32_t triangle = 0;  // the drawn triangle's number within the frame
};

// One byte-address access from a foreign trace (Dinero IV din: label 0 read, 1 write, 2
// instruction fetch). rastrace's own traces record logical ids instead.
struct AddressAccess {
  std::uint64_t address = 0;
  std::uint8_t label = 0;
};

}  // namespace rastrace

#include "traces/memory_sink.h"

namespace rastrace {

void MemorySink::clear() {
  draws.clear();
  draw_first_fetch.clear();
  fetches.clear();
  texels.clear();
  framebuffer.clear();
}

void MemorySink::begin_draw(const DrawInfo& draw) {
  draws.push_back(draw);
  draw_first_fetch.push_back(fetches.size());
}

void MemorySink::vertex_fetches(std::span<const VertexFetch> batch) {
  fetches.insert(fetches.end(), batch.begin(), batch.end());
}

void MemorySink::texel_accesses(std::span<const TexelAccess> batch) {
  texels.insert(texels.end(), batch.begin(), batch.end());
}

void MemorySink::framebuffer_accesses(std::span<const FramebufferAccess> batch) {
  framebuffer.insert(framebuffer.end(), batch.begin(), batch.end());
}

}  // namespace rastrace

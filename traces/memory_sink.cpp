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
  // A fetch span may be out across begin_draw (the protocol allows it): its slots are not fetches.
  draw_first_fetch.push_back(fetches.size() - fetches_lent_.lent());
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

std::span<VertexFetch> MemorySink::vertex_slots(std::size_t count) { return fetches_lent_.lend(fetches, count); }
void MemorySink::commit_vertices(std::size_t used) { fetches_lent_.commit(fetches, used); }
std::span<TexelAccess> MemorySink::texel_slots(std::size_t count) { return texels_lent_.lend(texels, count); }
void MemorySink::commit_texels(std::size_t used) { texels_lent_.commit(texels, used); }
std::span<FramebufferAccess> MemorySink::framebuffer_slots(std::size_t count) {
  return framebuffer_lent_.lend(framebuffer, count);
}
void MemorySink::commit_framebuffer(std::size_t used) { framebuffer_lent_.commit(framebuffer, used); }

}  // namespace rastrace

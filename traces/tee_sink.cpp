#include "traces/tee_sink.h"

namespace rastrace {

void TeeSink::begin_frame(std::uint32_t frame) {
  for (EventSink* sink : sinks_) sink->begin_frame(frame);
}
void TeeSink::begin_draw(const DrawInfo& draw) {
  for (EventSink* sink : sinks_) sink->begin_draw(draw);
}
void TeeSink::vertex_fetches(std::span<const VertexFetch> fetches) {
  for (EventSink* sink : sinks_) sink->vertex_fetches(fetches);
}
void TeeSink::texel_accesses(std::span<const TexelAccess> accesses) {
  for (EventSink* sink : sinks_) sink->texel_accesses(accesses);
}
void TeeSink::framebuffer_accesses(std::span<const FramebufferAccess> accesses) {
  for (EventSink* sink : sinks_) sink->framebuffer_accesses(accesses);
}
bool TeeSink::wants_framebuffer_events() const {
  for (const EventSink* sink : sinks_)
    if (sink->wants_framebuffer_events()) return true;
  return false;
}
void TeeSink::end_draw() {
  for (EventSink* sink : sinks_) sink->end_draw();
}
void TeeSink::address_accesses(std::span<const AddressAccess> accesses) {
  for (EventSink* sink : sinks_) sink->address_accesses(accesses);
}
void TeeSink::finish() {
  for (EventSink* sink : sinks_) sink->finish();
}

}  // namespace rastrace

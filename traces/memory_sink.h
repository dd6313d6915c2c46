// An in-memory sink: keeps every event, for tests and for replaying without a file.
// The event vectors are backed by huge pages once they pass 2 MiB (core/huge_page_allocator.h):
// a frame's tens of megabytes of events then cost a few dozen page faults, not thousands. Keep
// one sink across frames and clear() it: the capacity stays, and later frames fault not at all.
// It lends storage (sink.h): the recorders write events straight into these vectors, with
// streaming stores where they can.
#pragma once

#include <vector>

#include "core/huge_page_allocator.h"
#include "traces/event_window.h"
#include "traces/sink.h"

namespace rastrace {

class MemorySink final : public EventSink {
 public:
  void begin_draw(const DrawInfo& draw) override;
  void vertex_fetches(std::span<const VertexFetch> fetches) override;
  void texel_accesses(std::span<const TexelAccess> accesses) override;
  void framebuffer_accesses(std::span<const FramebufferAccess> accesses) override;
  bool wants_framebuffer_events() const override { return true; }

  bool lends_storage() const override { return true; }
  bool streams_lent_storage() const override { return true; }
  std::span<VertexFetch> vertex_slots(std::size_t count) override;
  void commit_vertices(std::size_t used) override;
  std::span<TexelAccess> texel_slots(std::size_t count) override;
  void commit_texels(std::size_t used) override;
  std::span<FramebufferAccess> framebuffer_slots(std::size_t count) override;
  void commit_framebuffer(std::size_t used) override;

  template <typename Event>
  using Events = std::vector<Event, UnsetHugePageAllocator<Event>>;

  // Forgets every event and keeps the capacity.
  void clear();

  std::vector<DrawInfo> draws;
  std::vector<std::size_t> draw_first_fetch;  // index into fetches where each draw starts
  Events<VertexFetch> fetches;
  Events<TexelAccess> texels;
  Events<FramebufferAccess> framebuffer;

 private:
  VectorLender<Events<VertexFetch>> fetches_lent_;
  VectorLender<Events<TexelAccess>> texels_lent_;
  VectorLender<Events<FramebufferAccess>> framebuffer_lent_;
};

}  // namespace rastrace

// An event sink that forwards every event to two sinks, e.g. a live cache bank and a trace writer
// fed by the same render.
#pragma once

#include <span>

#include "traces/sink.h"

namespace rastrace::testing {

class TeeSink final : public EventSink {
 public:
  TeeSink(EventSink& a, EventSink& b) : a_(a), b_(b) {}
  void begin_draw(const DrawInfo& d) override { a_.begin_draw(d), b_.begin_draw(d); }
  void vertex_fetches(std::span<const VertexFetch> f) override { a_.vertex_fetches(f), b_.vertex_fetches(f); }
  void texel_accesses(std::span<const TexelAccess> t) override { a_.texel_accesses(t), b_.texel_accesses(t); }
  void end_draw() override { a_.end_draw(), b_.end_draw(); }
  void address_accesses(std::span<const AddressAccess> x) override { a_.address_accesses(x), b_.address_accesses(x); }
  void finish() override { a_.finish(), b_.finish(); }

 private:
  EventSink& a_;
  EventSink& b_;
};

}  // namespace rastrace::testing

// Where a recorder stores events on their way to an EventSink. For a sink that lends storage
// (sink.h) the window is a span of the sink's own memory, committed when full or flushed, so an
// event is stored once; for any other sink it is a buffer of the window's own, handed over in
// batches of kCapacity events, exactly as the recorders always batched. Either way the hot loop
// stores an event and compares a count with a limit.
//
// A sink may also ask for its lent slots to be written with streaming stores (sink.h): a
// recorder that can asks streaming() and reserves with reserve_streamed(), and the window fences
// those stores before it commits, so that the sink, on whatever thread, reads the events.
//
// A lent span is asked for only when the first event after a flush arrives: that event is stored
// in the window's own buffer, and moved when the span comes. A sink is thus never left holding
// an open span between draws (a MemorySink read after flush() holds exactly its events).
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <exception>
#include <span>
#include <type_traits>

// Streaming stores of 8 and 16 bytes (SSE2 on x86-64); elsewhere every store is an ordinary one.
#if defined(__SSE2__) && defined(__x86_64__)
#include <emmintrin.h>
#define RASTRACE_STREAMING_STORES 1
#else
#define RASTRACE_STREAMING_STORES 0
#endif

#include "traces/sink.h"

namespace rastrace {

namespace sink_calls {
inline void deliver(EventSink& sink, std::span<const VertexFetch> events) { sink.vertex_fetches(events); }
inline void deliver(EventSink& sink, std::span<const TexelAccess> events) { sink.texel_accesses(events); }
inline void deliver(EventSink& sink, std::span<const FramebufferAccess> events) { sink.framebuffer_accesses(events); }
inline std::span<VertexFetch> lend(EventSink& sink, std::size_t count, std::type_identity<VertexFetch>) {
  return sink.vertex_slots(count);
}
inline std::span<TexelAccess> lend(EventSink& sink, std::size_t count, std::type_identity<TexelAccess>) {
  return sink.texel_slots(count);
}
inline std::span<FramebufferAccess> lend(EventSink& sink, std::size_t count, std::type_identity<FramebufferAccess>) {
  return sink.framebuffer_slots(count);
}
inline void commit(EventSink& sink, std::size_t used, std::type_identity<VertexFetch>) { sink.commit_vertices(used); }
inline void commit(EventSink& sink, std::size_t used, std::type_identity<TexelAccess>) { sink.commit_texels(used); }
inline void commit(EventSink& sink, std::size_t used, std::type_identity<FramebufferAccess>) {
  sink.commit_framebuffer(used);
}
}  // namespace sink_calls

// kSlack: events a caller may store past a full window in one go (a bilinear footprint's four
// texels are stored with one check); the batch then handed over is still exactly kCapacity.
template <typename Event, std::size_t kCapacity, std::size_t kSlack = 0>
class EventWindow {
 public:
  // sink may be nullptr: active() is then false and nothing may be stored.
  explicit EventWindow(EventSink* sink)
      : sink_(sink),
        lends_(sink && sink->lends_storage()),
        streams_(lends_ && sink->streams_lent_storage()),
        out_(nullptr),
        limit_(lends_ ? 1 : kCapacity) {
    out_ = buffer_.data();
  }
  EventWindow(const EventWindow&) = delete;
  EventWindow& operator=(const EventWindow&) = delete;
  // Destructors must not throw: while an error unwinds (a sink's write failed) the events are
  // dropped (a lent span is given back empty); a sink that fails here reports the failure again
  // from its finish().
  ~EventWindow() {
    try {
      if (std::uncaught_exceptions() == 0)
        flush();
      else if (lent())
        sink_calls::commit(*sink_, 0, kind());
    } catch (...) {
    }
  }

  bool active() const { return sink_ != nullptr; }
  // Room for kSlack + 1 events; store `count` (at most that) of them, then call stored().
  Event* reserve(std::size_t count) {
    Event* out = out_ + size_;
    size_ += count;
    prefetch(out);
    return out;
  }
  // Whether the slots reserve_streamed() gives are lent by a sink that wants streaming stores.
  bool streaming() const { return streaming_; }
  // As reserve(), for a caller that writes with streaming stores when streaming(): then without
  // the prefetch, which would fetch the very lines those stores avoid reading.
  Event* reserve_streamed(std::size_t count) {
    Event* out = out_ + size_;
    size_ += count;
    if (!streaming_) prefetch(out);
    return out;
  }
  // Inlined whatever the caller's size: called from the quad loop, a call would spill every
  // live vector register around it.
  [[gnu::always_inline]] void stored() {
    if (size_ >= limit_) [[unlikely]]
      overflow();
  }
  // Stores a run of events as one-by-one stores would: same batches, same calls to the sink.
  void append(std::span<const Event> events) {
    while (!events.empty()) {
      const std::size_t take = std::min(limit_ - size_, events.size());
      std::memcpy(static_cast<void*>(out_ + size_), events.data(), take * sizeof(Event));
      size_ += take;
      events = events.subspan(take);
      stored();
    }
  }
  // Hands the stored events to the sink: the rest of a batch, or a lent span's commit.
  void flush() {
    if (lent()) {
      commit_lent();
    } else if (!lends_ && size_) {
      const std::size_t used = size_;
      size_ = 0;
      sink_calls::deliver(*sink_, std::span<const Event>(buffer_.data(), used));
    }
  }

 private:
  static constexpr std::size_t kPrefetchBytes = 1024;
  static constexpr std::type_identity<Event> kind() { return {}; }
  // A lent span is memory the sink last wrote a frame ago, out of the caches: asking for its
  // lines a little ahead of the stores keeps the hot loop from waiting on each line's miss.
  // (Prefetching past the span's end is harmless: prefetches do not fault.)
  static void prefetch(const Event* out) { __builtin_prefetch(reinterpret_cast<const char*>(out) + kPrefetchBytes, 1); }
  bool lent() const { return out_ != buffer_.data(); }
  void idle() {
    out_ = buffer_.data();
    size_ = 0;
    limit_ = 1;
    streaming_ = false;
  }
  void commit_lent() {
    const std::size_t used = size_;
    idle();
#if RASTRACE_STREAMING_STORES
    // Streaming stores are weakly ordered: without the fence the sink's reader could see the
    // commit before the events.
    if (streams_) _mm_sfence();
#endif
    sink_calls::commit(*sink_, used, kind());
  }
  [[gnu::noinline]] void overflow() {
    if (!lends_) {
      sink_calls::deliver(*sink_, std::span<const Event>(buffer_.data(), kCapacity));
      size_ -= kCapacity;
      std::copy(buffer_.data() + kCapacity, buffer_.data() + kCapacity + size_, buffer_.data());
      return;
    }
    // Idle, with the first events since a flush in buffer_; or a full lent span to commit.
    std::size_t pending = size_;
    if (lent()) {
      commit_lent();
      pending = 0;
    }
    const std::span<Event> span = sink_calls::lend(*sink_, kCapacity + kSlack, kind());
    std::copy(buffer_.data(), buffer_.data() + pending, span.data());
    out_ = span.data();
    size_ = pending;
    limit_ = kCapacity;
    // Streaming stores take 8 and 16 bytes: spans of events that are not all 8-byte aligned are
    // written with ordinary stores.
    streaming_ = RASTRACE_STREAMING_STORES && streams_ && sizeof(Event) % 8 == 0 &&
                 reinterpret_cast<std::uintptr_t>(span.data()) % 8 == 0;
  }

  EventSink* sink_;
  bool lends_;
  bool streams_;
  bool streaming_ = false;  // streams_, and a span is lent
  Event* out_;
  std::size_t size_ = 0;
  std::size_t limit_;
  std::array<Event, kCapacity + kSlack> buffer_;
};

// Lends from a vector of a sink's own (the sink side of the protocol in sink.h): grows it by the
// span, then shrinks it to the events committed. With UnsetHugePageAllocator
// (core/huge_page_allocator.h) growing stores nothing.
template <typename Vector>
class VectorLender {
 public:
  using Event = typename Vector::value_type;
  std::span<Event> lend(Vector& events, std::size_t count) {
    kept_ = events.size();
    events.resize(kept_ + count);
    lent_ = count;
    return std::span<Event>(events.data() + kept_, count);
  }
  void commit(Vector& events, std::size_t used) {
    events.resize(kept_ + used);
    lent_ = 0;
  }
  // Slots lent and not yet committed (they are at the vector's end).
  std::size_t lent() const { return lent_; }

 private:
  std::size_t kept_ = 0, lent_ = 0;
};

}  // namespace rastrace

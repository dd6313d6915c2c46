// Copies into memory that is written once and read long after (a frame's events on their way into
// a MemorySink): the whole 64-byte lines of the destination are written with streaming
// (non-temporal) stores, which neither read each line before overwriting it nor evict what the
// caller is working on. On the two-thread trace of the grazing plane the parallel rasterizer's
// copy of 61 MB of events with memcpy (`rep movsb`) ran at 7 GB/s; with streaming stores it takes
// half the time (docs/PERFORMANCE.md).
//
// Short copies, and the partial lines at either end, use ordinary stores: a streaming store of
// part of a line costs more than it saves. Streaming stores are weakly ordered: call
// streaming_fence() before another thread may read what was copied.
#pragma once

#include <cstddef>
#include <type_traits>

namespace rastrace {

// Copies at least this many bytes with streaming stores; fewer with memcpy.
inline constexpr std::size_t kStreamedCopyMinBytes = 1024;

// memcpy(to, from, bytes), with streaming stores as above where the processor has them (SSE2).
void copy_bytes_streaming(void* to, const void* from, std::size_t bytes);

// Orders the streaming stores made so far by this thread before its later stores (SFENCE).
void streaming_fence();

template <typename T>
void copy_streaming(const T* first, const T* last, T* to) {
  static_assert(std::is_trivially_copyable_v<T>);
  copy_bytes_streaming(to, first, static_cast<std::size_t>(last - first) * sizeof(T));
}

}  // namespace rastrace

#include "core/streaming_copy.h"

#include <cstdint>
#include <cstring>

#if defined(__SSE2__) && defined(__x86_64__)
#include <emmintrin.h>
#define RASTRACE_STREAMED_COPY 1
#else
#define RASTRACE_STREAMED_COPY 0
#endif

namespace rastrace {

void copy_bytes_streaming(void* to, const void* from, std::size_t bytes) {
  if (bytes == 0) return;
  if (!RASTRACE_STREAMED_COPY || bytes < kStreamedCopyMinBytes) {
    std::memcpy(to, from, bytes);
    return;
  }
#if RASTRACE_STREAMED_COPY
  auto* out = static_cast<char*>(to);
  const auto* in = static_cast<const char*>(from);
  // Ordinary stores up to the destination's first line boundary, then whole lines streamed.
  const std::size_t head = (64 - reinterpret_cast<std::uintptr_t>(out) % 64) % 64;
  std::memcpy(out, in, head);
  std::size_t done = head;
  for (; done + 64 <= bytes; done += 64) {
    const auto* source = reinterpret_cast<const __m128i*>(in + done);
    auto* line = reinterpret_cast<__m128i*>(out + done);
    const __m128i a = _mm_loadu_si128(source), b = _mm_loadu_si128(source + 1);
    const __m128i c = _mm_loadu_si128(source + 2), d = _mm_loadu_si128(source + 3);
    _mm_stream_si128(line, a);
    _mm_stream_si128(line + 1, b);
    _mm_stream_si128(line + 2, c);
    _mm_stream_si128(line + 3, d);
  }
  std::memcpy(out + done, in + done, bytes - done);
#endif
}

void streaming_fence() {
#if RASTRACE_STREAMED_COPY
  _mm_sfence();
#endif
}

}  // namespace rastrace

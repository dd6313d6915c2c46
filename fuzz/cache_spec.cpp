// The cache-spec grammar (cache_sim/cache_spec.cpp), as --cache, --vcache, --tcache, --zcache
// and sweep take it: the parse, then the expansions and validations each command applies.
#include <string>

#include "cache_sim/cache_spec.h"
#include "fuzz/fuzz_target.h"

RASTRACE_FUZZ_TARGET(cache_spec) {
  using namespace rastrace;
  const std::string text(reinterpret_cast<const char*>(data), size);
  fuzz::expect_clean([&] {
    const CacheSpec spec = parse_cache_spec(text, "--cache");
    // The cross product is what a sweep would run: only expand a spec of a plausible size.
    if (spec.combinations() <= 4096) {
      if (spec.kind == CacheKind::Vertex) {
        for (const VertexCacheSpec& cache : vertex_caches(spec)) format_cache_spec(cache);
      } else {
        for (const ByteCacheChoice& cache : byte_caches(spec)) format_cache_spec(cache.cache);
        framebuffer_caches(spec);
        fuzz::expect_clean([&] { sweep_spec(spec, SweepSource::Texel); });
      }
    }
  });
  fuzz::expect_clean([&] { parse_vertex_cache(text, "--vcache"); });
  fuzz::expect_clean([&] { parse_byte_cache(text, "--tcache"); });
  fuzz::expect_clean([&] { parse_framebuffer_cache(text, "--zcache", FramebufferBuffer::Depth); });
}

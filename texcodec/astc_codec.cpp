#include <astcenc.h>

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>

#include "texcodec/encoders.h"

namespace rastrace::texcodec {

namespace {

// astcenc's "fastest" preset (effort 0 of 100), on every core: a noisy 1024x1024 level takes
// 1.3-1.9 s to encode at 4x4 and 0.13-0.2 s at 8x8 on the loaded 2-core machine
// (docs/PERFORMANCE.md), where "fast" (effort 10) took 3.5 s and 0.18 s in the same conditions
// for 0.1 dB more on the test images (33.49 against 33.38 dB at 4x4, 29.64 against 29.62 dB at 8x8).
const float kEffort = ASTCENC_PRE_FASTEST;

void check(astcenc_error status, const char* step) {
  if (status != ASTCENC_SUCCESS)
    throw std::runtime_error(std::string("astcenc ") + step + ": " + astcenc_get_error_string(status));
}

struct ContextDeleter {
  void operator()(astcenc_context* context) const { astcenc_context_free(context); }
};
using Context = std::unique_ptr<astcenc_context, ContextDeleter>;

Context make_context(int block_size, unsigned flags, unsigned threads) {
  astcenc_config config{};
  check(astcenc_config_init(ASTCENC_PRF_LDR, static_cast<unsigned>(block_size), static_cast<unsigned>(block_size), 1,
                            kEffort, flags, &config),
        "config");
  astcenc_context* context = nullptr;
  check(astcenc_context_alloc(&config, threads, &context), "context");
  return Context(context);
}

astcenc_image image_of(int width, int height, void*& slice) {
  return astcenc_image{static_cast<unsigned>(width), static_cast<unsigned>(height), 1, ASTCENC_TYPE_U8, &slice};
}

constexpr astcenc_swizzle kIdentity{ASTCENC_SWZ_R, ASTCENC_SWZ_G, ASTCENC_SWZ_B, ASTCENC_SWZ_A};

}  // namespace

std::vector<std::uint8_t> astc_encode(int block_size, int width, int height, std::span<const std::uint8_t> rgba) {
  const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
  Context context = make_context(block_size, 0, threads);
  void* slice = const_cast<std::uint8_t*>(rgba.data());  // astcenc only reads the source
  astcenc_image image = image_of(width, height, slice);
  const auto blocks_x = static_cast<std::size_t>((width + block_size - 1) / block_size);
  const auto blocks_y = static_cast<std::size_t>((height + block_size - 1) / block_size);
  std::vector<std::uint8_t> blocks(blocks_x * blocks_y * 16);
  // astcenc splits one image among the threads that call it with distinct thread indices.
  std::vector<astcenc_error> status(threads, ASTCENC_SUCCESS);
  std::vector<std::thread> workers;
  for (unsigned t = 1; t < threads; ++t)
    workers.emplace_back([&, t] {
      status[t] = astcenc_compress_image(context.get(), &image, &kIdentity, blocks.data(), blocks.size(), t);
    });
  status[0] = astcenc_compress_image(context.get(), &image, &kIdentity, blocks.data(), blocks.size(), 0);
  for (std::thread& worker : workers) worker.join();
  for (astcenc_error s : status) check(s, "compress");
  return blocks;
}

std::vector<std::uint8_t> astc_decode(int block_size, int width, int height, std::span<const std::uint8_t> blocks) {
  Context context = make_context(block_size, ASTCENC_FLG_DECOMPRESS_ONLY, 1);
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
  void* slice = rgba.data();
  astcenc_image image = image_of(width, height, slice);
  check(astcenc_decompress_image(context.get(), blocks.data(), blocks.size(), &image, &kIdentity, 0), "decompress");
  return rgba;
}

}  // namespace rastrace::texcodec

// The recorder writes events as words, and a whole quad's footprints as vectors: with streaming
// stores into a MemorySink, with ordinary ones into storage lent by a sink that does not stream
// and into the batch buffer. All three must hold the same events, byte for byte, padding
// included, as the recorder's calls describe them (a quad as its footprints one by one).
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "raster/texel_recorder.h"
#include "traces/memory_sink.h"
#include "traces/tee_sink.h"

namespace rastrace {
namespace {

// Lends its storage, as a worker's tile buffer does, and does not ask for streaming stores.
class LendsWithoutStreaming final : public EventSink {
 public:
  bool lends_storage() const override { return true; }
  std::span<TexelAccess> texel_slots(std::size_t count) override { return lender_.lend(texels, count); }
  void commit_texels(std::size_t used) override { lender_.commit(texels, used); }
  std::span<VertexFetch> vertex_slots(std::size_t count) override { return fetch_lender_.lend(fetches, count); }
  void commit_vertices(std::size_t used) override { fetch_lender_.commit(fetches, used); }
  std::span<FramebufferAccess> framebuffer_slots(std::size_t count) override {
    return framebuffer_lender_.lend(framebuffer, count);
  }
  void commit_framebuffer(std::size_t used) override { framebuffer_lender_.commit(framebuffer, used); }

  MemorySink::Events<TexelAccess> texels;
  MemorySink::Events<VertexFetch> fetches;
  MemorySink::Events<FramebufferAccess> framebuffer;

 private:
  VectorLender<MemorySink::Events<TexelAccess>> lender_;
  VectorLender<MemorySink::Events<VertexFetch>> fetch_lender_;
  VectorLender<MemorySink::Events<FramebufferAccess>> framebuffer_lender_;
};

TexelAccess event(const TexelSite& site, unsigned level, int x, int y) {
  TexelAccess e;
  e.texture = site.texture;
  e.level = static_cast<std::uint8_t>(level);
  e.x = static_cast<std::uint16_t>(x);
  e.y = static_cast<std::uint16_t>(y);
  e.pixel_x = site.pixel_x;
  e.pixel_y = site.pixel_y;
  e.triangle = site.triangle;
  return e;
}

// The fields as wanted, the padding after `level` zero, and the bytes those of `reference`.
template <typename Events, typename Reference>
void expect_events(const Events& got, const std::vector<TexelAccess>& want, const Reference& reference,
                   const char* what) {
  ASSERT_EQ(got.size(), want.size()) << what;
  for (std::size_t i = 0; i < want.size(); ++i) {
    const TexelAccess &a = got[i], &b = want[i];
    ASSERT_TRUE(a.texture == b.texture && a.level == b.level && a.x == b.x && a.y == b.y && a.pixel_x == b.pixel_x &&
                a.pixel_y == b.pixel_y && a.triangle == b.triangle)
        << what << " event " << i;
    const auto* bytes = reinterpret_cast<const unsigned char*>(&a);
    for (std::size_t k = offsetof(TexelAccess, level) + 1; k < offsetof(TexelAccess, x); ++k)
      ASSERT_EQ(bytes[k], 0) << what << " event " << i;
    ASSERT_EQ(std::memcmp(&a, &reference[i], sizeof a), 0) << what << " event " << i;
  }
}

TEST(TexelRecorder, StreamedLentAndBatchedEventsAreTheSameBytes) {
  // Whole quads in vector lanes (seeds 1-3) and footprint by footprint (4-6), as without AVX2.
  for (unsigned seed = 1; seed <= 6; ++seed) {
    TexelRecorder::use_vector_quads(seed <= 3);
    MemorySink streamed, batched;
    LendsWithoutStreaming lent;
    TeeSink tee({&batched});
    ASSERT_TRUE(streamed.streams_lent_storage());
    ASSERT_FALSE(lent.streams_lent_storage());
    std::vector<TexelAccess> want;
    {
      TexelRecorder a(&streamed), b(&lent), c(&tee);
      std::mt19937 random(seed);
      // Past three spans of TexelRecorder::kCapacity, with flushes between some of them.
      for (int step = 0; step < 6000; ++step) {
        TexelSite site;
        site.texture = static_cast<std::uint16_t>(random());
        site.pixel_x = static_cast<std::uint16_t>(random());
        site.pixel_y = static_cast<std::uint16_t>(random());
        site.triangle = random();
        const unsigned level = random() % 300;  // stored as its low byte
        const int x0 = static_cast<int>(random()), x1 = static_cast<int>(random());
        const int y0 = static_cast<int>(random()), y1 = static_cast<int>(random());
        const unsigned what = random() % 16;
        if (what < 4) {
          for (TexelRecorder* r : {&a, &b, &c}) r->record(site, level, x0, y0);
          want.push_back(event(site, level, x0, y0));
        } else if (what < 10) {
          for (TexelRecorder* r : {&a, &b, &c}) r->record_footprint(site, level, x0, x1, y0, y1);
          for (const TexelAccess& e : {event(site, level, x0, y0), event(site, level, x1, y0),
                                       event(site, level, x0, y1), event(site, level, x1, y1)})
            want.push_back(e);
        } else if (what < 15) {
          // A whole quad: pixel p's footprint in lane p (and lane p + 4 in the next level).
          TexelRecorder::Lanes lx0, lx1, ly0, ly1;
          for (int lane = 0; lane < 8; ++lane) {
            lx0[lane] = static_cast<int>(random());
            lx1[lane] = static_cast<int>(random());
            ly0[lane] = static_cast<int>(random());
            ly1[lane] = static_cast<int>(random());
          }
          const int qx = static_cast<int>(random() % 70000), qy = static_cast<int>(random() % 70000);
          const bool trilinear = what % 2 == 0;
          for (TexelRecorder* r : {&a, &b, &c}) {
            if (trilinear)
              r->record_quad<true>(site, level, qx, qy, lx0, lx1, ly0, ly1);
            else
              r->record_quad<false>(site, level, qx, qy, lx0, lx1, ly0, ly1);
          }
          for (int p = 0; p < 4; ++p) {
            TexelSite pixel = site;
            pixel.pixel_x = static_cast<std::uint16_t>(qx + (p & 1));
            pixel.pixel_y = static_cast<std::uint16_t>(qy + (p >> 1));
            for (int l = 0; l < (trilinear ? 2 : 1); ++l) {
              const int lane = p + 4 * l;
              for (const TexelAccess& e :
                   {event(pixel, level + l, lx0[lane], ly0[lane]), event(pixel, level + l, lx1[lane], ly0[lane]),
                    event(pixel, level + l, lx0[lane], ly1[lane]), event(pixel, level + l, lx1[lane], ly1[lane])})
                want.push_back(e);
            }
          }
        } else {
          for (TexelRecorder* r : {&a, &b, &c}) r->flush();
        }
      }
      EXPECT_EQ(a.reads(), want.size());
    }
    expect_events(batched.texels, want, batched.texels, "batched");
    expect_events(streamed.texels, want, batched.texels, "streamed");
    expect_events(lent.texels, want, batched.texels, "lent");
  }
  TexelRecorder::use_vector_quads(true);
}

}  // namespace
}  // namespace rastrace

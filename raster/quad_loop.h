// The loop over a triangle's quads (traversal.h's order through quad_stage.h's QuadStage), shared
// by the serial and the parallel rasterizer, and compiled twice: for the baseline and, where the
// processor has it, for x86-64-v4 (AVX-512: 32 vector registers, three-operand instructions, and
// a conversion of 64-bit edge functions to float per vector instead of per lane). The quad stage
// is a few hundred instructions per quad; on the baseline a third of them moved vectors between
// its 16 registers and the stack.
//
// Both copies give the same bits: every operation is a lane-wise IEEE operation, and the files
// that instantiate the loop are compiled without contracting a*b+c into fused multiply-adds
// (raster/CMakeLists.txt), which x86-64-v4 would otherwise allow. Everything the loop calls per
// quad is inlined into each copy (always_inline); what stays a call (recording events, the
// filter kernel, log2f) keeps its one baseline body, so no inline function of the rest of the
// program is compiled for x86-64-v4.
//
// In both copies the loop runs each quad's front half before the back half of the quad before it
// (QuadStage in quad_stage.h says why that is safe and what it gains), except under hierarchical
// Z and with the debug planes.
#pragma once

#include "raster/quad_stage.h"
#include "raster/traversal.h"

namespace rastrace {

// Whether the quad loop runs its x86-64-v4 copy: where the processor has it, unless RASTRACE_SIMD
// is "sse2" (raster/quad_filter.h), so that one variable compares the baseline path end to end.
bool wide_quad_loop();
// Tests: force the baseline copy (false) or the processor's best (true) for the whole process.
void use_wide_quad_loop(bool wide);

namespace quad_loop_detail {

template <bool kTextured, bool kDebug, typename AfterQuad>
[[gnu::always_inline]] inline void visit(QuadStage& stage, const TriangleSetup& s, const TriangleState& state,
                                         Traversal traversal, const PixelRect& clip, unsigned hilbert_bits,
                                         AfterQuad& after_quad) {
  const QuadCoefficients coefficients(s);
  if (kDebug || !stage.pipelined()) {
    for_each_quad<kDebug>(
        s, traversal, clip,
        [&](int qx, int qy, const simd::i64x4* e) __attribute__((always_inline)) {
          stage.quad<kTextured, kDebug>(s, coefficients, state, qx, qy, e);
          after_quad(qx, qy);
        },
        hilbert_bits);
    return;
  }
  // Each quad's front half runs before the back half of the quad before it (quad_stage.h); a
  // quad that its front half finishes (no coverage) has no back half and no events, so it needs
  // no after_quad either.
  PendingQuad pending[2];
  int due = -1, next = 0;  // the quad whose back half is due (-1: none), the slot for the next
  auto finish = [&](const PendingQuad& q) __attribute__((always_inline)) {
    stage.back<kTextured, kDebug>(coefficients, state, q);
    after_quad(q.qx, q.qy);
  };
  for_each_quad<kDebug>(
      s, traversal, clip,
      [&](int qx, int qy, const simd::i64x4* e) __attribute__((always_inline)) {
        if (!stage.front<kTextured, kDebug>(s, coefficients, state, qx, qy, e, pending[next])) return;
        if (due >= 0) finish(pending[due]);
        due = next;
        next ^= 1;
      },
      hilbert_bits);
  if (due >= 0) finish(pending[due]);
}

template <bool kTextured, bool kDebug, typename AfterQuad>
void visit_baseline(QuadStage& stage, const TriangleSetup& s, const TriangleState& state, Traversal traversal,
                    const PixelRect& clip, unsigned hilbert_bits, AfterQuad& after_quad) {
  visit<kTextured, kDebug>(stage, s, state, traversal, clip, hilbert_bits, after_quad);
}

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define RASTRACE_WIDE_QUAD_LOOP 1
template <bool kTextured, bool kDebug, typename AfterQuad>
__attribute__((target("arch=x86-64-v4"))) void visit_wide(QuadStage& stage, const TriangleSetup& s,
                                                          const TriangleState& state, Traversal traversal,
                                                          const PixelRect& clip, unsigned hilbert_bits,
                                                          AfterQuad& after_quad) {
  visit<kTextured, kDebug>(stage, s, state, traversal, clip, hilbert_bits, after_quad);
}
#endif

}  // namespace quad_loop_detail

// Runs `stage` on every quad of the triangle inside `clip`, in the traversal's order, calling
// after_quad(qx, qy) once a quad's events are all recorded (inlined too: pass a lambda marked
// always_inline). Quads that cover no pixel record nothing and may get no call.
template <bool kTextured, bool kDebug, typename AfterQuad>
void visit_quads(QuadStage& stage, const TriangleSetup& s, const TriangleState& state, Traversal traversal,
                 const PixelRect& clip, unsigned hilbert_bits, AfterQuad&& after_quad) {
#ifdef RASTRACE_WIDE_QUAD_LOOP
  if (wide_quad_loop()) {
    quad_loop_detail::visit_wide<kTextured, kDebug>(stage, s, state, traversal, clip, hilbert_bits, after_quad);
    return;
  }
#endif
  quad_loop_detail::visit_baseline<kTextured, kDebug>(stage, s, state, traversal, clip, hilbert_bits, after_quad);
}

}  // namespace rastrace

// Batch-based vertex reuse on current GPUs, after Kerbl, Kenzel, Ivanchenko, Schmalstieg,
// Steinberger, "Revisiting the Vertex Cache: Understanding and Optimizing Vertex Processing on the
// modern GPU", HPG 2018. They measured that NVIDIA, AMD and Intel GPUs keep no post-transform
// cache shared between batches: the index stream is cut into batches, the vertices of a batch are
// shaded together (one warp or wave, or a few SIMD threads) and reuse happens only inside a batch.
// The parameters below are those of the simulator published with the paper (GPUPeople,
// vertex_batch_optimization, BatchSimulationParameters.h); this file is our own implementation of
// the same rules.
//
//   preset       batch: indices / vertices   cut        reuse inside the batch          lanes
//   kerbl-nv     96 / 32                     triangle   last use within ~42 indices (D3D)  32
//   kerbl-nv-gl  96 / 32                     triangle   last use within 42 indices (GL)    32
//   kerbl-amd    384 static, 64 vertices     index      LRU of 15 vertices                 64
//   kerbl-intel  1791 / 128                  triangle   every vertex of the batch           8
//
// - NVIDIA: a batch closes before the triangle that would exceed 96 indices or 32 shaded vertices
//   (so a repeated 0,1,2 pattern is shaded 3 times up to 96 indices, 6 times at 99, as the paper
//   measured). Inside the batch a vertex is reused while its last reference is recent: under GL,
//   at most 42 indices back; under D3D the window depends on the reference's position modulo 3
//   (< 45 for the first corner, <= 40 or 42 for the second, <= 39, 41 or 42 for the third).
// - AMD: static batches of 384 indices (the cache is cleared at every multiple of 384); a batch
//   that reaches 64 shaded vertices is cut at that index, even inside a triangle, and the LRU of 15
//   vertices carries over that soft cut.
// - Intel: the paper found its behaviour the most dynamic; the simulator's lower bound, batches of
//   up to 1791 indices and 128 vertices with every vertex of the batch reused, is modelled here,
//   and SIMD8 vertex shader threads give its lanes.
// Each batch's invocations run on ceil(invocations / lanes) warps (waves, threads).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace rastrace {

enum class KerblGpu : std::uint8_t { NvidiaD3d, NvidiaGl, Amd, Intel };

struct KerblBatchParameters {
  unsigned batch_indices;    // indices per batch at most
  unsigned batch_vertices;   // shaded vertices per batch at most
  unsigned static_period;    // the cache is cleared every this many indices; 0 = never
  bool cut_at_triangles;     // a batch ends before a triangle, not inside one
  unsigned lanes;            // SIMD width a batch's invocations are rounded up to
};
KerblBatchParameters kerbl_parameters(KerblGpu gpu);

class KerblBatch {
 public:
  explicit KerblBatch(KerblGpu gpu);

  // One primitive of `count` (3 or 6) fetched indices.
  void primitive(const std::uint32_t* vertices, unsigned count);
  // Closes the open batch and clears every reuse state (a draw boundary).
  void flush();

  // What appending this triangle would cost, without appending it: the invocations it adds to
  // the open batch, or kDoesNotFit when it would open a new batch. For the models that cut at
  // triangles (all but AMD; std::logic_error otherwise). Used by batch-aware orderings.
  static constexpr unsigned kDoesNotFit = ~0u;
  unsigned append_cost(const std::uint32_t* triangle) const;

  std::uint64_t invocations() const { return invocations_; }
  std::uint64_t batches() const { return batches_ + (batch_indices_ > 0); }
  std::uint64_t warps() const { return warps_ + warps_for(batch_invocations_); }
  const KerblBatchParameters& parameters() const { return p_; }

 private:
  bool reused(std::uint32_t vertex, std::uint64_t position) const;
  void use(std::uint32_t vertex, std::uint64_t position);
  void close_batch(bool clear_lru);
  std::uint64_t warps_for(std::uint64_t invocations) const { return (invocations + p_.lanes - 1) / p_.lanes; }

  KerblGpu gpu_;
  KerblBatchParameters p_;
  std::uint64_t position_ = 0;       // indices processed so far (the stream position)
  std::uint64_t period_start_ = 0;   // position of the last static cut
  unsigned batch_indices_ = 0, batch_invocations_ = 0;
  std::uint64_t invocations_ = 0, batches_ = 0, warps_ = 0;
  // NVIDIA and Intel: per vertex, the batch it was last used in (generation) and the position.
  std::uint32_t generation_ = 1;
  std::vector<std::uint32_t> used_in_;
  std::vector<std::uint64_t> last_use_;
  // AMD: the LRU, most recent last.
  std::array<std::uint32_t, 15> lru_{};
  unsigned lru_size_ = 0;
};

}  // namespace rastrace

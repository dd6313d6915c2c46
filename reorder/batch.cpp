// A triangle order for batch-based vertex reuse (the NVIDIA model of Kerbl, Kenzel, Ivanchenko,
// Schmalstieg, Steinberger, "Revisiting the Vertex Cache: Understanding and Optimizing Vertex
// Processing on the modern GPU", HPG 2018; cache_sim/kerbl_batch.h). Their observation is that
// a batch of 32 triangles (96 indices) shades each of its vertices once, and nothing is reused
// between batches; so an order should cut the mesh into compact patches of 32 triangles with as
// few vertices as possible, one patch per batch, rather than sweep fans through a FIFO.
//
// Ours builds the batches greedily while running the batch model itself: the next triangle is,
// among the live triangles around the open batch's vertices, the one that adds the fewest shader
// invocations to the batch (the model's own count, so a vertex whose last use has left the reuse
// window counts as new); ties go to the triangle whose vertices have the fewest live triangles
// left (it closes the patch's border instead of widening it), then to the one using the batch
// vertex closest to leaving the reuse window (used before it is lost, as Tipsy's time stamps
// favour), then to the lower face id. Those two tie-breaks were chosen on fandisk, triceratops and
// bunny00 (with cost alone the order is worse than Forsyth's); docs/PERFORMANCE.md also gives
// meshes they were not chosen on. When no
// triangle fits, the next batch is seeded next to the last one: at the live vertex of the closed
// batch with the fewest live triangles (a corner of what is left, as Tipsy's dead-end rule picks),
// else at the first live face in file order. Linear in the faces times the triangles around a
// batch (about 200 cost queries per triangle). Deterministic.
#include <algorithm>
#include <limits>

#include "cache_sim/kerbl_batch.h"
#include "reorder/ordering.h"
#include "reorder/vertex_faces.h"

namespace rastrace {

Ordering reorder_batch(const Mesh& mesh, const ReorderParams&) {
  const MeshTopology topology = build_vertex_faces(mesh);
  const std::uint32_t vertex_count = topology.vertex_count, face_count = topology.face_count;
  const std::uint32_t* idx = mesh.indices.data();

  std::vector<std::uint32_t> live(vertex_count);
  for (std::uint32_t v = 0; v < vertex_count; ++v)
    live[v] = topology.vertex_face_offsets[v + 1] - topology.vertex_face_offsets[v];
  std::vector<std::uint8_t> emitted(face_count, 0);
  std::vector<std::uint64_t> in_batch(vertex_count, 0);  // the batch number (1-based) a vertex was last in
  std::vector<std::uint64_t> last_use(vertex_count, 0);  // stream position of the vertex's last use
  std::uint64_t position = 0;
  constexpr std::uint64_t kWindow = 42;                  // NVIDIA's reuse window (kerbl_batch.h)
  std::vector<std::uint32_t> batch_vertices, closed_batch;
  KerblBatch model(KerblGpu::NvidiaD3d);
  std::uint64_t batch = 0;
  std::uint32_t scan = 0;  // faces below are emitted

  std::vector<std::uint32_t> order;
  order.reserve(face_count);
  const auto emit = [&](std::uint32_t f) {
    model.primitive(idx + 3 * std::size_t(f), 3);
    if (model.batches() != batch) {  // the model opened a batch
      batch = model.batches();
      closed_batch.swap(batch_vertices);
      batch_vertices.clear();
    }
    emitted[f] = 1;
    order.push_back(f);
    for (unsigned j = 0; j < 3; ++j) {
      const std::uint32_t v = idx[3 * std::size_t(f) + j];
      if ((j == 1 && v == idx[3 * std::size_t(f)]) || (j == 2 && (v == idx[3 * std::size_t(f)] || v == idx[3 * std::size_t(f) + 1])))
        continue;
      --live[v];
      last_use[v] = position + j;
      if (in_batch[v] != batch) {
        in_batch[v] = batch;
        batch_vertices.push_back(v);
      }
    }
    position += 3;
  };

  while (order.size() < face_count) {
    // The cheapest live triangle that fits in the open batch.
    std::uint32_t best = face_count;
    std::uint64_t best_score = std::numeric_limits<std::uint64_t>::max();
    for (const std::uint32_t v : batch_vertices) {
      if (live[v] == 0) continue;
      for (const std::uint32_t f : topology.faces_of_vertex(v)) {
        if (emitted[f]) continue;
        const unsigned cost = model.append_cost(idx + 3 * std::size_t(f));
        if (cost == KerblBatch::kDoesNotFit) continue;
        std::uint64_t border = 0, oldest = 0;
        for (unsigned j = 0; j < 3; ++j) {
          const std::uint32_t u = idx[3 * std::size_t(f) + j];
          border += live[u];
          if (in_batch[u] == batch && position - last_use[u] <= kWindow) oldest = std::max(oldest, position - last_use[u]);
        }
        const std::uint64_t score = (std::uint64_t{cost} << 48) | (border << 8) | (kWindow - oldest);
        if (score < best_score || (score == best_score && f < best)) {
          best_score = score;
          best = f;
        }
      }
    }
    if (best == face_count) {
      // Seed the next batch beside the last one, at a corner of what is left.
      std::uint32_t seed_vertex = vertex_count;
      for (const std::vector<std::uint32_t>* around : {&batch_vertices, &closed_batch})
        for (const std::uint32_t v : *around)
          if (live[v] > 0 && (seed_vertex == vertex_count || live[v] < live[seed_vertex])) seed_vertex = v;
      if (seed_vertex != vertex_count) {
        for (const std::uint32_t f : topology.faces_of_vertex(seed_vertex))
          if (!emitted[f]) {
            best = f;
            break;
          }
      } else {
        while (emitted[scan]) ++scan;
        best = scan;
      }
    }
    emit(best);
  }
  return list_ordering(mesh, std::move(order));
}

}  // namespace rastrace

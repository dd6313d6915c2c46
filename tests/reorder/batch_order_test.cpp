// The batch-aware order (reorder/batch.cpp) under the batch model it is made for, against the
// FIFO-tuned orders: fewer shader invocations under kerbl-nv on fandisk and triceratops; and its
// shortcuts for vertices in many triangles against the plain full scan.
#include <algorithm>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "cache_sim/kerbl_batch.h"
#include "cache_sim/vertex_reuse.h"
#include "reorder/ordering.h"
#include "reorder/vertex_faces.h"
#include "tests/support/ordering_checks.h"
#include "tests/support/test_meshes.h"

namespace rastrace {
namespace {

std::uint64_t invocations(const Ordering& ordering, const char* preset) {
  return simulate_vertex_reuse(ordering.indices, ordering.type, find_vertex_reuse_preset(preset)->spec,
                               ordering.restart_index)
      .misses;
}

TEST(BatchOrder, IsAPermutationAndBeatsEveryFifoTunedOrderUnderTheNvidiaBatchModel) {
  for (const char* name : {"fandisk.off", "triceratops.off"}) {
    const Mesh& mesh = testing::cached_mesh(name);
    ReorderParams params;  // FIFO 16, the orders' default target
    const Ordering batch = find_reorder_algorithm("batch").run(mesh, params);
    testing::expect_permutation_with_winding(mesh, batch, name);
    const std::uint64_t ours = invocations(batch, "kerbl-nv");
    for (const char* fifo_tuned : {"forsyth", "tipsy", "kcache", "greedy"}) {
      const Ordering other = find_reorder_algorithm(fifo_tuned).run(mesh, params);
      EXPECT_LT(ours, invocations(other, "kerbl-nv")) << name << " against " << fifo_tuned;
    }
  }
}

// The batch order's shortcuts for large fans (reorder/batch.cpp) skip only triangles that cannot
// win. This is the plain rule without them: every live triangle around the open batch scored at
// every step.
std::vector<std::uint32_t> full_scan_batch_order(const Mesh& mesh) {
  const MeshTopology topology = build_vertex_faces(mesh);
  const std::uint32_t vertex_count = topology.vertex_count, face_count = topology.face_count;
  const std::uint32_t* idx = mesh.indices.data();
  constexpr std::uint64_t kWindow = 42;
  std::vector<std::uint32_t> live(vertex_count);
  for (std::uint32_t v = 0; v < vertex_count; ++v) live[v] = std::uint32_t(topology.faces_of_vertex(v).size());
  std::vector<std::uint8_t> emitted(face_count, 0);
  std::vector<std::uint64_t> in_batch(vertex_count, 0), last_use(vertex_count, 0);
  std::vector<std::uint32_t> batch_vertices, closed_batch, order;
  KerblBatch model(KerblGpu::NvidiaD3d);
  std::uint64_t position = 0, batch = 0;
  std::uint32_t scan = 0;
  while (order.size() < face_count) {
    std::uint32_t best = face_count;
    std::uint64_t best_score = ~std::uint64_t{0};
    for (const std::uint32_t v : batch_vertices)
      for (const std::uint32_t f : topology.faces_of_vertex(v)) {
        if (emitted[f]) continue;
        const unsigned cost = model.append_cost(idx + 3 * std::size_t(f));
        if (cost == KerblBatch::kDoesNotFit) continue;
        std::uint64_t border = 0, oldest = 0;
        for (unsigned j = 0; j < 3; ++j) {
          const std::uint32_t u = idx[3 * std::size_t(f) + j];
          border += live[u];
          if (in_batch[u] == batch && position - last_use[u] <= kWindow)
            oldest = std::max(oldest, position - last_use[u]);
        }
        const std::uint64_t score = (std::uint64_t{cost} << 48) | (border << 8) | (kWindow - oldest);
        if (score < best_score || (score == best_score && f < best)) {
          best_score = score;
          best = f;
        }
      }
    if (best == face_count) {
      std::uint32_t seed = vertex_count;
      for (const auto* around : {&batch_vertices, &closed_batch})
        for (const std::uint32_t v : *around)
          if (live[v] > 0 && (seed == vertex_count || live[v] < live[seed])) seed = v;
      if (seed != vertex_count) {
        for (const std::uint32_t f : topology.faces_of_vertex(seed))
          if (!emitted[f]) {
            best = f;
            break;
          }
      } else {
        while (emitted[scan]) ++scan;
        best = scan;
      }
    }
    const std::uint32_t* c = idx + 3 * std::size_t(best);
    model.primitive(c, 3);
    if (model.batches() != batch) {
      batch = model.batches();
      closed_batch.swap(batch_vertices);
      batch_vertices.clear();
    }
    emitted[best] = 1;
    order.push_back(best);
    for (unsigned j = 0; j < 3; ++j) {
      if ((j == 1 && c[1] == c[0]) || (j == 2 && (c[2] == c[0] || c[2] == c[1]))) continue;
      --live[c[j]];
      last_use[c[j]] = position + j;
      if (in_batch[c[j]] != batch) {
        in_batch[c[j]] = batch;
        batch_vertices.push_back(c[j]);
      }
    }
    position += 3;
  }
  return order;
}

// Random faces on `vertices` vertices, a share of them on hub vertex 0 and a share degenerate
// (a repeated corner), so large fans with and without degenerate triangles are walked.
Mesh hub_mesh(std::uint32_t vertices, std::uint32_t faces, std::uint32_t hub_percent, std::uint32_t degenerate_percent,
              std::uint32_t seed) {
  Mesh mesh;
  mesh.name = "hub";
  for (std::uint32_t v = 0; v < vertices; ++v) mesh.positions.emplace_back(float(v), 0.0f, 0.0f);
  std::uint32_t state = seed;
  const auto next = [&](std::uint32_t n) {
    state = state * 1664525u + 1013904223u;
    return (state >> 8) % n;
  };
  for (std::uint32_t f = 0; f < faces; ++f) {
    std::uint32_t a = next(100) < hub_percent ? 0 : next(vertices), b = next(vertices), c = next(vertices);
    if (next(100) < degenerate_percent) {
      c = next(2) ? a : b;
    } else {
      if (b == a) b = (b + 1) % vertices;
      if (c == a || c == b) c = (c + 1) % vertices;
      if (c == a || c == b) c = (c + 1) % vertices;
    }
    mesh.indices.insert(mesh.indices.end(), {a, b, c});
  }
  return mesh;
}

TEST(BatchOrder, LargeFanShortcutsChooseTheFullScansTriangleAtEveryStep) {
  struct Case {
    std::uint32_t vertices, faces, hub_percent, degenerate_percent, seed;
  };
  for (const Case& c : {Case{12, 1500, 0, 0, 1}, Case{30, 2000, 40, 0, 2}, Case{30, 2000, 40, 10, 3},
                        Case{400, 2000, 60, 5, 4}, Case{2000, 2000, 90, 0, 5}, Case{16, 1200, 20, 30, 6}}) {
    const Mesh mesh = hub_mesh(c.vertices, c.faces, c.hub_percent, c.degenerate_percent, c.seed);
    EXPECT_EQ(find_reorder_algorithm("batch").run(mesh, ReorderParams{}).face_order, full_scan_batch_order(mesh))
        << "seed " << c.seed;
  }
}

}  // namespace
}  // namespace rastrace

// Pins the exact output (face order and index stream) of the orderings made faster for the
// pathological corpus (bench/pathological.cpp) on real meshes, as the code before those changes
// produced it: the speed-ups skip work that cannot change a choice, so every figure here must
// stay. The hashes were taken from that code; a change that alters an ordering on well-formed
// meshes shows up here even where no ACMR test looks.
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "reorder/ordering.h"
#include "scenes/mesh_io.h"
#include "tests/support/test_data.h"

namespace rastrace {
namespace {

// FNV-1a over the 32-bit words of the face order, then the index stream.
std::uint64_t ordering_hash(const Ordering& ordering) {
  std::uint64_t hash = 14695981039346656037ull;
  const auto add = [&](const std::vector<std::uint32_t>& words) {
    for (const std::uint32_t w : words) {
      hash ^= w;
      hash *= 1099511628211ull;
    }
  };
  add(ordering.face_order);
  add(ordering.indices);
  return hash;
}

struct Pinned {
  const char* algorithm;
  const char* mesh;
  std::uint64_t hash;
};

// Default parameters (cache size 16, FIFO).
const Pinned kPinned[] = {
    {"nvstrip", "bunny00", 818804009208621596ull},        {"nvstrip", "fandisk", 14952500782278527725ull},
    {"nvstrip", "triceratops", 6851142875259938073ull},   {"greedy", "bunny00", 502351622530610596ull},
    {"greedy", "fandisk", 11314278815489747317ull},       {"greedy", "triceratops", 320354264629206385ull},
    {"kcache", "bunny00", 4089733054921939356ull},        {"kcache", "fandisk", 5073183391119153154ull},
    {"kcache", "triceratops", 9322602028314607203ull},    {"strip", "bunny00", 1512687614768160072ull},
    {"strip", "fandisk", 5168684695811071504ull},         {"strip", "triceratops", 17433766058431235345ull},
    {"texgroup", "bunny00", 1512687614768160072ull},      {"texgroup", "fandisk", 5168684695811071504ull},
    {"texgroup", "triceratops", 17433766058431235345ull}, {"forsyth", "bunny00", 13274104722757043402ull},
    {"forsyth", "fandisk", 3367951236812519780ull},       {"forsyth", "triceratops", 8856306872058004249ull},
};

TEST(OrdersOnRealMeshes, FasterOrderingsDrawExactlyTheSameStreams) {
  for (const Pinned& pinned : kPinned) {
    const Mesh mesh = load_mesh(testing::data_file(std::string("meshes/") + pinned.mesh + ".off"));
    const Ordering ordering = find_reorder_algorithm(pinned.algorithm).run(mesh, ReorderParams{});
    EXPECT_EQ(ordering_hash(ordering), pinned.hash) << pinned.algorithm << " on " << pinned.mesh;
  }
}

}  // namespace
}  // namespace rastrace

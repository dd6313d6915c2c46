#include "reorder/adjacency/encode.h"

#include <stdexcept>

namespace rastrace {
namespace {

constexpr std::uint8_t kNoSlot = 3;

std::uint32_t opposite_vertex(const Mesh& mesh, const AdjacencyDual& dual, std::uint32_t f, unsigned slot) {
  const std::uint32_t g = dual.across(f, slot);
  return mesh.indices[3 * std::size_t{g} + (dual.neighbour_slot[3 * f + slot] + 2) % 3];
}

void append(AdjacencyPrimitives& out, const std::uint32_t six[6], std::uint32_t cover, std::uint32_t assigned) {
  out.indices.insert(out.indices.end(), six, six + 6);
  out.cover_face.push_back(cover);
  out.assigned_face.push_back(assigned);
}

}  // namespace

AdjacencyPrimitives encode_adjacency_primitives(const Mesh& mesh, const AdjacencyDual& dual,
                                                const std::vector<std::uint8_t>& in_cover,
                                                const FaceAssignment& assignment) {
  const std::uint32_t F = dual.face_count;
  const std::uint32_t* idx = mesh.indices.data();
  auto partner = [&](std::uint32_t f) { return assignment.partner[f]; };
  // A cover face is needy when it has neither an assigned face nor a boundary edge: it must hand
  // its position-0 edge to a neighbouring cover face.
  auto needy = [&](std::uint32_t f) { return in_cover[f] && dual.interior(f) && partner(f) == kNoFace; };

  // Breadth-first forest from the faces that can take position 0 themselves; each needy face
  // hands the edge towards its parent, so no edge is handed over twice.
  std::vector<std::uint8_t> handover(F, kNoSlot), reached(F, 0);
  std::vector<std::uint32_t> queue;
  for (std::uint32_t f = 0; f < F; ++f)
    if (in_cover[f] && dual.kind[f] != DualFaceKind::Degenerate && !needy(f)) {
      reached[f] = 1;
      queue.push_back(f);
    }
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const std::uint32_t x = queue[head];
    for (unsigned i = 0; i < 3; ++i) {
      const std::uint32_t g = dual.across(x, i);
      if (g == kNoFace || reached[g] || !needy(g)) continue;
      reached[g] = 1;
      handover[g] = dual.neighbour_slot[3 * x + i];
      queue.push_back(g);
    }
  }

  AdjacencyPrimitives out;
  for (std::uint32_t f = 0; f < F; ++f) {
    if (!in_cover[f]) continue;
    const std::uint32_t* v = idx + 3 * std::size_t{f};
    std::uint32_t six[6];
    if (dual.kind[f] == DualFaceKind::Degenerate) {
      for (unsigned p = 0; p < 3; ++p) {
        six[2 * p] = v[p];
        six[2 * p + 1] = v[(p + 1) % 3];
      }
      append(out, six, f, kNoFace);
      continue;
    }
    if (needy(f) && !reached[f]) throw std::logic_error("encoding: a cover component has no assigned or boundary face");
    unsigned first = 0;
    if (partner(f) != kNoFace) {
      while (dual.across(f, first) != partner(f)) ++first;
    } else if (dual.kind[f] == DualFaceKind::Boundary) {
      while (dual.across(f, first) != kNoFace) ++first;
    } else {
      first = handover[f];
    }
    for (unsigned p = 0; p < 3; ++p) {
      const unsigned slot = (first + p) % 3;
      const std::uint32_t start = v[slot], end = v[(slot + 1) % 3];
      six[2 * p] = start;
      const std::uint32_t g = dual.across(f, slot);
      bool processed;
      if (g == kNoFace) {
        six[2 * p + 1] = start;  // boundary edge
        continue;
      } else if (!in_cover[g]) {
        processed = true;
      } else if (handover[f] == slot) {
        processed = false;
      } else if (handover[g] == dual.neighbour_slot[3 * f + slot]) {
        processed = true;
      } else {
        processed = f < g;
      }
      six[2 * p + 1] = processed ? opposite_vertex(mesh, dual, f, slot) : end;
    }
    append(out, six, f, partner(f));
  }
  return out;
}

AdjacencyPrimitives encode_one_primitive_per_face(const Mesh& mesh, const AdjacencyDual& dual) {
  AdjacencyPrimitives out;
  for (std::uint32_t f = 0; f < dual.face_count; ++f) {
    const std::uint32_t* v = mesh.indices.data() + 3 * std::size_t{f};
    std::uint32_t six[6];
    for (unsigned p = 0; p < 3; ++p) {
      six[2 * p] = v[p];
      const bool real = dual.kind[f] != DualFaceKind::Degenerate && dual.across(f, p) != kNoFace;
      six[2 * p + 1] = real ? opposite_vertex(mesh, dual, f, p) : v[p];
    }
    append(out, six, f, kNoFace);
  }
  return out;
}

DecodedPrimitive decode_adjacency_primitive(const std::uint32_t* six) {
  DecodedPrimitive d;
  for (unsigned p = 0; p < 3; ++p) {
    d.cover[p] = six[2 * p];
    d.opposite[p] = six[2 * p + 1];
  }
  const bool degenerate = d.cover[0] == d.cover[1] || d.cover[1] == d.cover[2] || d.cover[0] == d.cover[2];
  for (unsigned p = 0; p < 3; ++p) {
    const std::uint32_t start = six[2 * p], end = six[(2 * p + 2) % 6], across = six[2 * p + 1];
    if (degenerate || across == end)
      d.role[p] = EdgeRole::Skipped;
    else if (across == start)
      d.role[p] = EdgeRole::Boundary;
    else
      d.role[p] = EdgeRole::Interior;
  }
  d.has_assigned = d.role[0] == EdgeRole::Interior;
  return d;
}

AdjacencyPrimitives permute_primitives(const AdjacencyPrimitives& primitives, const std::vector<std::uint32_t>& order) {
  AdjacencyPrimitives out;
  out.indices.reserve(order.size() * 6);
  for (const std::uint32_t k : order) {
    out.indices.insert(out.indices.end(), primitives.indices.begin() + 6 * std::size_t{k},
                       primitives.indices.begin() + 6 * std::size_t{k} + 6);
    out.cover_face.push_back(primitives.cover_face[k]);
    out.assigned_face.push_back(primitives.assigned_face[k]);
  }
  return out;
}

}  // namespace rastrace

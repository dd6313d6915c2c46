// Meshlets: the clusters a mesh shader draws, each a short list of vertices (indices into the
// mesh's vertex buffer) and triangles whose corners are 8-bit indices into that list. The
// transform cost of a mesh drawn as meshlets is the sum of the meshlets' vertex counts: a vertex
// shared by two meshlets is shaded twice, whatever the order inside them. Usual limits are 64
// vertices and 124-126 triangles (meshoptimizer 0.18 requires a multiple of 4 triangles).
//
// The builders, one file each, all take a triangle list (three indices per triangle, in the order
// an ordering drew them) and put every triangle in exactly one meshlet. Vertices per triangle on
// CGAL's fandisk, triceratops and bunny00 in file order, at 64/124 and 64/64 (meshoptimizer's
// buildMeshlets: 0.662-0.681 and 0.712-0.729):
//   build_meshlets_scan     in the stream's order, as meshopt_buildMeshletsScan (equal output):
//                           as good as the order (fandisk 1.042 in file order, 0.703 after Tipsy)
//   build_meshlets_greedy   grown by shared vertices (meshlet_greedy.cpp): 0.659-0.666, 0.706-0.714
//   build_meshlets_spatial  recursive bisection of the triangles' centroids: 0.744-0.788 at 64/124
// meshlet_peer.h runs meshoptimizer's two builders on the same input; meshlet_stats.h measures.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

namespace rastrace {

// The mesh-shader limits a builder respects. A meshlet vertex is an 8-bit local index, so at most
// 256 vertices; 512 triangles is the largest output NVIDIA's and meshoptimizer's limits allow.
struct MeshletLimits {
  std::uint32_t max_vertices = 64;
  std::uint32_t max_triangles = 124;
};
inline constexpr std::uint32_t kMeshletMaxVertices = 256;
inline constexpr std::uint32_t kMeshletMaxTriangles = 512;

// Throws InputError unless 3 <= max_vertices <= 256 and 1 <= max_triangles <= 512.
void validate(const MeshletLimits& limits);

struct Meshlet {
  std::uint32_t vertex_offset = 0;    // into MeshletSet::vertices
  std::uint32_t triangle_offset = 0;  // into MeshletSet::triangles, in triangles (3 bytes each)
  std::uint32_t vertex_count = 0;
  std::uint32_t triangle_count = 0;
};

struct MeshletSet {
  std::vector<Meshlet> meshlets;
  std::vector<std::uint32_t> vertices;  // mesh vertex ids, meshlet after meshlet
  std::vector<std::uint8_t> triangles;  // 3 local indices per triangle, meshlet after meshlet

  std::size_t triangle_count() const { return triangles.size() / 3; }
  // Mesh vertex id of corner k (0..2) of triangle t of meshlet m.
  std::uint32_t corner(const Meshlet& m, std::uint32_t t, int k) const {
    return vertices[m.vertex_offset + triangles[3 * (std::size_t{m.triangle_offset} + t) + k]];
  }
};

// Appends triangles to the meshlet being built and closes it; the builders' shared bookkeeping.
// A vertex's local index lives in a per-vertex array (0xFFFF = not in the open meshlet), so a
// lookup is O(1) and closing a meshlet costs its vertex count.
class MeshletAccumulator {
 public:
  MeshletAccumulator(std::size_t vertex_count, const MeshletLimits& limits);

  // Vertices of the triangle not yet in the open meshlet (a repeated corner counts once).
  std::uint32_t new_vertices(std::uint32_t a, std::uint32_t b, std::uint32_t c) const;
  // True if the triangle fits in the open meshlet without exceeding either limit.
  bool fits(std::uint32_t a, std::uint32_t b, std::uint32_t c) const {
    return open_.triangle_count < limits_.max_triangles &&
           open_.vertex_count + new_vertices(a, b, c) <= limits_.max_vertices;
  }
  bool contains(std::uint32_t vertex) const { return local_[vertex] != kAbsent; }
  // Adds the triangle to the open meshlet; the caller has checked fits().
  void append(std::uint32_t a, std::uint32_t b, std::uint32_t c);
  // Closes the open meshlet (nothing if it is empty).
  void close();
  const Meshlet& open() const { return open_; }
  std::span<const std::uint32_t> open_vertices() const {
    return std::span<const std::uint32_t>(set_.vertices).subspan(open_.vertex_offset, open_.vertex_count);
  }
  const MeshletLimits& limits() const { return limits_; }
  // Closes the open meshlet and hands the set over.
  MeshletSet finish();

 private:
  static constexpr std::uint16_t kAbsent = 0xFFFF;
  std::uint8_t local(std::uint32_t vertex);

  MeshletLimits limits_;
  MeshletSet set_;
  Meshlet open_;
  std::vector<std::uint16_t> local_;
};

// Throws InputError when the list is not whole triangles or an index is >= vertex_count.
void validate_triangle_list(std::span<const std::uint32_t> triangles, std::size_t vertex_count);

MeshletSet build_meshlets_scan(std::span<const std::uint32_t> triangles, std::size_t vertex_count,
                               const MeshletLimits& limits);
MeshletSet build_meshlets_greedy(std::span<const std::uint32_t> triangles, std::span<const glm::vec3> positions,
                                 const MeshletLimits& limits);
MeshletSet build_meshlets_spatial(std::span<const std::uint32_t> triangles, std::span<const glm::vec3> positions,
                                  const MeshletLimits& limits);

}  // namespace rastrace

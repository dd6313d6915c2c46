// Fan triangulation of a polygon whose corners arrive one at a time, in file order:
// (c0 c1 c2), (c0 c2 c3), ... The OFF and PLY readers share it, so both split polygons the same way
// and reject a corner outside the vertex array with the same message.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace rastrace {

class PolygonFan {
 public:
  PolygonFan(std::vector<std::uint32_t>& indices, std::uint64_t vertex_count)
      : indices_(indices), vertex_count_(vertex_count) {}

  void begin_polygon() { corners_ = 0; }

  // Adds the next corner; false (nothing added) when `index` is not a vertex of the mesh.
  bool add(std::int64_t index) {
    if (index < 0 || static_cast<std::uint64_t>(index) >= vertex_count_) return false;
    const auto current = static_cast<std::uint32_t>(index);
    if (corners_ == 0)
      first_ = current;
    else if (corners_ >= 2)
      indices_.insert(indices_.end(), {first_, previous_, current});
    previous_ = current;
    ++corners_;
    return true;
  }

  // Why add(index) refused: "face index 40012 >= vertex count 34835".
  std::string range_error(std::int64_t index) const {
    return "face index " + std::to_string(index) +
           (index < 0 ? " < 0" : " >= vertex count " + std::to_string(vertex_count_));
  }

 private:
  std::vector<std::uint32_t>& indices_;
  std::uint64_t vertex_count_;
  std::uint64_t corners_ = 0;
  std::uint32_t first_ = 0;
  std::uint32_t previous_ = 0;
};

}  // namespace rastrace

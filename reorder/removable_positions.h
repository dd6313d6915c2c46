// Positions 0..n-1 of an array, some removed for good, walked in order without re-reading the
// removed ones: first(i) is the first position >= i not removed (n if none), by forward links
// with path halving, so runs of removed positions cost amortized nearly nothing however often
// they are walked past. The strip orderings use it to skip committed or drawn faces in face
// lists whose order matters, around a vertex or an edge shared by thousands of faces.
#pragma once

#include <cstdint>
#include <numeric>
#include <vector>

namespace rastrace {

class RemovablePositions {
 public:
  explicit RemovablePositions(std::uint32_t n) : next_(std::size_t(n) + 1) {
    std::iota(next_.begin(), next_.end(), 0u);
  }
  std::uint32_t first(std::uint32_t i) {
    while (next_[i] != i) {
      next_[i] = next_[next_[i]];
      i = next_[i];
    }
    return i;
  }
  void remove(std::uint32_t i) { next_[i] = i + 1; }

 private:
  std::vector<std::uint32_t> next_;
};

}  // namespace rastrace

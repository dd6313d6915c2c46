// The seeded generator behind every random choice of an algorithm (the random order, local
// optimization's visiting order, the adjacency cover's perturbations): splitmix64 (Steele, Lea,
// Flood, "Fast splittable pseudorandom number generators", OOPSLA 2014). std:: engines are
// portable but std:: distributions and std::shuffle are not: the same seed gives different
// results with another standard library. Drawing with below() and shuffling with shuffle() here
// keeps a seed's result identical everywhere.
#pragma once

#include <cstdint>
#include <span>
#include <utility>

namespace rastrace {

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : state_(seed) {}

  // The next 64 uniformly distributed bits.
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }

  // A value in [0, n), n > 0. The modulo's bias is below n / 2^64: negligible for any n used here.
  std::uint64_t below(std::uint64_t n) { return next() % n; }
  // A double in [0, 1): the top 53 bits of next().
  double uniform() { return double(next() >> 11) * 0x1.0p-53; }

 private:
  std::uint64_t state_;
};

// splitmix64 of one value: a well-mixed 64-bit hash of x (the first output of Rng(x)), for
// seeded tie-breaking without a generator's state.
inline std::uint64_t mix64(std::uint64_t x) { return Rng(x).next(); }

// Fisher-Yates: a uniformly random permutation of `values`, the same for a given generator state
// on every platform.
template <typename T>
void shuffle(std::span<T> values, Rng& rng) {
  for (std::size_t i = values.size(); i > 1; --i) std::swap(values[i - 1], values[rng.below(i)]);
}

}  // namespace rastrace

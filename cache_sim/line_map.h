// A flat open-addressing hash map from a cache line number to a 32-bit slot, for the simulators'
// hot loops (linear probing, backward-shift deletion, no allocation after construction unless it
// has to grow). The key ~0 is reserved as "empty".
#pragma once

#include <cstdint>
#include <vector>

namespace rastrace {

class LineMap {
 public:
  static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};
  static constexpr std::uint32_t kMissing = ~std::uint32_t{0};

  explicit LineMap(std::uint64_t expected = 64) { reset(expected); }

  void reset(std::uint64_t expected) {
    std::uint64_t capacity = 16;
    while (capacity < expected * 2) capacity *= 2;
    keys_.assign(capacity, kEmpty);
    values_.assign(capacity, 0);
    mask_ = capacity - 1;
    size_ = 0;
  }

  std::uint32_t find(std::uint64_t key) const {
    for (std::uint64_t i = hash(key) & mask_;; i = (i + 1) & mask_) {
      if (keys_[i] == key) return values_[i];
      if (keys_[i] == kEmpty) return kMissing;
    }
  }

  // Returns a reference to the value, inserting `fresh` when the key is new (sets `inserted`).
  std::uint32_t& find_or_insert(std::uint64_t key, std::uint32_t fresh, bool& inserted) {
    if ((size_ + 1) * 2 > keys_.size()) grow();
    std::uint64_t i = hash(key) & mask_;
    for (;; i = (i + 1) & mask_) {
      if (keys_[i] == key) {
        inserted = false;
        return values_[i];
      }
      if (keys_[i] == kEmpty) break;
    }
    keys_[i] = key;
    values_[i] = fresh;
    ++size_;
    inserted = true;
    return values_[i];
  }

  void insert(std::uint64_t key, std::uint32_t value) {
    bool inserted;
    find_or_insert(key, value, inserted) = value;
  }

  void erase(std::uint64_t key) {
    std::uint64_t i = hash(key) & mask_;
    while (keys_[i] != key) {
      if (keys_[i] == kEmpty) return;
      i = (i + 1) & mask_;
    }
    // Backward shift: pull later members of the probe run into the hole.
    std::uint64_t hole = i;
    for (std::uint64_t j = (i + 1) & mask_; keys_[j] != kEmpty; j = (j + 1) & mask_) {
      const std::uint64_t home = hash(keys_[j]) & mask_;
      if (((j - home) & mask_) >= ((j - hole) & mask_)) {
        keys_[hole] = keys_[j];
        values_[hole] = values_[j];
        hole = j;
      }
    }
    keys_[hole] = kEmpty;
    --size_;
  }

  std::uint64_t size() const { return size_; }

  template <typename Visit>
  void for_each(Visit&& visit) const {
    for (std::size_t i = 0; i < keys_.size(); ++i)
      if (keys_[i] != kEmpty) visit(keys_[i], values_[i]);
  }

 private:
  static std::uint64_t hash(std::uint64_t key) {
    key ^= key >> 33;
    key *= 0xff51afd7ed558ccdull;
    key ^= key >> 33;
    return key;
  }

  void grow() {
    std::vector<std::uint64_t> keys = std::move(keys_);
    std::vector<std::uint32_t> values = std::move(values_);
    keys_.assign(keys.size() * 2, kEmpty);
    values_.assign(keys.size() * 2, 0);
    mask_ = keys_.size() - 1;
    size_ = 0;
    for (std::size_t i = 0; i < keys.size(); ++i)
      if (keys[i] != kEmpty) insert(keys[i], values[i]);
  }

  std::vector<std::uint64_t> keys_;
  std::vector<std::uint32_t> values_;
  std::uint64_t mask_ = 0;
  std::uint64_t size_ = 0;
};

}  // namespace rastrace

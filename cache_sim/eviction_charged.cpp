#include "cache_sim/eviction_charged.h"

#include <algorithm>
#include <vector>

#include "cache_sim/vertex_cache.h"
#include "core/error.h"

namespace rastrace {

namespace {

class EvictionChargedFifo {
 public:
  explicit EvictionChargedFifo(unsigned entries) : entries_(entries) {}

  void add_primitive(const std::uint32_t* vertices, std::size_t count) {
    std::uint64_t absent = 0;  // a repeated absent vertex counts once per occurrence, as nvmesh did
    for (std::size_t i = 0; i < count; ++i) absent += !resident(vertices[i]);
    const std::uint64_t held = std::min<std::uint64_t>(inserted_, entries_);
    if (held + absent > entries_) charged_ += held + absent - entries_;
    for (std::size_t i = 0; i < count; ++i)
      if (!resident(vertices[i])) insert(vertices[i]);
  }

  // The vertices still cached were transformed too: nvmesh charged them when it flushed.
  std::uint64_t total() const { return charged_ + std::min<std::uint64_t>(inserted_, entries_); }

 private:
  bool resident(std::uint32_t vertex) const {
    return vertex < stamps_.size() && stamps_[vertex] != 0 && inserted_ - (stamps_[vertex] - 1) <= entries_;
  }
  void insert(std::uint32_t vertex) {
    if (vertex >= stamps_.size()) stamps_.resize(std::max<std::size_t>(std::size_t{vertex} + 1, stamps_.size() * 2), 0);
    stamps_[vertex] = ++inserted_;  // stamp - 1 = insertions before this one
  }

  unsigned entries_;
  std::uint64_t inserted_ = 0;
  std::uint64_t charged_ = 0;
  std::vector<std::uint64_t> stamps_;  // 0: never inserted
};

}  // namespace

std::uint64_t eviction_charged_transforms(std::span<const std::uint32_t> indices, PrimitiveType type, unsigned entries,
                                          RestartIndex restart_index) {
  if (entries == 0) throw InputError("vertex cache size 0: expected at least 1 entry");
  EvictionChargedFifo cache(entries);
  walk_index_stream(
      indices, type, restart_index, [](std::size_t, bool) {},
      [&](const AssembledTriangle& t) {
        if (type != PrimitiveType::TriangleStrip) {
          cache.add_primitive(&indices[t.first], t.count);
        } else if (!t.degenerate()) {
          // As a list, as the nvmesh simulator saw strips (NvTriStrip's lists-only output): the
          // strip's swaps and joins draw nothing and are not in it.
          cache.add_primitive(t.vertices.data(), 3);
        }
      });
  return cache.total();
}

}  // namespace rastrace

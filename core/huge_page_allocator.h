// An allocator for large, append-only buffers (a frame's events: tens of megabytes), for
// std::vector. Blocks of 2 MiB or more are mapped 2 MiB-aligned and advised as transparent huge
// pages (madvise MADV_HUGEPAGE, Linux), so first touching a fresh block faults once per 2 MiB
// instead of once per 4 KiB. On a virtualised or loaded machine a 4 KiB fault costs
// microseconds: filling 50 MB of fresh events took longer than rendering the frame. Smaller
// blocks, and systems without huge pages, use ordinary allocation (the advice is only advice).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>

#include <sys/mman.h>

namespace rastrace {

template <typename T>
class HugePageAllocator {
 public:
  using value_type = T;
  static constexpr std::size_t kHugePage = std::size_t{2} << 20;

  HugePageAllocator() = default;
  template <typename U>
  HugePageAllocator(const HugePageAllocator<U>&) {}

  T* allocate(std::size_t n) {
    if (n > static_cast<std::size_t>(-1) / sizeof(T) - kHugePage) throw std::bad_alloc();
    const std::size_t bytes = n * sizeof(T);
    if (bytes < kHugePage) return std::allocator<T>{}.allocate(n);
    const std::size_t mapped = rounded(bytes);
    // Map one huge page more than needed and unmap the slack either side of the aligned block.
    void* raw = mmap(nullptr, mapped + kHugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (raw == MAP_FAILED) throw std::bad_alloc();
    const auto start = reinterpret_cast<std::uintptr_t>(raw);
    const std::uintptr_t aligned = (start + kHugePage - 1) & ~(kHugePage - 1);
    if (aligned > start) munmap(raw, aligned - start);
    const std::size_t tail = start + mapped + kHugePage - (aligned + mapped);
    if (tail) munmap(reinterpret_cast<void*>(aligned + mapped), tail);
#ifdef MADV_HUGEPAGE
    madvise(reinterpret_cast<void*>(aligned), mapped, MADV_HUGEPAGE);
#endif
    return reinterpret_cast<T*>(aligned);
  }

  void deallocate(T* p, std::size_t n) noexcept {
    const std::size_t bytes = n * sizeof(T);
    if (bytes < kHugePage) {
      std::allocator<T>{}.deallocate(p, n);
      return;
    }
    munmap(p, rounded(bytes));
  }

  template <typename U>
  bool operator==(const HugePageAllocator<U>&) const {
    return true;
  }

 private:
  static std::size_t rounded(std::size_t bytes) { return (bytes + kHugePage - 1) & ~(kHugePage - 1); }
};

// A HugePageAllocator whose vectors leave the elements they grow by unset when those are
// trivially copyable (events): storage lent to a recorder (traces/sink.h) is written right
// after, and setting it first would store every event twice. resize() on such a vector thus
// gives unset elements, to be overwritten.
template <typename T>
struct UnsetHugePageAllocator : HugePageAllocator<T> {
  template <typename U>
  struct rebind {
    using other = UnsetHugePageAllocator<U>;
  };
  UnsetHugePageAllocator() = default;
  template <typename U>
  UnsetHugePageAllocator(const UnsetHugePageAllocator<U>&) {}
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args) {
    if constexpr (sizeof...(Args) == 0 && std::is_trivially_copyable_v<U> && std::is_trivially_destructible_v<U>)
      static_cast<void>(p);  // implicit-lifetime: the storage is the object
    else
      ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

}  // namespace rastrace

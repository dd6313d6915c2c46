#include "cache_sim/kerbl_batch.h"

#include <algorithm>
#include <stdexcept>

namespace rastrace {

KerblBatchParameters kerbl_parameters(KerblGpu gpu) {
  switch (gpu) {
    case KerblGpu::NvidiaD3d:
    case KerblGpu::NvidiaGl:
      return {96, 32, 0, true, 32};
    case KerblGpu::Amd:
      return {384, 64, 384, false, 64};
    case KerblGpu::Intel:
      return {1791, 128, 0, true, 8};
  }
  throw std::logic_error("kerbl_parameters: unknown GPU");
}

KerblBatch::KerblBatch(KerblGpu gpu) : gpu_(gpu), p_(kerbl_parameters(gpu)) {}

bool KerblBatch::reused(std::uint32_t vertex, std::uint64_t position) const {
  if (gpu_ == KerblGpu::Amd) return std::find(lru_.begin(), lru_.begin() + lru_size_, vertex) != lru_.begin() + lru_size_;
  if (vertex >= used_in_.size() || used_in_[vertex] != generation_) return false;
  const std::uint64_t last = last_use_[vertex];
  const std::uint64_t distance = position - last;
  switch (gpu_) {
    case KerblGpu::NvidiaGl:
      return distance <= 42;
    case KerblGpu::NvidiaD3d:
      switch (last % 3) {
        case 0:
          return distance < 45;
        case 1:
          return distance <= 40 || distance == 42;
        default:
          return distance <= 39 || distance == 41 || distance == 42;
      }
    default:
      return true;  // Intel: the whole batch
  }
}

void KerblBatch::use(std::uint32_t vertex, std::uint64_t position) {
  if (gpu_ == KerblGpu::Amd) {
    auto* const end = lru_.begin() + lru_size_;
    auto* const found = std::find(lru_.begin(), end, vertex);
    if (found != end) {
      std::rotate(found, found + 1, end);  // to the most recent end
    } else if (lru_size_ < lru_.size()) {
      lru_[lru_size_++] = vertex;
    } else {
      std::rotate(lru_.begin(), lru_.begin() + 1, lru_.end());  // evict the least recent
      lru_.back() = vertex;
    }
    return;
  }
  if (vertex >= used_in_.size()) {
    const std::size_t size = std::max<std::size_t>(std::size_t{vertex} + 1, used_in_.size() * 2);
    used_in_.resize(size, 0);
    last_use_.resize(size, 0);
  }
  used_in_[vertex] = generation_;
  last_use_[vertex] = position;
}

void KerblBatch::close_batch(bool hard) {
  batches_ += batch_indices_ > 0;
  warps_ += warps_for(batch_invocations_);
  batch_indices_ = batch_invocations_ = 0;
  if (gpu_ == KerblGpu::Amd) {
    if (hard) lru_size_ = 0;  // a soft cut keeps the LRU
    return;
  }
  if (++generation_ == 0) {  // wrapped: forget every stamp
    std::fill(used_in_.begin(), used_in_.end(), 0);
    generation_ = 1;
  }
}

void KerblBatch::primitive(const std::uint32_t* vertices, unsigned count) {
  if (p_.static_period && position_ > 0 && position_ % p_.static_period == 0 && period_start_ != position_) {
    close_batch(true);
    period_start_ = position_;
  }
  unsigned start = 0;  // first index of this primitive in the open batch
  unsigned adds = 0;   // its invocations in the open batch
  for (unsigned j = 0; j < count; ++j) {
    adds += !reused(vertices[j], position_ + j);
    const bool full =
        batch_invocations_ + adds > p_.batch_vertices || batch_indices_ + (j - start) + 1 > p_.batch_indices;
    if (!full) {
      use(vertices[j], position_ + j);
    } else if (p_.cut_at_triangles) {
      // The batch ends before this primitive: its indices so far start the next one.
      close_batch(false);
      adds = 0;
      for (unsigned k = 0; k <= j; ++k) {
        adds += !reused(vertices[k], position_ + k);
        use(vertices[k], position_ + k);
      }
    } else {
      // Cut at this index: the earlier ones stay in the old batch, this one opens the next.
      batch_invocations_ += adds - 1;
      invocations_ += adds - 1;
      batch_indices_ += j - start;
      close_batch(false);
      start = j;
      adds = 1;
      use(vertices[j], position_ + j);
    }
  }
  batch_invocations_ += adds;
  invocations_ += adds;
  batch_indices_ += count - start;
  position_ += count;
}

unsigned KerblBatch::append_cost(const std::uint32_t* triangle) const {
  if (!p_.cut_at_triangles) throw std::logic_error("KerblBatch::append_cost: the model does not cut at triangles");
  unsigned adds = 0;
  for (unsigned j = 0; j < 3; ++j) {
    // A corner repeating an earlier corner of the same triangle was just used: reused.
    const bool repeat = (j > 0 && triangle[j] == triangle[0]) || (j > 1 && triangle[j] == triangle[1]);
    adds += !repeat && !reused(triangle[j], position_ + j);
  }
  if (batch_invocations_ + adds > p_.batch_vertices || batch_indices_ + 3 > p_.batch_indices) return kDoesNotFit;
  return adds;
}

void KerblBatch::flush() {
  close_batch(true);
  position_ = period_start_ = 0;
}

}  // namespace rastrace

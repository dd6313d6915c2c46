#include "lod/sliding_window.h"

#include <algorithm>

#include "lod/skip_strips.h"
#include "lod/vanilla_numbering.h"

namespace rastrace {

std::vector<std::uint32_t> sliding_window_level_starts(const ProgressiveMesh& pm) {
  std::vector<std::uint32_t> starts{0};
  std::vector<std::uint32_t> changed_in(pm.triangles.size(), 0);  // level + 1 of the last change
  for (std::uint32_t n = 0; n < pm.collapses.size(); ++n) {
    const CollapseRecord& c = pm.collapses[n];
    auto conflicts = [&](std::uint32_t t) { return changed_in[t] == starts.size(); };
    if (std::any_of(c.binned_triangles.begin(), c.binned_triangles.end(), conflicts) ||
        std::any_of(c.changed_triangles.begin(), c.changed_triangles.end(), conflicts))
      starts.push_back(n);
    for (std::uint32_t t : c.changed_triangles) changed_in[t] = static_cast<std::uint32_t>(starts.size());
  }
  return starts;
}

SlidingWindow::SlidingWindow(std::vector<std::uint32_t> indices, std::vector<SlidingWindowRecord> records,
                             std::vector<std::uint32_t> level_first_lod, std::uint32_t vertex_bytes)
    : indices_(std::move(indices)),
      records_(std::move(records)),
      level_first_lod_(std::move(level_first_lod)),
      vertex_bytes_(vertex_bytes) {
  const std::uint32_t vertices = records_.empty() ? 0 : records_.front().vertices;
  index_bytes_ = vipm_index_bytes(vertices);
  std::uint32_t max_count = 0;
  for (const SlidingWindowRecord& r : records_) max_count = std::max({max_count, r.triangles, r.vertices});
  record_bytes_ = max_count <= 0xFFFF ? 8 : 12;
}

LodChangeCost SlidingWindow::set_lod(std::uint32_t lod) {
  lod_ = std::min<std::uint32_t>(lod, lod_count() - 1);
  LodChangeCost cost;
  cost.record_bytes_read = record_bytes_;
  return cost;
}

std::vector<VipmDraw> SlidingWindow::draws() const {
  const SlidingWindowRecord& r = records_[lod_];
  if (r.triangles == 0) return {};
  return {VipmDraw{PrimitiveType::TriangleList,
                   std::span<const std::uint32_t>(indices_.data() + r.first_index, 3 * std::size_t(r.triangles)),
                   kNoRestart, r.vertices, std::uint64_t(r.first_index) * index_bytes_}};
}

VipmMemory SlidingWindow::memory() const {
  VipmMemory m;
  m.vertex_bytes = std::uint64_t(records_.front().vertices) * vertex_bytes_;
  m.index_list_bytes = indices_.size() * index_bytes_;
  m.table_bytes = records_.size() * record_bytes_;
  m.instance_bytes = kInstanceBytes;
  return m;
}

std::uint64_t SlidingWindow::streaming_bytes() const {
  const SlidingWindowRecord& r = records_[lod_];
  return std::uint64_t(r.vertices) * vertex_bytes_ + 3 * std::uint64_t(r.triangles) * index_bytes_ + record_bytes_;
}

std::uint32_t SlidingWindow::level() const {
  return static_cast<std::uint32_t>(std::upper_bound(level_first_lod_.begin(), level_first_lod_.end(), lod_) -
                                    level_first_lod_.begin() - 1);
}

std::string SlidingWindow::layout() const {
  return "SlidingWindowRecord " + std::to_string(record_bytes_) + " bytes (first index 32-bit, counts " +
         (record_bytes_ == 8 ? "16" : "32") + "-bit)";
}

std::unique_ptr<SlidingWindow> build_sliding_window(const ProgressiveMesh& pm, const Mesh& vertices,
                                                    const SlidingWindowParams& window, const VipmBuildParams& params) {
  using Triangle = std::array<std::uint32_t, 3>;
  const auto vertex_count = static_cast<std::uint32_t>(pm.vertex_order.size());
  const auto last = static_cast<std::uint32_t>(pm.collapses.size());
  std::vector<std::uint32_t> starts = sliding_window_level_starts(pm);
  std::vector<std::uint32_t> indices;
  std::vector<SlidingWindowRecord> records(last + 1);
  TriangleReplay replay(pm);
  std::vector<std::uint8_t> touched(pm.triangles.size(), 0);
  for (std::size_t l = 0; l < starts.size(); ++l) {
    const std::uint32_t first = starts[l];
    const std::uint32_t end = l + 1 < starts.size() ? starts[l + 1] : last;
    replay.advance_to(first);
    const std::uint32_t alive = replay.alive();
    for (std::uint32_t n = first; n < end; ++n) {
      for (std::uint32_t t : pm.collapses[n].binned_triangles) touched[t] = 1;
      for (std::uint32_t t : pm.collapses[n].changed_triangles) touched[t] = 1;
    }
    std::vector<Triangle> middle;
    for (std::uint32_t t = 0; t < alive; ++t)
      if (!touched[t]) middle.push_back(replay.triangle(t));
    auto put = [&](const Triangle& t) { indices.insert(indices.end(), t.begin(), t.end()); };
    // Added section: the new versions, last collapse first.
    std::vector<std::uint32_t> added(end - first, 0), removed(end - first, 0);
    for (std::uint32_t n = end; n-- > first;) {
      const CollapseRecord& c = pm.collapses[n];
      for (std::size_t i = 0; i < c.changed_triangles.size(); ++i) {
        Triangle t = replay.triangle(c.changed_triangles[i]);
        t[c.changed_corners[i] % 3] = c.kept;
        put(t);
      }
      added[n - first] = static_cast<std::uint32_t>(c.changed_triangles.size());
    }
    const auto middle_at = static_cast<std::uint32_t>(indices.size());
    if (!middle.empty()) {
      const std::vector<std::uint32_t> ordered =
          lod_detail::order_triangles(vertices, middle, window.algorithm, window.reorder, PrimitiveType::TriangleList)
              .indices;
      indices.insert(indices.end(), ordered.begin(), ordered.end());
    }
    // Binned-or-changed section: the old versions, first collapse at the end.
    for (std::uint32_t n = end; n-- > first;) {
      const CollapseRecord& c = pm.collapses[n];
      std::vector<std::uint32_t> old(c.binned_triangles);
      old.insert(old.end(), c.changed_triangles.begin(), c.changed_triangles.end());
      std::sort(old.begin(), old.end());
      for (std::uint32_t t : old) put(replay.triangle(t));
      removed[n - first] = static_cast<std::uint32_t>(old.size());
    }
    const auto level_end = static_cast<std::uint32_t>(indices.size());
    // LoD first + j: the j newest added blocks before the middle, the j first removed blocks cut.
    std::uint32_t start = middle_at, stop = level_end;
    const std::uint32_t lods = (l + 1 < starts.size() ? end : last + 1) - first;
    for (std::uint32_t j = 0; j < lods; ++j) {
      if (j > 0) {
        start -= 3 * added[j - 1];
        stop -= 3 * removed[j - 1];
      }
      records[first + j] = {start, (stop - start) / 3, vertex_count - (first + j)};
    }
    for (std::uint32_t n = first; n < end; ++n) {
      for (std::uint32_t t : pm.collapses[n].binned_triangles) touched[t] = 0;
      for (std::uint32_t t : pm.collapses[n].changed_triangles) touched[t] = 0;
    }
  }
  return std::make_unique<SlidingWindow>(std::move(indices), std::move(records), std::move(starts),
                                         params.vertex_bytes);
}

}  // namespace rastrace

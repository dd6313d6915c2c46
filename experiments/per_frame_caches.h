// Cache counts frame by frame, for several frames drawn (render --frames N) or replayed (replay
// --per-frame) through caches that keep their contents between frames: the inter-frame reuse
// that Cox, Bhandari and Shantz ("Multi-level texture caching for 3D graphics hardware", ISCA
// 1998) measure for an L2 of 0.25-4 MB. Every cache is a hierarchy of a HierarchySink (a single
// texture cache being a one-level hierarchy), so the live render and the replay of its trace run
// the same model and give the same rows.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "cache_sim/hierarchy_sink.h"
#include "core/table.h"
#include "experiments/hierarchy_tables.h"

namespace rastrace {

// Put beside the HierarchySink in a TeeSink: takes the sink's cumulative counts when a frame ends
// (at begin_frame of the next frame, and at finish()). Events before any begin_frame are frame 0.
class FrameCountsSink final : public EventSink {
 public:
  explicit FrameCountsSink(const HierarchySink& caches) : caches_(caches) {}
  void begin_frame(std::uint32_t frame) override;
  void finish() override;

  struct FrameEnd {
    std::uint32_t frame = 0;
    std::vector<std::vector<LevelStats>> totals;  // per hierarchy, per level: counts up to the frame's end
  };
  const std::vector<FrameEnd>& frames() const { return ends_; }

 private:
  void end_frame();
  const HierarchySink& caches_;
  std::uint32_t frame_ = 0;
  bool finished_ = false;
  std::vector<FrameEnd> ends_;
};

// "Caches per frame": one row per frame, cache and level with that frame's share of the counts:
// frame, cache (names[i] for hierarchy i), level, accesses, misses, line_misses, miss_rate,
// bytes_fetched (from the next level; memory below the last).
Table per_frame_table(TableParameters parameters, const std::vector<std::string>& names, const FrameCountsSink& counts);

// `rastrace replay TRACE --cache SPEC... --level SPEC... --per-frame`: every texture (or address)
// byte cache of the specs as a one-level hierarchy, and the --level hierarchy, replayed once; the
// per-frame table. Throws InputError for a bad trace or for specs that are not byte caches of
// texels or addresses (vertex, depth and colour caches; policy=opt, which needs the future).
Table per_frame_replay_table(const std::string& trace, const std::vector<std::string>& specs,
                             const HierarchyRequest& hierarchy, const std::string& option = "--cache");

}  // namespace rastrace

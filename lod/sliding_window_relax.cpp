#include "lod/sliding_window_relax.h"

#include <algorithm>
#include <set>
#include <utility>

#include "core/error.h"
#include "lod/sliding_window.h"
#include "lod/vanilla_numbering.h"

namespace rastrace {

RelaxedOrder relax_for_sliding_window(const ProgressiveMesh& pm, double tolerance) {
  if (!(tolerance >= 0.0)) throw InputError("--tolerance " + std::to_string(tolerance) + ": expected a value >= 0");
  const std::size_t count = pm.collapses.size();
  const auto vertex_count = static_cast<std::uint32_t>(pm.vertex_order.size());

  // predecessors[n]: the earlier collapses whose one-ring held n's binned vertex.
  std::vector<std::vector<std::uint32_t>> predecessors(count);
  {
    std::vector<std::vector<std::uint32_t>> touched_by(vertex_count);
    TriangleReplay replay(pm);
    std::vector<std::uint32_t> seen(vertex_count, 0);
    for (std::uint32_t n = 0; n < count; ++n) {
      const CollapseRecord& c = pm.collapses[n];
      auto ring = [&](std::uint32_t t) {
        for (std::uint32_t v : replay.triangle(t))
          if (v != c.binned && seen[v] != n + 1) {
            seen[v] = n + 1;
            touched_by[v].push_back(n);
          }
      };
      for (std::uint32_t t : c.binned_triangles) ring(t);
      for (std::uint32_t t : c.changed_triangles) ring(t);
      predecessors[n] = std::move(touched_by[c.binned]);
      touched_by[c.binned] = {};
      replay.advance_to(n + 1);
    }
  }

  double mean_error = 0.0;
  for (const CollapseRecord& c : pm.collapses) mean_error += c.error;
  if (count) mean_error /= double(count);
  const double slack = tolerance * mean_error;

  std::vector<std::uint8_t> done(count, 0);
  std::vector<std::uint32_t> changed_in(pm.triangles.size(), 0);  // level of the last change
  std::uint32_t level = 1;
  auto compatible = [&](std::uint32_t n) {
    const CollapseRecord& c = pm.collapses[n];
    auto conflicts = [&](std::uint32_t t) { return changed_in[t] == level; };
    return std::none_of(c.binned_triangles.begin(), c.binned_triangles.end(), conflicts) &&
           std::none_of(c.changed_triangles.begin(), c.changed_triangles.end(), conflicts);
  };
  auto ready = [&](std::uint32_t n) {
    return std::all_of(predecessors[n].begin(), predecessors[n].end(), [&](std::uint32_t p) { return done[p] != 0; });
  };
  // The collapses not done, by error (then by position), minus those blocked in this level:
  // a collapse that conflicts stays in conflict until the next level.
  std::set<std::pair<double, std::uint32_t>> open;
  for (std::uint32_t n = 0; n < count; ++n) open.insert({pm.collapses[n].error, n});
  std::vector<std::uint32_t> blocked;
  std::vector<std::uint32_t> order;
  order.reserve(count);
  RelaxedOrder out;
  auto take = [&](std::uint32_t n) {
    for (std::uint32_t t : pm.collapses[n].changed_triangles) changed_in[t] = level;
    done[n] = 1;
    open.erase({pm.collapses[n].error, n});
    order.push_back(n);
  };
  std::uint32_t head = 0;
  while (order.size() < count) {
    while (done[head]) ++head;
    if (compatible(head)) {
      take(head);
      continue;
    }
    const double bound = pm.collapses[head].error + slack;
    std::uint32_t found = head;
    for (auto it = open.begin(); it != open.end() && it->first <= bound;) {
      const std::uint32_t n = it->second;
      if (n != head && !compatible(n)) {
        blocked.push_back(n);
        it = open.erase(it);
        continue;
      }
      if (n != head && ready(n)) {
        found = n;
        break;
      }
      ++it;
    }
    if (found == head) {
      ++level;
      for (std::uint32_t n : blocked) open.insert({pm.collapses[n].error, n});
      blocked.clear();
    } else {
      ++out.out_of_order;
    }
    take(found);
  }

  // Rebuild the numbering for the new order (this also checks that it is a valid sequence).
  std::vector<HalfEdgeCollapse> sequence;
  sequence.reserve(count);
  for (std::uint32_t n : order)
    sequence.push_back({pm.collapses[n].binned, pm.collapses[n].kept, pm.collapses[n].error});
  Mesh input;
  input.name = pm.name;
  input.positions.resize(vertex_count);
  for (const auto& t : pm.triangles) input.indices.insert(input.indices.end(), t.begin(), t.end());
  out.pm = progressive_mesh_from_collapses(input, sequence);
  out.input_vertex = out.pm.vertex_order;
  for (std::uint32_t& v : out.pm.vertex_order) v = pm.vertex_order[v];
  for (std::uint32_t& t : out.pm.triangle_origin) t = pm.triangle_origin[t];
  out.levels = static_cast<std::uint32_t>(sliding_window_level_starts(out.pm).size());
  return out;
}

}  // namespace rastrace

// Sequential triangle strips (Evans, Skiena, Varshney 1996 "Optimizing triangle strips for fast
// rendering": the SGI tomesh greedy with swaps; NvTriStrip's restart-based strips), counted as in
// Yang, Mitra, Huang (vertices sent) and Hoppe 1999 (indices per triangle b). See strip.h.
#include "reorder/strip.h"

#include <algorithm>
#include <array>
#include <functional>

#include "reorder/local_opt.h"

namespace rastrace {

namespace {

bool degenerate(const std::uint32_t* v) { return v[0] == v[1] || v[1] == v[2] || v[0] == v[2]; }

// The neighbour of face f across its undirected edge (a, b), or kNoFace.
std::uint32_t neighbor_across(const Mesh& mesh, const MeshTopology& topology, std::uint32_t f, std::uint32_t a,
                              std::uint32_t b) {
  const int slot = edge_slot(mesh.indices.data() + 3 * std::size_t(f), a, b);
  return slot < 0 ? kNoFace : topology.neighbor(f, static_cast<unsigned>(slot));
}

}  // namespace


StripStats strip_stats(std::span<const std::uint32_t> indices, PrimitiveType type, std::uint32_t restart_index) {
  StripStats stats;
  stats.indices = indices.size();
  if (type != PrimitiveType::TriangleStrip) {
    const std::size_t per = type == PrimitiveType::TriangleList ? 3 : 6;
    stats.vertices_sent = indices.size();
    for (std::size_t i = 0; i + per <= indices.size(); i += per) {
      const std::uint32_t a = indices[i], b = indices[i + (per == 6 ? 2 : 1)], c = indices[i + (per == 6 ? 4 : 2)];
      ++stats.strips;
      if (a == b || b == c || a == c)
        ++stats.swaps;
      else
        ++stats.triangles;
    }
    return stats;
  }
  std::size_t in_strip = 0;
  for (std::size_t i = 0; i < indices.size(); ++i) {
    if (indices[i] == restart_index) {
      in_strip = 0;
      continue;
    }
    ++stats.vertices_sent;
    if (++in_strip == 1) ++stats.strips;
    if (in_strip >= 3) {
      const std::uint32_t a = indices[i - 2], b = indices[i - 1], c = indices[i];
      if (a == b || b == c || a == c)
        ++stats.swaps;
      else
        ++stats.triangles;
    }
  }
  return stats;
}

namespace {

// The emitter's state between faces: whether a strip is open and its last two vertices.
struct StripCursor {
  bool open = false;
  std::uint32_t u = 0, w = 0;  // the strip's last two vertices, older first
  std::uint64_t sent = 0;      // indices excluding restart markers
  std::uint64_t strips = 0;
};

// Emits face f, knowing the face that follows it (kNoFace at the end). An open strip was left
// by the previous face through the edge (u, w), which f shares.
template <typename Out>
void strip_step(const Mesh& mesh, const MeshTopology& topology, StripCursor& c, std::uint32_t f, std::uint32_t next,
                Out&& out) {
  const std::uint32_t* v = mesh.indices.data() + 3 * std::size_t(f);
  const bool more = next != kNoFace && strip_continues(mesh, topology, f, next);
  if (!c.open) {
    if (c.strips) out(kStripRestart);
    ++c.strips;
    c.sent += 3;
    int exit = -1;
    if (more)
      for (int s = 0; s < 3 && exit < 0; ++s)
        if (topology.neighbor(f, s) == next) exit = s;
    if (exit < 0) {
      out(v[0]);
      out(v[1]);
      out(v[2]);
      return;
    }
    // Rotate so the last two vertices are the edge shared with the next face.
    out(v[(exit + 2) % 3]);
    out(v[exit]);
    out(v[(exit + 1) % 3]);
    c.u = v[exit];
    c.w = v[(exit + 1) % 3];
    c.open = true;
    return;
  }
  const std::uint32_t u = c.u, w = c.w;
  const std::uint32_t nv = v[0] != u && v[0] != w ? v[0] : v[1] != u && v[1] != w ? v[1] : v[2];
  if (more && neighbor_across(mesh, topology, f, w, nv) == next) {
    out(nv);
    ++c.sent;
    c.u = w;
    c.w = nv;
  } else if (more && neighbor_across(mesh, topology, f, u, nv) == next) {
    out(u);  // swap: the repeated pivot makes one degenerate triangle
    out(nv);
    c.sent += 2;
    c.w = nv;
  } else {
    out(nv);
    ++c.sent;
    c.open = false;
  }
}

}  // namespace

Ordering strip_ordering(const Mesh& mesh, const MeshTopology& topology, std::vector<std::uint32_t> order) {
  Ordering ordering;
  ordering.type = PrimitiveType::TriangleStrip;
  ordering.restart_index = kStripRestart;
  std::vector<std::uint32_t>& out = ordering.indices;
  out.reserve(order.size() * 3 / 2 + 16);
  StripCursor cursor;
  for (std::size_t i = 0; i < order.size(); ++i)
    strip_step(mesh, topology, cursor, order[i], i + 1 < order.size() ? order[i + 1] : kNoFace,
               [&](std::uint32_t index) { out.push_back(index); });
  ordering.face_order = std::move(order);
  return ordering;
}

Ordering reorder_strip(const Mesh& mesh, const ReorderParams& params) {
  const MeshTopology topology = build_mesh_topology(mesh);
  const std::uint32_t F = topology.face_count;
  const std::uint32_t* idx = mesh.indices.data();

  std::vector<std::uint8_t> visited(F, 0);
  std::vector<std::uint8_t> unvisited_neighbors(F, 0);
  for (std::uint32_t f = 0; f < F; ++f) unvisited_neighbors[f] = static_cast<std::uint8_t>(topology.neighbor_count(f));
  // Bucket queue by unvisited-neighbour count with lazy deletion: an entry is live while the face
  // is unvisited and its count still equals the bucket. Faces are pushed in reverse so that ties
  // resolve to the lowest face id first.
  std::array<std::vector<std::uint32_t>, 4> buckets;
  for (std::uint32_t f = F; f-- > 0;) buckets[unvisited_neighbors[f]].push_back(f);
  auto pop_fewest = [&]() -> std::uint32_t {
    for (unsigned b = 0; b < 4; ++b) {
      std::vector<std::uint32_t>& bucket = buckets[b];
      while (!bucket.empty() && (visited[bucket.back()] || unvisited_neighbors[bucket.back()] != b)) bucket.pop_back();
      if (!bucket.empty()) return bucket.back();
    }
    return kNoFace;
  };
  auto visit = [&](std::uint32_t f) {
    visited[f] = 1;
    for (unsigned s = 0; s < 3; ++s) {
      const std::uint32_t g = topology.neighbor(f, s);
      if (g == kNoFace || visited[g]) continue;
      buckets[--unvisited_neighbors[g]].push_back(g);
    }
  };

  // Experiments (NvTriStrip's idea): grow a candidate strip without committing it; faces taken by
  // the experiment carry the current stamp.
  std::vector<std::uint32_t> taken(F, 0);
  std::uint32_t stamp = 0;
  auto live = [&](std::uint32_t g) { return g != kNoFace && !visited[g] && taken[g] != stamp; };
  auto live_neighbors = [&](std::uint32_t g) {
    return int(live(topology.neighbor(g, 0))) + int(live(topology.neighbor(g, 1))) + int(live(topology.neighbor(g, 2)));
  };
  enum class Mode { Zigzag, FewestNeighbors, AvoidSwaps };
  // Returns the number of swaps; the faces go to `strip`.
  auto grow = [&](std::uint32_t f, unsigned first_exit, Mode mode, std::vector<std::uint32_t>& strip) {
    ++stamp;
    strip.clear();
    std::uint64_t swaps = 0;
    std::uint32_t u = 0, w = 0;  // the strip's last two vertices, older first
    for (;;) {
      taken[f] = stamp;
      strip.push_back(f);
      const std::uint32_t* v = idx + 3 * std::size_t(f);
      if (degenerate(v)) break;
      const bool first = strip.size() == 1;
      const std::uint32_t nv = first ? 0 : v[0] != u && v[0] != w ? v[0] : v[1] != u && v[1] != w ? v[1] : v[2];
      auto is_swap = [&](unsigned s) {
        if (first) return false;
        const std::uint32_t a = v[s], b = v[(s + 1) % 3];
        return !((a == w && b == nv) || (a == nv && b == w));
      };
      int best = -1;
      int best_key[3] = {0, 0, 0};
      for (unsigned s = 0; s < 3; ++s) {
        const std::uint32_t g = topology.neighbor(f, s);
        if (!live(g) || degenerate(idx + 3 * std::size_t(g))) continue;
        if (first && s != first_exit) continue;
        if (mode == Mode::Zigzag && is_swap(s)) continue;
        int next_min = -1;  // no live neighbour at all is best: the strip ends cleanly there
        for (unsigned t = 0; t < 3; ++t) {
          const std::uint32_t h = topology.neighbor(g, t);
          if (!live(h) || h == f) continue;
          const int count = live_neighbors(h) - 1;  // g is about to be taken
          if (next_min < 0 || count < next_min) next_min = count;
        }
        const int fewest = live_neighbors(g);
        const int swap = is_swap(s) ? 1 : 0;
        int key[3] = {fewest, next_min, swap};
        if (mode == Mode::AvoidSwaps) {
          key[0] = swap;
          key[1] = fewest;
          key[2] = next_min;
        }
        if (best < 0 || key[0] < best_key[0] || (key[0] == best_key[0] && key[1] < best_key[1]) ||
            (key[0] == best_key[0] && key[1] == best_key[1] && key[2] < best_key[2])) {
          best = static_cast<int>(s);
          for (int k = 0; k < 3; ++k) best_key[k] = key[k];
        }
      }
      if (best < 0) break;
      const std::uint32_t a = v[best], b = v[(best + 1) % 3];
      if (first) {
        u = a;
        w = b;
      } else if (!is_swap(static_cast<unsigned>(best))) {
        u = w;
        w = nv;
      } else {
        w = nv;  // swap: u stays the pivot
        ++swaps;
      }
      f = topology.neighbor(f, static_cast<unsigned>(best));
    }
    return swaps;
  };

  std::vector<std::uint32_t> order;
  order.reserve(F);
  std::vector<std::uint32_t> candidate, best_strip;
  std::vector<std::vector<std::uint32_t>> strips;
  std::vector<std::uint32_t> starts, isolated_mark(F, 0);
  constexpr unsigned kStarts = 8;
  for (;;) {
    const std::uint32_t first = pop_fewest();
    if (first == kNoFace) break;
    // Candidate starts: the most recent faces with the fewest unvisited neighbours.
    starts.assign(1, first);
    {
      const std::vector<std::uint32_t>& bucket = buckets[unvisited_neighbors[first]];
      for (std::size_t i = bucket.size(); i-- > 0 && starts.size() < kStarts;) {
        const std::uint32_t g = bucket[i];
        if (visited[g] || unvisited_neighbors[g] != unvisited_neighbors[first] ||
            std::find(starts.begin(), starts.end(), g) != starts.end())
          continue;
        starts.push_back(g);
      }
    }
    // Keep the experiment with the fewest vertices sent per triangle, counting the faces it
    // leaves isolated (each will be a 3-vertex strip of its own).
    double best_cost = 0.0;
    best_strip.clear();
    for (const std::uint32_t f : starts)
      for (Mode mode : {Mode::FewestNeighbors, Mode::AvoidSwaps, Mode::Zigzag})
        for (unsigned exit = 0; exit < 3; ++exit) {
          const std::uint64_t swaps = grow(f, exit, mode, candidate);
          std::uint64_t isolated = 0;
          for (const std::uint32_t h : candidate)
            for (unsigned t = 0; t < 3; ++t) {
              const std::uint32_t g = topology.neighbor(h, t);
              if (!live(g) || isolated_mark[g] == stamp || live_neighbors(g) != 0) continue;
              isolated_mark[g] = stamp;
              ++isolated;
            }
          const double cost = double(candidate.size() + 2 + swaps + 3 * isolated) / double(candidate.size() + isolated);
          if (best_strip.empty() || cost < best_cost) {
            best_cost = cost;
            best_strip.swap(candidate);
          }
        }
    for (const std::uint32_t g : best_strip) visit(g);
    strips.push_back(best_strip);
  }

  // Join strips whose end faces are neighbours when that sends fewer vertices (a join saves a
  // restart but may shift the strip's left/right phase and cost swaps). Each strip first takes
  // whichever direction sends fewer vertices. Strips are face sequences: joining is concatenation.
  auto ignore = [](std::uint32_t) {};
  struct Evaluated {
    std::uint64_t sent = 0;
    StripCursor before_last;  // state once all but the last face are emitted
  };
  auto evaluate_from = [&](StripCursor c, std::uint32_t first_next, const std::vector<std::uint32_t>& tail_faces,
                           const std::vector<std::uint32_t>& faces) {
    // Emits tail_faces' last face (if any) followed by faces.
    Evaluated e;
    if (!tail_faces.empty())
      strip_step(mesh, topology, c, tail_faces.back(), faces.empty() ? kNoFace : first_next, ignore);
    for (std::size_t i = 0; i < faces.size(); ++i) {
      if (i + 1 == faces.size()) e.before_last = c;
      strip_step(mesh, topology, c, faces[i], i + 1 < faces.size() ? faces[i + 1] : kNoFace, ignore);
    }
    e.sent = c.sent;
    return e;
  };
  static const std::vector<std::uint32_t> kEmpty;
  std::vector<Evaluated> eval(strips.size());
  for (std::uint32_t id = 0; id < strips.size(); ++id) {
    std::vector<std::uint32_t>& strip = strips[id];
    Evaluated forward = evaluate_from(StripCursor{}, kNoFace, kEmpty, strip);
    std::reverse(strip.begin(), strip.end());
    Evaluated backward = evaluate_from(StripCursor{}, kNoFace, kEmpty, strip);
    if (backward.sent < forward.sent)
      eval[id] = backward;
    else {
      std::reverse(strip.begin(), strip.end());
      eval[id] = forward;
    }
  }
  constexpr std::uint32_t kNone = 0xFFFFFFFFu;
  std::vector<std::uint32_t> end_of(F, kNone);  // strip id of a face that ends a live strip
  for (std::uint32_t id = 0; id < strips.size(); ++id) {
    end_of[strips[id].front()] = id;
    end_of[strips[id].back()] = id;
  }
  std::vector<std::uint8_t> merged(strips.size(), 0);
  std::vector<std::uint32_t> appended;
  for (std::uint32_t id = 0; id < strips.size(); ++id) {
    if (merged[id]) continue;
    std::vector<std::uint32_t>& s = strips[id];
    for (int side = 0; side < 2; ++side) {
      if (side == 1) {
        std::reverse(s.begin(), s.end());
        eval[id] = evaluate_from(StripCursor{}, kNoFace, kEmpty, s);
      }
      for (bool joined = true; joined;) {
        joined = false;
        const std::uint32_t tail = s.back();
        for (unsigned k = 0; k < 3 && !joined; ++k) {
          const std::uint32_t g = topology.neighbor(tail, k);
          if (g == kNoFace || end_of[g] == kNone || end_of[g] == id || !strip_continues(mesh, topology, tail, g))
            continue;
          const std::uint32_t other = end_of[g];
          appended = strips[other];
          if (appended.front() != g) std::reverse(appended.begin(), appended.end());
          const Evaluated e = evaluate_from(eval[id].before_last, appended.front(), s, appended);
          if (e.sent >= eval[id].sent + eval[other].sent) continue;
          end_of[strips[other].front()] = kNone;
          end_of[strips[other].back()] = kNone;
          end_of[tail] = s.size() == 1 ? id : kNone;
          for (const std::uint32_t face : appended) s.push_back(face);
          strips[other].clear();
          merged[other] = 1;
          eval[id] = e;
          end_of[s.front()] = id;
          end_of[s.back()] = id;
          joined = true;
        }
      }
    }
    end_of[s.front()] = kNone;
    end_of[s.back()] = kNone;
    order.insert(order.end(), s.begin(), s.end());
  }
  ReorderParams local = params;
  local.iteration_budget =
      params.iteration_budget ? params.iteration_budget : std::clamp<std::uint64_t>(F / 2, 1, 4000);
  auto improve_strips = [&]() {
    // Strips as runs of continuing faces.
    std::vector<std::vector<std::uint32_t>> runs;
    for (std::size_t begin = 0; begin < order.size();) {
      std::size_t end = begin + 1;
      while (end < order.size() && strip_continues(mesh, topology, order[end - 1], order[end])) ++end;
      runs.emplace_back(order.begin() + std::ptrdiff_t(begin), order.begin() + std::ptrdiff_t(end));
      begin = end;
    }
    // Tunnelling (after Stewart's tunnelling for strips, a few steps deep): a strip end touching
    // the inside of strip B takes one half of B; the other half's new end goes on to touch another
    // strip, and so on until an end of some strip is reached and joined. Kept when the strips
    // involved send fewer vertices, one strip fewer.
    std::vector<std::uint32_t> run_of(F), index_in_run(F);
    auto reindex = [&]() {
      for (std::uint32_t r = 0; r < runs.size(); ++r)
        for (std::uint32_t i = 0; i < runs[r].size(); ++i) {
          run_of[runs[r][i]] = r;
          index_in_run[runs[r][i]] = i;
        }
    };
    reindex();
    // Emission cost of base + faces, continuing from base's evaluation (base_last: its last face).
    auto extend = [&](const Evaluated& base, std::uint32_t base_last, const std::uint32_t* faces, std::size_t n) {
      if (n == 0) return base;
      Evaluated e;
      StripCursor c = base.before_last;
      if (base_last != kNoFace) strip_step(mesh, topology, c, base_last, faces[0], ignore);
      for (std::size_t i = 0; i < n; ++i) {
        if (i + 1 == n) e.before_last = c;
        strip_step(mesh, topology, c, faces[i], i + 1 < n ? faces[i + 1] : kNoFace, ignore);
      }
      e.sent = c.sent;
      return e;
    };
    std::vector<std::uint64_t> run_sent(runs.size());
    for (std::uint32_t r = 0; r < runs.size(); ++r)
      run_sent[r] = extend(Evaluated{}, kNoFace, runs[r].data(), runs[r].size()).sent;
    // chain(): the strip being rebuilt (its free end `t` last, evaluated as `ev`) meets the strip X
    // of a neighbour of t: an end of X joins it (done); an inside face of X takes one half of X
    // into it and the other half continues the chain. `gain`: old minus new vertices so far.
    struct Step {
      std::uint32_t x, i;
      int option;  // 0: X[i], X[i-1].. joins, X[i+1].. rests; 1: X[i].. joins; -1: end join
    };
    std::vector<Step> steps;
    std::uint32_t steps_origin = 0;
    std::vector<std::uint32_t> scratch;
    std::function<bool(const Evaluated&, std::uint32_t, int, std::int64_t)> chain =
        [&](const Evaluated& ev, std::uint32_t t, int depth, std::int64_t gain) -> bool {
      for (unsigned k = 0; k < 3; ++k) {
        const std::uint32_t m = topology.neighbor(t, k);
        if (m == kNoFace || !strip_continues(mesh, topology, t, m)) continue;
        const std::uint32_t x = run_of[m], i = index_in_run[m];
        bool used = false;
        for (const Step& step : steps) used |= step.x == x;
        if (used || x == steps_origin) continue;
        const std::vector<std::uint32_t>& X = runs[x];
        const std::int64_t x_sent = std::int64_t(run_sent[x]);
        if (i == 0 || i + 1 == X.size()) {
          scratch.assign(X.begin(), X.end());
          if (i != 0) std::reverse(scratch.begin(), scratch.end());
          if (gain + x_sent - std::int64_t(extend(ev, t, scratch.data(), scratch.size()).sent) > 0) {
            steps.push_back({x, i, -1});
            return true;
          }
          continue;
        }
        if (depth == 0) continue;
        for (int option = 0; option < 2; ++option) {
          std::vector<std::uint32_t> half, rest;
          if (option == 0) {
            half.assign(X.rend() - std::ptrdiff_t(i) - 1, X.rend());    // X[i], X[i-1], .., X[0]
            rest.assign(X.rbegin(), X.rend() - std::ptrdiff_t(i) - 1);  // .., X[i+1]
          } else {
            half.assign(X.begin() + i, X.end());
            rest.assign(X.begin(), X.begin() + i);  // .., X[i-1]
          }
          const std::int64_t next_gain = gain + x_sent - std::int64_t(extend(ev, t, half.data(), half.size()).sent);
          if (next_gain < -2) continue;  // a final join saves at most 2 more
          steps.push_back({x, i, option});
          if (chain(extend(Evaluated{}, kNoFace, rest.data(), rest.size()), rest.back(), depth - 1, next_gain))
            return true;
          steps.pop_back();
        }
      }
      return false;
    };
    constexpr int kDepth = 3;
    for (int round = 0; round < 8; ++round) {
      bool improved = false;
      for (std::uint32_t a = 0; a < runs.size(); ++a) {
        for (int side = 0; side < 2 && !runs[a].empty(); ++side) {
          std::vector<std::uint32_t> current = runs[a];
          if (side == 1) std::reverse(current.begin(), current.end());
          steps.clear();
          steps_origin = a;
          if (!chain(extend(Evaluated{}, kNoFace, current.data(), current.size()), current.back(), kDepth,
                     std::int64_t(run_sent[a])))
            continue;
          // Rebuild: the strip grows through the steps; each consumed strip's slot takes the next
          // rebuilt strip, the last one is emptied.
          std::uint32_t slot = a;
          for (const Step& step : steps) {
            const std::vector<std::uint32_t> X = runs[step.x];
            std::vector<std::uint32_t> rest;
            if (step.option < 0) {
              if (step.i == 0)
                current.insert(current.end(), X.begin(), X.end());
              else
                current.insert(current.end(), X.rbegin(), X.rend());
            } else if (step.option == 0) {
              current.insert(current.end(), X.rend() - std::ptrdiff_t(step.i) - 1, X.rend());
              rest.assign(X.rbegin(), X.rend() - std::ptrdiff_t(step.i) - 1);
            } else {
              current.insert(current.end(), X.begin() + step.i, X.end());
              rest.assign(X.begin(), X.begin() + step.i);
            }
            runs[slot] = std::move(current);
            run_sent[slot] = extend(Evaluated{}, kNoFace, runs[slot].data(), runs[slot].size()).sent;
            current = std::move(rest);
            slot = step.x;
          }
          runs[slot].clear();
          run_sent[slot] = 0;
          reindex();
          improved = true;
        }
      }
      if (!improved) break;
    }
    // Each strip takes the direction that sends fewer vertices.
    order.clear();
    for (std::vector<std::uint32_t>& run : runs) {
      if (run.empty()) continue;
      const std::uint64_t forward = evaluate_from(StripCursor{}, kNoFace, kEmpty, run).sent;
      std::reverse(run.begin(), run.end());
      if (evaluate_from(StripCursor{}, kNoFace, kEmpty, run).sent >= forward) std::reverse(run.begin(), run.end());
      order.insert(order.end(), run.begin(), run.end());
    }
  };
  improve_strips();
  for (int r = 0; r < 3; ++r) {
    local.seed = params.seed + std::uint64_t(r);
    optimize_vertices_sent(mesh, topology, local, order);
    improve_strips();
  }
  return strip_ordering(mesh, topology, std::move(order));
}

}  // namespace rastrace

#include "reorder/adjacency/cover.h"

#include <chrono>

#include "core/progress.h"
#include "core/rng.h"

namespace rastrace {
namespace {

// A maximal independent set of the interior faces with its tightness counts (the number of
// neighbours in the set) kept current, and an undo log of the changes of one iteration.
class IndependentSet {
 public:
  explicit IndependentSet(const AdjacencyDual& dual) : F_(dual.face_count) {
    nb_.assign(3 * std::size_t{F_}, kNoFace);
    for (std::uint32_t f = 0; f < F_; ++f) {
      if (!dual.interior(f)) continue;
      interior_.push_back(f);
      for (unsigned i = 0; i < 3; ++i) {
        const std::uint32_t g = dual.across(f, i);
        if (g != kNoFace && dual.interior(g)) nb_[3 * f + i] = g;
      }
    }
    in_.assign(F_, 0);
    tight_.assign(F_, 0);
    tabu_until_.assign(F_, 0);
  }

  void greedy_min_degree() {
    // Min-degree greedy: the degree is at most 3, so four buckets with lazy deletion.
    std::vector<std::uint8_t> degree(F_, 0), alive(F_, 0);
    std::vector<std::uint32_t> bucket[4];
    for (const std::uint32_t f : interior_) {
      alive[f] = 1;
      for (unsigned i = 0; i < 3; ++i) degree[f] += nb_[3 * f + i] != kNoFace;
    }
    // Faces in reverse order so that pop_back takes them in face order: deterministic.
    for (std::size_t k = interior_.size(); k-- > 0;) bucket[degree[interior_[k]]].push_back(interior_[k]);
    for (;;) {
      int b = 0;
      while (b < 4 && bucket[b].empty()) ++b;
      if (b == 4) break;
      const std::uint32_t f = bucket[b].back();
      bucket[b].pop_back();
      if (!alive[f] || degree[f] != b) continue;
      insert(f);
      alive[f] = 0;
      for (unsigned i = 0; i < 3; ++i) {
        const std::uint32_t g = nb_[3 * f + i];
        if (g == kNoFace || !alive[g]) continue;
        alive[g] = 0;
        for (unsigned j = 0; j < 3; ++j) {
          const std::uint32_t h = nb_[3 * g + j];
          if (h == kNoFace || !alive[h]) continue;
          bucket[--degree[h]].push_back(h);
        }
      }
    }
    log_.clear();
  }

  // One iteration of perturbation plus local search; returns false if there is nothing to do.
  void iterate(Rng& random) {
    if (interior_.empty()) return;
    ++clock_;
    std::uint32_t v = kNoFace;
    for (int attempt = 0; attempt < 16 && v == kNoFace; ++attempt) {
      const std::uint32_t f = interior_[random.below(interior_.size())];
      if (!in_[f] && tabu_until_[f] <= clock_) v = f;
    }
    if (v == kNoFace) return;
    const std::uint32_t before = size_;
    log_.clear();
    work_.clear();
    // Perturbation: force v in; its neighbours leave and are tabu for a few iterations.
    std::uint32_t removed[3];
    unsigned removed_count = 0;
    for (unsigned i = 0; i < 3; ++i) {
      const std::uint32_t w = nb_[3 * v + i];
      if (w != kNoFace && in_[w]) {
        remove(w);
        tabu_until_[w] = clock_ + 1 + static_cast<std::uint32_t>(random.below(kTenure));
        removed[removed_count++] = w;
      }
    }
    insert(v);
    locked_ = v;
    for (unsigned r = 0; r < removed_count; ++r) {
      add_free_neighbours(removed[r]);
      push_near(removed[r]);
    }
    push_near(v);
    // Local search: (1,2)-swaps around the change until none applies.
    while (!work_.empty()) {
      const std::uint32_t x = work_.back();
      work_.pop_back();
      if (in_[x] && x != locked_) two_improvement(x);
    }
    if (size_ < before) undo();
  }

  // Adds every free face regardless of tabu: the set becomes maximal, the cover minimal.
  void make_maximal() {
    for (const std::uint32_t f : interior_)
      if (!in_[f] && tight_[f] == 0) insert(f);
  }

  bool contains(std::uint32_t f) const { return in_[f] != 0; }
  std::uint32_t size() const { return size_; }

 private:
  static constexpr std::uint32_t kTenure = 7;

  void insert(std::uint32_t f) {
    in_[f] = 1;
    ++size_;
    log_.push_back(f);
    for (unsigned i = 0; i < 3; ++i)
      if (nb_[3 * f + i] != kNoFace) ++tight_[nb_[3 * f + i]];
  }
  void remove(std::uint32_t f) {
    in_[f] = 0;
    --size_;
    log_.push_back(f);
    for (unsigned i = 0; i < 3; ++i)
      if (nb_[3 * f + i] != kNoFace) --tight_[nb_[3 * f + i]];
  }
  void undo() {
    for (std::size_t k = log_.size(); k-- > 0;) {
      const std::uint32_t f = log_[k];
      const int delta = in_[f] ? -1 : 1;
      in_[f] = !in_[f];
      size_ += delta;
      for (unsigned i = 0; i < 3; ++i)
        if (nb_[3 * f + i] != kNoFace) tight_[nb_[3 * f + i]] += delta;
    }
    log_.clear();
  }
  bool allowed(std::uint32_t f) const { return tabu_until_[f] <= clock_; }
  bool free(std::uint32_t f) const { return !in_[f] && tight_[f] == 0; }
  void add_free_neighbours(std::uint32_t f) {
    if (free(f) && allowed(f)) insert(f);
    for (unsigned i = 0; i < 3; ++i) {
      const std::uint32_t g = nb_[3 * f + i];
      if (g != kNoFace && free(g) && allowed(g)) insert(g);
    }
  }
  // Queues the set members within two dual edges of f for a (1,2)-swap test.
  void push_near(std::uint32_t f) {
    for (unsigned i = 0; i < 3; ++i) {
      const std::uint32_t g = nb_[3 * f + i];
      if (g == kNoFace) continue;
      if (in_[g]) work_.push_back(g);
      for (unsigned j = 0; j < 3; ++j) {
        const std::uint32_t h = nb_[3 * g + j];
        if (h != kNoFace && in_[h]) work_.push_back(h);
      }
    }
  }
  bool adjacent(std::uint32_t a, std::uint32_t b) const {
    return nb_[3 * a] == b || nb_[3 * a + 1] == b || nb_[3 * a + 2] == b;
  }
  // x out, two non-adjacent neighbours that only x blocked in.
  void two_improvement(std::uint32_t x) {
    std::uint32_t candidates[3];
    unsigned count = 0;
    for (unsigned i = 0; i < 3; ++i) {
      const std::uint32_t g = nb_[3 * x + i];
      if (g != kNoFace && tight_[g] == 1 && allowed(g)) candidates[count++] = g;
    }
    for (unsigned a = 0; a < count; ++a)
      for (unsigned b = a + 1; b < count; ++b) {
        if (adjacent(candidates[a], candidates[b])) continue;
        remove(x);
        insert(candidates[a]);
        insert(candidates[b]);
        for (unsigned c = 0; c < count; ++c)
          if (free(candidates[c])) insert(candidates[c]);
        push_near(candidates[a]);
        push_near(candidates[b]);
        return;
      }
  }

  std::uint32_t F_;
  std::vector<std::uint32_t> nb_;  // three per face: interior neighbours only
  std::vector<std::uint32_t> interior_;
  std::vector<std::uint8_t> in_, tight_;
  std::vector<std::uint64_t> tabu_until_;
  std::vector<std::uint32_t> log_, work_;
  std::uint32_t size_ = 0;
  std::uint32_t locked_ = kNoFace;
  std::uint64_t clock_ = 0;
};

}  // namespace

CoverResult find_adjacency_cover(const AdjacencyDual& dual, const CoverParams& params) {
  const auto start = std::chrono::steady_clock::now();
  CoverResult result;
  IndependentSet set(dual);
  set.greedy_min_degree();
  std::uint32_t interior = 0;
  for (std::uint32_t f = 0; f < dual.face_count; ++f) interior += dual.interior(f);
  result.forced = dual.face_count - interior;
  result.greedy_size = dual.face_count - set.size();

  const std::uint64_t iterations =
      params.max_iterations >= 0 ? static_cast<std::uint64_t>(params.max_iterations) : 20ull * dual.face_count;
  Rng random(params.seed);
  Progress progress("cover", iterations);
  constexpr std::uint64_t kChunk = 4096;
  std::uint64_t done = 0;
  while (done < iterations) {
    const std::uint64_t chunk = std::min(kChunk, iterations - done);
    for (std::uint64_t k = 0; k < chunk; ++k) set.iterate(random);
    done += chunk;
    progress.advance(chunk);
    if (params.time_budget_seconds > 0 &&
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > params.time_budget_seconds)
      break;
  }
  progress.finish();
  set.make_maximal();

  result.iterations = done;
  result.in_cover.assign(dual.face_count, 1);
  for (std::uint32_t f = 0; f < dual.face_count; ++f)
    if (dual.interior(f) && set.contains(f)) result.in_cover[f] = 0;
  result.size = dual.face_count - set.size();
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

bool is_edge_cover(const AdjacencyDual& dual, const std::vector<std::uint8_t>& in_cover) {
  if (in_cover.size() != dual.face_count) return false;
  for (std::uint32_t f = 0; f < dual.face_count; ++f) {
    if (!dual.interior(f) && !in_cover[f]) return false;
    if (in_cover[f]) continue;
    for (unsigned i = 0; i < 3; ++i) {
      const std::uint32_t g = dual.across(f, i);
      if (g != kNoFace && !in_cover[g]) return false;
    }
  }
  return true;
}

bool is_minimal_cover(const AdjacencyDual& dual, const std::vector<std::uint8_t>& in_cover) {
  if (!is_edge_cover(dual, in_cover)) return false;
  for (std::uint32_t f = 0; f < dual.face_count; ++f) {
    if (!dual.interior(f) || !in_cover[f]) continue;
    bool needed = false;
    for (unsigned i = 0; i < 3; ++i) needed = needed || !in_cover[dual.across(f, i)];
    if (!needed) return false;
  }
  return true;
}

}  // namespace rastrace

// The `strip` algorithm: a cache-unaware stripifier minimizing vertices sent, in the spirit of
// Evans, Skiena, Varshney, "Optimizing triangle strips for fast rendering" (1996; the SGI tomesh
// greedy with swaps) and NvTriStrip (experiments):
//  1. grow strips from a face with the fewest unvisited neighbours (Evans et al.'s SGI start);
//     for the 4 most recent such faces, each of the three start edges and two growth rules
//     (fewest unvisited neighbours first; no swap first, then fewest neighbours), keep the strip
//     sending the fewest vertices per triangle, counting the faces it isolates as 3-vertex strips;
//  2. improve the strips as a path cover of the face graph, whose cost is local (2 per strip, 1
//     per swap: a link where four consecutive faces fan around one vertex, 1 when a strip's
//     second face turns against the first face's winding in both directions). Lin-Kernighan
//     style chains of up to 4 steps from every strip end: link the end to a neighbour; if that
//     ends a strip the two join, else the neighbour drops one of its links and that face goes on
//     (Stewart's tunnelling; a reflection within the end's own strip). Also every swap's link is
//     cut and a chain from either side must pay for it. A change is kept when it lowers the cost;
//     passes over the faces whose neighbourhood changed repeat until none does (at most 64
//     passes; 2-5 on the test meshes). Deterministic, no time budget: the parameters are unused.
//  3. each strip is sent from its cheaper end, strips in the order they were first built, with
//     an explicit restart between strips (strip_ordering, strip.h).
// CGAL's meshes: triceratops 6,820 vertices for 5,660 triangles (Yang et al., Table 1: 6,911 with
// Evans et al.'s strips, which need not keep the winding), fandisk 14,457 for 12,946, bunny00
// 91,460 for 75,408. Bounded work per face and pass (plus re-walking the strips a change
// touches): bunny00 in about 0.3 s of CPU.
#include <algorithm>
#include <array>
#include <bit>
#include <initializer_list>

#include "reorder/mesh_topology.h"
#include "reorder/ordering.h"
#include "reorder/strip.h"

namespace rastrace {

namespace {

bool degenerate(const std::uint32_t* v) { return v[0] == v[1] || v[1] == v[2] || v[0] == v[2]; }

// The strips as a path cover of the dual graph: each face links to at most two neighbours across
// its edges (a bit per edge slot). What a cover sends is local (strip.h counts it): per strip
// 2 + triangles, plus one swap per link whose two faces pivot around the same vertex (four
// consecutive faces fanning around one vertex), plus one swap if the strip starts turning the way
// a sequential strip with the first face's winding cannot (the cheaper of its two directions is
// taken). So a change of a few links is re-costed in O(1): the links at the changed faces and the
// terms of the strips whose ends change.
class StripCover {
 public:
  StripCover(const Mesh& mesh, const MeshTopology& topology)
      : idx_(mesh.indices.data()),
        topology_(topology),
        F_(topology.face_count),
        mask_(F_, 0),
        partner_(F_),
        path_(F_, 0),
        pos_(F_, 0) {
    for (std::uint32_t f = 0; f < F_; ++f) partner_[f] = f;
    linkable_.resize(F_);
    for (std::uint32_t f = 0; f < F_; ++f)
      for (unsigned s = 0; s < 3; ++s) linkable_[f] |= std::uint8_t(compute_linkable(f, s) << s);
  }
  bool linkable(std::uint32_t f, unsigned s) const { return linkable_[f] >> s & 1; }

  // Whether f and its neighbour across slot s may be consecutive in a strip: non-degenerate
  // oriented neighbours sharing exactly one edge (so the slot on each side is unambiguous).
  bool compute_linkable(std::uint32_t f, unsigned s) const {
    const std::uint32_t g = topology_.neighbor(f, s);
    if (g == kNoFace || g == f || degenerate(idx_ + 3 * std::size_t(f)) || degenerate(idx_ + 3 * std::size_t(g)))
      return false;
    unsigned count = 0;
    for (unsigned t = 0; t < 3; ++t) count += topology_.neighbor(g, t) == f;
    unsigned back = 0;
    for (unsigned t = 0; t < 3; ++t) back += topology_.neighbor(f, t) == g;
    return count == 1 && back == 1;
  }

  // Links the faces of each strip in turn (pairs that may not be consecutive are left unlinked).
  void add_strip(const std::vector<std::uint32_t>& faces) {
    for (std::size_t i = 0; i + 1 < faces.size(); ++i) {
      const int s = slot_to(faces[i], faces[i + 1]);
      if (s >= 0 && linkable(faces[i], unsigned(s)) && deg(faces[i]) < 2 && deg(faces[i + 1]) < 2) {
        const std::uint32_t pa = partner_[faces[i]], pb = partner_[faces[i + 1]];
        if (pa == faces[i + 1]) continue;
        link(faces[i], faces[i + 1]);
        partner_[pa] = pb;
        partner_[pb] = pa;
      }
    }
    undo_mask_.clear();
  }

  // Improvement passes (deterministic: faces in id order, first improving chain applied) until a
  // pass finds nothing or max_passes is reached. Returns the passes run.
  unsigned improve(int depth, unsigned max_passes) {
    unsigned pass = 0;
    reindex_all();
    const std::size_t radius = 2 * std::size_t(depth) + 2;
    mark_radius_ = radius / 2;
    near_radius_ = radius - mark_radius_;
    never_searched_.assign(F_, 1u << kEndSearch | 1u << kSwapSearch);
    reached_at_.assign(F_, 0);
    for (unsigned kind : {kEndSearch, kSwapSearch}) {
      searched_at_[kind].assign(F_, 0);
      failure_[kind].assign(F_, FailureRecord{});
    }
    for (; pass < max_passes; ++pass) {
      bool improved = false;
      for (std::uint32_t f = 0; f < F_; ++f) {
        if (deg(f) >= 2 || !search_due(kEndSearch, f)) continue;
        begin_record();
        note_strip(path_[f]);
        used_.assign(1, path_[f]);
        origin_ = f;
        undo_mask_.clear();
        undo_partner_.clear();
        if (chain(f, depth, 0)) {
          end_record(kEndSearch, f, false);
          improved = true;
          reindex_changed();
        } else {
          end_record(kEndSearch, f, true);
        }
      }
      improved |= break_swaps(depth);
      if (!improved) break;
    }
    return pass;
  }

  // A swap's link is cut (the strip splits in two, +1 or +2) and a chain from either new end
  // must pay that back.
  bool break_swaps(int depth) {
    bool improved = false;
    for (std::uint32_t g = 0; g < F_; ++g) {
      if (!search_due(kSwapSearch, g)) continue;
      begin_record();
      note_strip(path_[g]);  // which of g's links are swaps
      bool found = false;
      for (unsigned s = 0; s < 3; ++s) {
        if (!(mask_[g] >> s & 1) || !fan(g, s)) continue;
        const std::uint32_t h = topology_.neighbor(g, s);
        const std::uint32_t P = path_[g];
        const bool g_first = pos_[g] < pos_[h];
        const std::uint32_t eg = g_first ? head_[P] : tail_[P], eh = g_first ? tail_[P] : head_[P];
        undo_mask_.clear();
        undo_partner_.clear();
        const int before = int(links_cost({g, h}) + path_term(head_[P], tail_[P]));
        unlink(g, h);
        set_partner(g, eg);
        set_partner(eg, g);
        set_partner(h, eh);
        set_partner(eh, h);
        const int acc = int(links_cost({g, h}) + path_term(g, eg) + path_term(h, eh)) - before;
        const std::size_t mm = undo_mask_.size(), mp = undo_partner_.size();
        used_.assign(1, P);
        origin_ = kNoFace;
        if (chain(g, depth, acc) || (undo_to(mm, mp), chain(h, depth, acc))) {
          found = true;
          break;
        }
        undo_to(0, 0);
      }
      end_record(kSwapSearch, g, !found);
      if (found) {
        improved = true;
        reindex_changed();
      }
    }
    return improved;
  }

  // The strips, in the order their first face appears in `visit`, each from its cheaper end.
  std::vector<std::uint32_t> order(const std::vector<std::uint32_t>& visit, std::vector<std::uint8_t>& starts) const {
    std::vector<std::uint32_t> out;
    starts.assign(F_, 0);
    out.reserve(F_);
    std::vector<std::uint8_t> done(F_, 0);
    for (const std::uint32_t f : visit) {
      if (done[f]) continue;
      const std::uint32_t a = walk_to_end(f);
      const std::uint32_t b = partner_[a];
      std::uint32_t from = pen(b) < pen(a) ? b : a;
      starts[out.size()] = 1;
      for (std::uint32_t prev = kNoFace, at = from; at != kNoFace && !done[at];) {  // a path: no face twice
        out.push_back(at);
        done[at] = 1;
        const std::uint32_t next = step(at, prev);
        prev = at;
        at = next;
      }
    }
    return out;
  }

 private:
  unsigned deg(std::uint32_t f) const { return (0x32212110u >> (4 * mask_[f])) & 0xFu; }  // popcount of 3 bits
  int slot_to(std::uint32_t f, std::uint32_t g) const {
    for (unsigned s = 0; s < 3; ++s)
      if (topology_.neighbor(f, s) == g) return int(s);
    return -1;
  }
  // The vertex a face with two links turns around: the one its two linked edges share.
  std::uint32_t pivot(std::uint32_t g) const {
    const unsigned free_slot = unsigned(std::countr_zero(unsigned(~mask_[g] & 7u)));
    return idx_[3 * std::size_t(g) + (free_slot + 2) % 3];
  }
  // One swap for the link across f's slot s if both faces turn around the same vertex.
  unsigned fan(std::uint32_t f, unsigned s) const {
    const std::uint32_t g = topology_.neighbor(f, s);
    return deg(f) == 2 && deg(g) == 2 && pivot(f) == pivot(g) ? 1u : 0u;
  }
  // One swap if a strip starting at end e turns the wrong way at its second face: the emitter
  // sends e as (v[s+2], v[s], v[s+1]) for exit slot s, so the second face must not turn around v[s].
  unsigned pen(std::uint32_t e) const {
    if (deg(e) != 1) return 0;
    const unsigned s = unsigned(std::countr_zero(unsigned(mask_[e])));
    const std::uint32_t g = topology_.neighbor(e, s);
    return deg(g) == 2 && pivot(g) == idx_[3 * std::size_t(e) + s] ? 1u : 0u;
  }
  unsigned path_term(std::uint32_t a, std::uint32_t b) const { return 2 + (a == b ? 0 : std::min(pen(a), pen(b))); }
  // The linked neighbour of f other than prev (kNoFace at an end).
  std::uint32_t step(std::uint32_t f, std::uint32_t prev) const {
    for (unsigned s = 0; s < 3; ++s)
      if (mask_[f] >> s & 1) {
        const std::uint32_t g = topology_.neighbor(f, s);
        if (g != prev) return g;
      }
    return kNoFace;
  }
  std::uint32_t walk_to_end(std::uint32_t f) const {
    if (deg(f) < 2) return f;
    const std::uint32_t start = f;
    std::uint32_t prev = step(f, kNoFace), at = f;
    // Walk away from the first linked neighbour.
    for (;;) {
      const std::uint32_t next = step(at, prev);
      if (next == kNoFace) return at;
      prev = at;
      at = next;
      if (at == start) return at;  // cannot happen in a path cover; guards against a cycle
    }
  }

  void set_mask(std::uint32_t f, std::uint8_t m) {
    undo_mask_.push_back({f, mask_[f]});
    mask_[f] = m;
  }
  void link(std::uint32_t f, std::uint32_t g) {
    set_mask(f, std::uint8_t(mask_[f] | 1u << slot_to(f, g)));
    set_mask(g, std::uint8_t(mask_[g] | 1u << slot_to(g, f)));
  }
  void unlink(std::uint32_t f, std::uint32_t g) {
    set_mask(f, std::uint8_t(mask_[f] & ~(1u << slot_to(f, g))));
    set_mask(g, std::uint8_t(mask_[g] & ~(1u << slot_to(g, f))));
  }
  void set_partner(std::uint32_t f, std::uint32_t p) {
    undo_partner_.push_back({f, partner_[f]});
    partner_[f] = p;
  }
  void undo_to(std::size_t masks, std::size_t partners) {
    while (undo_mask_.size() > masks) {
      mask_[undo_mask_.back().first] = undo_mask_.back().second;
      undo_mask_.pop_back();
    }
    while (undo_partner_.size() > partners) {
      partner_[undo_partner_.back().first] = undo_partner_.back().second;
      undo_partner_.pop_back();
    }
  }

  // Swaps on the links touching the given faces (each link once: a link between two listed
  // faces counts at the first).
  unsigned links_cost(std::initializer_list<std::uint32_t> faces) const {
    unsigned cost = 0;
    const std::uint32_t* list = faces.begin();
    for (std::size_t i = 0; i < faces.size(); ++i) {
      const std::uint32_t f = list[i];
      for (unsigned s = 0; s < 3; ++s) {
        if (!(mask_[f] >> s & 1)) continue;
        const std::uint32_t g = topology_.neighbor(f, s);
        bool counted = false;
        for (std::size_t j = 0; j < i; ++j) counted |= list[j] == g;
        if (!counted) cost += fan(f, s);
      }
    }
    return cost;
  }

  // Lin-Kernighan-style chain from the free end t: link t to a neighbour m; if m ends a strip the
  // two strips join, otherwise m drops one of its links and the face it drops is the next free
  // end. Each step is re-costed locally; the chain is applied as soon as its total is negative.
  // Strips entered by the chain must be untouched so far (so the original positions tell which
  // side of m is which and no cycle can form), except a reflection within t's own strip at the
  // first step.
  bool chain(std::uint32_t t, int depth, int acc) {
    const std::size_t mark_mask = undo_mask_.size(), mark_partner = undo_partner_.size();
    const std::uint32_t pt = partner_[t];
    const int t_term = int(path_term(t, pt));  // t's strip before this step (restored after each try)
    // A tunnel's strips cost at least 2 each afterwards (path_term), its links at least 0: when
    // even that cannot make the total negative, or keep it within kSlack to go on, the tunnel
    // is not tried.
    const int give_up = depth > 1 ? kSlack : -1;
    // Joins first (they end the chain), then tunnels.
    for (unsigned k = 0; k < 6; ++k) {
      const unsigned s = k % 3;
      if (mask_[t] >> s & 1 || !linkable(t, s)) continue;
      const std::uint32_t m = topology_.neighbor(t, s);
      note_strip(path_[m]);
      if ((deg(m) < 2) != (k < 3)) continue;
      if (deg(m) < 2) {
        if (m == pt) continue;
        const std::uint32_t pm = partner_[m];
        const int before = int(links_cost({t, m})) + t_term + int(path_term(m, pm));
        link(t, m);
        set_partner(pt, pm);
        set_partner(pm, pt);
        const int after = int(links_cost({t, m}) + path_term(pt, pm));
        if (acc + after - before < 0) return true;
        undo_to(mark_mask, mark_partner);
        continue;
      }
      const std::uint32_t P = path_[m];
      const bool own = t == origin_ && P == path_[t];
      if (!own && std::find(used_.begin(), used_.end(), P) != used_.end()) continue;
      const int p_term = own ? 0 : int(path_term(head_[P], tail_[P]));
      for (unsigned r = 0; r < 3; ++r) {
        if (!(mask_[m] >> r & 1)) continue;
        const std::uint32_t a = topology_.neighbor(m, r);
        const bool a_before = pos_[a] < pos_[m];
        int before, after;
        if (own) {
          // Reflection: m must drop the link towards t (t is the head or the tail of the strip).
          if (a_before != (t == head_[P])) continue;
          before = int(links_cost({t, m, a})) + t_term;
          if (acc + 2 - before > give_up) continue;
          link(t, m);
          unlink(m, a);
          set_partner(a, pt);
          set_partner(pt, a);
          after = int(links_cost({t, m, a}) + path_term(a, pt));
        } else {
          const std::uint32_t ea = a_before ? head_[P] : tail_[P], eb = a_before ? tail_[P] : head_[P];
          before = int(links_cost({t, m, a})) + t_term + p_term;
          if (acc + 4 - before > give_up) continue;
          link(t, m);
          unlink(m, a);
          set_partner(pt, eb);
          set_partner(eb, pt);
          set_partner(a, ea);
          set_partner(ea, a);
          after = int(links_cost({t, m, a}) + path_term(pt, eb) + path_term(a, ea));
        }
        const int total = acc + after - before;
        if (total < 0) return true;
        if (depth > 1 && total <= kSlack) {
          used_.push_back(P);
          if (chain(a, depth - 1, total)) return true;
          used_.pop_back();
        }
        undo_to(mark_mask, mark_partner);
      }
    }
    return false;
  }

  static constexpr int kSlack = 2;  // a join at the end of a chain saves 2, or 3 with a start swap

  // Strip ids and positions, from each strip's head. A re-walked strip gets a new id, and the
  // ids its faces had are no longer current (see FailureRecord).
  void index_from(std::uint32_t head) {
    const std::uint32_t id = std::uint32_t(head_.size());
    head_.push_back(head);
    strip_current_.push_back(1);
    noted_.push_back(0);
    std::uint32_t prev = kNoFace, at = head, i = 0;
    for (;;) {
      // From reindex_all, path_ holds ids of the strips before it cleared strip_current_ (whose
      // marks it resets afterwards): only a current id may be marked.
      if (path_[at] < strip_current_.size()) strip_current_[path_[at]] = 0;
      path_[at] = id;
      pos_[at] = i++;
      const std::uint32_t next = step(at, prev);
      if (next == kNoFace) break;
      prev = at;
      at = next;
    }
    tail_.push_back(at);
  }
  void reindex_all() {
    head_.clear();
    tail_.clear();
    strip_current_.clear();
    noted_.clear();
    for (std::uint32_t f = 0; f < F_; ++f)
      if (deg(f) < 2 && partner_[f] >= f) index_from(f);
    strip_current_.assign(head_.size(), 1);
  }
  // After an applied change: re-walks the strips it touched, and marks the faces within
  // mark_radius_ of those whose links changed (see search_due).
  void reindex_changed() {
    stamp_.resize(F_, 0);
    ++epoch_;
    ++changes_;
    for (const auto& [f, old] : undo_mask_) {
      const std::uint32_t end = walk_to_end(f);
      if (stamp_[end] == epoch_) continue;
      stamp_[end] = stamp_[partner_[end]] = epoch_;
      index_from(end);
    }
    seen_.resize(F_, 0);
    ++epoch_;
    queue_.clear();
    for (const auto& [f, old] : undo_mask_)
      if (seen_[f] != epoch_) {
        seen_[f] = epoch_;
        reached_at_[f] = changes_;
        queue_.push_back(f);
      }
    ball(mark_radius_, [&](std::uint32_t g) {
      reached_at_[g] = changes_;
      return false;
    });
    undo_mask_.clear();
    undo_partner_.clear();
  }

  // Which searches run. The rule: a search from f (a chain from a strip end, or breaking f's
  // swaps) is due again when some face within 2 * depth + 2 of f changed its links since f's
  // last search (chains starting near a change may now find something: a chain reaches about
  // two faces per step from its start). Marking that whole ball at every change costs most of
  // the mesh per change when the dual graph is an expander, so the distance is split: a change
  // marks its ball of radius mark_radius_ (reached_at_), and a search is due when a marked face
  // lies within near_radius_ of it, the two radii adding up to the rule's.
  // A due search is skipped when its last failure record still holds: it would fail again, so
  // skipping it leaves every decision, hence every strip, as it was.
  bool search_due(unsigned kind, std::uint32_t f) {
    const std::uint8_t bit = std::uint8_t(1u << kind);
    if (never_searched_[f] & bit) {
      never_searched_[f] &= std::uint8_t(~bit);
      searched_at_[kind][f] = changes_;
      return true;
    }
    if (fails_again(failure_[kind][f])) {
      searched_at_[kind][f] = changes_;  // as if searched: it would have failed
      return false;
    }
    if (!changed_near(f, searched_at_[kind][f])) return false;
    searched_at_[kind][f] = changes_;
    return true;
  }
  // Whether a face within near_radius_ of f (f included) was marked by a change after change
  // number `since`.
  bool changed_near(std::uint32_t f, std::uint32_t since) {
    if (changes_ == since) return false;
    if (reached_at_[f] > since) return true;
    seen_.resize(F_, 0);
    ++epoch_;
    seen_[f] = epoch_;
    queue_.assign(1, f);
    return ball(near_radius_, [&](std::uint32_t g) { return reached_at_[g] > since; });
  }
  // Breadth-first from the faces in queue_ (seen_ == epoch_), calling visit(g) on each face first
  // reached within `radius` steps; stops early, returning true, when visit does.
  template <typename Visit>
  bool ball(std::size_t radius, Visit&& visit) {
    const std::uint32_t* neighbors = topology_.face_neighbors.data();
    std::uint32_t* seen = seen_.data();
    const std::uint32_t epoch = epoch_;
    for (std::size_t head = 0, level_end = queue_.size(), level = 0; head < queue_.size(); ++head) {
      if (head == level_end) {
        ++level;
        level_end = queue_.size();
      }
      if (level == radius) break;  // the last level is visited, not expanded
      const std::uint32_t* n = neighbors + 3 * std::size_t(queue_[head]);
      for (unsigned s = 0; s < 3; ++s) {
        const std::uint32_t g = n[s];
        if (g == kNoFace || seen[g] == epoch) continue;
        seen[g] = epoch;
        if (visit(g)) return true;
        queue_.push_back(g);
      }
    }
    return false;
  }

  // A failed search's record: the strips whose faces it read (their links, ends, ids and
  // positions). A chain reads t's strip and, for every neighbour m it tries, m's strip; every
  // other face it reads is linked to one of those (links_cost, pen, partners, head_/tail_, pos_).
  // A strip whose faces keep their links keeps its ends and is not re-walked, so while every
  // recorded strip is current the search reads the same values and fails again. (An applied
  // change re-walks every strip containing a face whose links changed, and each piece of a
  // changed strip contains such a face.)
  struct FailureRecord {
    std::uint32_t begin = kNoFace, end = 0;  // range in recorded_strips_; begin kNoFace: none
  };
  void begin_record() {
    ++note_epoch_;
    record_begin_ = recorded_strips_.size();
  }
  void note_strip(std::uint32_t strip) {
    if (noted_[strip] == note_epoch_) return;
    noted_[strip] = note_epoch_;
    recorded_strips_.push_back(strip);
  }
  void end_record(unsigned kind, std::uint32_t f, bool failed) {
    FailureRecord& record = failure_[kind][f];
    if (record.begin != kNoFace) recorded_live_ -= record.end - record.begin;
    record = FailureRecord{};
    if (failed) {
      record = {std::uint32_t(record_begin_), std::uint32_t(recorded_strips_.size())};
      recorded_live_ += record.end - record.begin;
    } else {
      recorded_strips_.resize(record_begin_);
    }
    if (recorded_strips_.size() > 2 * recorded_live_ + 4096) compact_records();
  }
  bool fails_again(const FailureRecord& record) const {
    if (record.begin == kNoFace) return false;
    for (std::uint32_t i = record.begin; i < record.end; ++i)
      if (!strip_current_[recorded_strips_[i]]) return false;
    return true;
  }
  void compact_records() {
    std::vector<std::uint32_t> kept;
    kept.reserve(2 * recorded_live_);
    for (std::vector<FailureRecord>& records : failure_)
      for (FailureRecord& record : records) {
        if (record.begin == kNoFace) continue;
        const std::uint32_t begin = std::uint32_t(kept.size());
        kept.insert(kept.end(), recorded_strips_.begin() + record.begin, recorded_strips_.begin() + record.end);
        record = {begin, std::uint32_t(kept.size())};
      }
    recorded_strips_.swap(kept);
  }

  const std::uint32_t* idx_;
  const MeshTopology& topology_;
  std::uint32_t F_;
  std::vector<std::uint8_t> mask_;                       // linked edge slots
  std::vector<std::uint8_t> linkable_;                   // edge slots that may be linked
  std::vector<std::uint32_t> partner_;                   // for a strip end: the other end (itself when alone)
  std::vector<std::uint32_t> path_, pos_, head_, tail_;  // strip ids and positions (see chain)
  std::vector<std::uint32_t> stamp_, seen_, queue_;
  std::size_t mark_radius_ = 0, near_radius_ = 0;  // see search_due
  std::uint32_t epoch_ = 0;
  // Searches (see search_due): kinds, and per kind and face the change count at the last search
  // and the last failure's record.
  static constexpr unsigned kEndSearch = 0, kSwapSearch = 1;
  std::vector<std::uint8_t> never_searched_;     // a bit per kind
  std::vector<std::uint32_t> searched_at_[2];    // changes_ at the last search
  std::vector<FailureRecord> failure_[2];
  std::vector<std::uint32_t> reached_at_;        // per face: the last change within mark_radius_
  std::uint32_t changes_ = 0;                    // applied changes so far
  std::vector<std::uint8_t> strip_current_;      // per strip id: not re-walked since
  std::vector<std::uint32_t> noted_;             // per strip id: note_epoch_ when last recorded
  std::vector<std::uint32_t> recorded_strips_;   // the records' strip ids
  std::size_t record_begin_ = 0, recorded_live_ = 0;
  std::uint32_t note_epoch_ = 0;
  std::vector<std::pair<std::uint32_t, std::uint8_t>> undo_mask_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> undo_partner_;
  std::vector<std::uint32_t> used_;
  std::uint32_t origin_ = 0;
};

}  // namespace

Ordering reorder_strip(const Mesh& mesh, const ReorderParams& /*params*/) {
  // Chain depth 4 (3 was 0.1-0.2% worse, 6 and 8 no better); the passes converge in 2-5 on
  // the test meshes, so the cap only bounds pathological inputs.
  constexpr int kChainDepth = 4;
  constexpr unsigned kMaxPasses = 64;
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

  enum class Mode { FewestNeighbors, AvoidSwaps };
  // Returns the number of swaps; the faces go to `strip`. modes_agree: whether the other mode
  // would have made the same choice at every step (then it grows the same strip).
  auto grow = [&](std::uint32_t f, unsigned first_exit, Mode mode, std::vector<std::uint32_t>& strip,
                  bool& modes_agree) {
    modes_agree = true;
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
      int best = -1, best_other = -1;
      int best_key[3] = {0, 0, 0}, best_other_key[3] = {0, 0, 0};
      auto less = [](const int* a, const int* b) {
        return a[0] < b[0] || (a[0] == b[0] && a[1] < b[1]) || (a[0] == b[0] && a[1] == b[1] && a[2] < b[2]);
      };
      // The faces the strip can go on to; the keys only rank two or more (one is taken as it is,
      // in either mode).
      unsigned options[3], option_count = 0;
      for (unsigned s = 0; s < 3; ++s) {
        const std::uint32_t g = topology.neighbor(f, s);
        if (!live(g) || degenerate(idx + 3 * std::size_t(g))) continue;
        if (first && s != first_exit) continue;
        options[option_count++] = s;
      }
      if (option_count == 1) best = best_other = static_cast<int>(options[0]);
      for (unsigned o = 0; o < option_count && option_count > 1; ++o) {
        const unsigned s = options[o];
        const std::uint32_t g = topology.neighbor(f, s);
        int next_min = -1;  // no live neighbour at all is best: the strip ends cleanly there
        for (unsigned t = 0; t < 3; ++t) {
          const std::uint32_t h = topology.neighbor(g, t);
          if (!live(h) || h == f) continue;
          const int count = live_neighbors(h) - 1;  // g is about to be taken
          if (next_min < 0 || count < next_min) next_min = count;
        }
        const int fewest = live_neighbors(g);
        const int swap = is_swap(s) ? 1 : 0;
        const int fewest_key[3] = {fewest, next_min, swap}, avoid_key[3] = {swap, fewest, next_min};
        const int* key = mode == Mode::AvoidSwaps ? avoid_key : fewest_key;
        const int* other_key = mode == Mode::AvoidSwaps ? fewest_key : avoid_key;
        if (best < 0 || less(key, best_key)) {
          best = static_cast<int>(s);
          for (int k = 0; k < 3; ++k) best_key[k] = key[k];
        }
        if (best_other < 0 || less(other_key, best_other_key)) {
          best_other = static_cast<int>(s);
          for (int k = 0; k < 3; ++k) best_other_key[k] = other_key[k];
        }
      }
      modes_agree &= best == best_other;
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

  StripCover cover(mesh, topology);
  std::vector<std::uint32_t> built;  // faces in the order the strips were built
  built.reserve(F);
  std::vector<std::uint32_t> candidate, best_strip;
  std::vector<std::uint32_t> starts, isolated_mark(F, 0);
  constexpr unsigned kStarts = 4;  // 2, 8 and 16 did no better on fandisk, triceratops, bunny00
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
    for (const std::uint32_t f : starts) {
      bool same_in_both_modes[3] = {false, false, false};
      for (Mode mode : {Mode::FewestNeighbors, Mode::AvoidSwaps})
        for (unsigned exit = 0; exit < 3; ++exit) {
          // The second mode's strip is then the first's, already weighed: an equal cost never
          // replaces the best, so it cannot change the choice.
          if (mode == Mode::AvoidSwaps && same_in_both_modes[exit]) continue;
          bool agree = false;
          const std::uint64_t swaps = grow(f, exit, mode, candidate, agree);
          if (mode == Mode::FewestNeighbors) same_in_both_modes[exit] = agree;
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
    }
    for (const std::uint32_t g : best_strip) visit(g);
    cover.add_strip(best_strip);
    built.insert(built.end(), best_strip.begin(), best_strip.end());
  }

  cover.improve(kChainDepth, kMaxPasses);
  std::vector<std::uint8_t> strip_starts;
  std::vector<std::uint32_t> order = cover.order(built, strip_starts);
  return strip_ordering(mesh, topology, std::move(order), strip_starts);
}

}  // namespace rastrace

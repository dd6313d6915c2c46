// NvTriStrip's stripifier (NVIDIA's public NvTriStrip library), rewritten from its description
// in reorder/nvstrip.h. Terms follow the library's: an experiment is one start face and oriented
// start edge grown into a strip and then into the neighbouring strips it leads to; a piece is a
// strip cut to the cache's length.
#include "reorder/nvstrip.h"

#include <algorithm>
#include <optional>
#include <set>

#include "reorder/mesh_topology.h"
#include "reorder/removable_positions.h"
#include "reorder/strip.h"

namespace rastrace {

namespace {

constexpr int kSamples = 10;                // start faces per round of experiments
constexpr unsigned kCacheInefficiency = 6;  // NvTriStrip orders for (cache size - 6)
constexpr unsigned kMaxCache = 1024;

bool degenerate(const std::uint32_t* c) { return c[0] == c[1] || c[1] == c[2] || c[0] == c[2]; }

// A strip's start: a face and one of its edges, oriented (a, b). Growth goes forward across the
// face's edge (b, third) and backward across (b, a).
struct Start {
  std::uint32_t face, a, b;
};

class Stripifier {
 public:
  Stripifier(const Mesh& mesh, const MeshTopology& topology)
      : mesh_(mesh),
        topology_(topology),
        committed_(topology.face_count, 0),
        experiment_of_(topology.face_count, 0),
        strip_of_(topology.face_count, 0),
        vertex_strip_(topology.vertex_count, 0) {
    for (std::uint32_t f = 0; f < topology.face_count; ++f) {
      if (degenerate(corners(f)))
        committed_[f] = 1;  // never part of a strip
      else
        faces_.push_back(f);
    }
    position_.resize(topology.face_count, 0);
    for (std::uint32_t i = 0; i < faces_.size(); ++i) position_[faces_[i]] = i;
    uncommitted_ = RemovablePositions(static_cast<std::uint32_t>(faces_.size()));
    index_leads();
  }

  // Rounds of experiments until every face is in a committed strip.
  std::vector<std::vector<std::uint32_t>> find_all_strips() {
    std::vector<std::vector<std::uint32_t>> committed;
    bool done = false;
    while (!done) {
      std::vector<Start> starts;
      std::set<std::uint32_t> tried;
      for (int i = 0; i < kSamples; ++i) {
        const std::optional<std::uint32_t> face = reset_point();
        if (!face) {
          done = true;
          break;
        }
        if (!tried.insert(*face).second) continue;
        const std::uint32_t* c = corners(*face);
        for (int e = 0; e < 3; ++e) {
          starts.push_back({*face, c[e], c[(e + 1) % 3]});
          starts.push_back({*face, c[(e + 1) % 3], c[e]});
        }
      }
      // The experiment with the longest strips on average wins (the first on ties).
      std::vector<std::vector<std::uint32_t>> best;
      double best_value = 0.0;
      for (const Start& start : starts) {
        std::vector<std::vector<std::uint32_t>> strips = experiment(start);
        std::size_t faces = 0;
        for (const auto& strip : strips) faces += strip.size();
        const double value = double(faces) / double(strips.size());
        if (value > best_value) {
          best_value = value;
          best = std::move(strips);
        }
      }
      for (auto& strip : best) {
        for (const std::uint32_t f : strip) commit(f);
        committed.push_back(std::move(strip));
      }
    }
    return committed;
  }

 private:
  const std::uint32_t* corners(std::uint32_t f) const { return mesh_.indices.data() + 3 * std::size_t(f); }
  std::uint32_t third(std::uint32_t f, std::uint32_t a, std::uint32_t b) const {
    const std::uint32_t* c = corners(f);
    return c[0] != a && c[0] != b ? c[0] : (c[1] != a && c[1] != b ? c[1] : c[2]);
  }
  std::uint32_t across(std::uint32_t f, std::uint32_t a, std::uint32_t b) const {
    const int slot = edge_slot(corners(f), a, b);
    return slot < 0 ? kNoFace : topology_.neighbor(f, unsigned(slot));
  }
  bool marked(std::uint32_t f) const { return committed_[f] || experiment_of_[f] == experiment_; }
  void mark(std::uint32_t f) {
    experiment_of_[f] = experiment_;
    strip_of_[f] = strip_;
    for (int n = 0; n < 3; ++n) vertex_strip_[corners(f)[n]] = strip_;
  }

  // The first reset point is the face with the most boundary edges (if any); later ones jump
  // through the face list by tenths, taking the next uncommitted face.
  std::optional<std::uint32_t> reset_point() {
    const auto n = static_cast<std::uint32_t>(faces_.size());
    if (n == 0) return std::nullopt;
    std::int64_t start = -1;
    if (first_reset_) {
      first_reset_ = false;
      unsigned best = 0;
      for (std::uint32_t i = 0; i < n; ++i) {
        const unsigned boundary = 3 - topology_.neighbor_count(faces_[i]);
        if (boundary > best) {
          best = boundary;
          start = i;
        }
      }
    }
    if (start < 0) start = static_cast<std::int64_t>((static_cast<float>(n) - 1.0f) * jump_);
    jump_ += 0.1f;
    if (jump_ > 1.0f) jump_ = 0.05f;
    std::uint32_t i = next_uncommitted(std::uint32_t(start));
    if (i == n) i = next_uncommitted(0);
    if (i == n) return std::nullopt;
    return faces_[i];
  }

  // The first position >= i in faces_ whose face is uncommitted, or faces_.size(): the library's
  // linear scan, with the committed runs skipped by path halving (committed faces stay so).
  std::uint32_t next_uncommitted(std::uint32_t i) { return uncommitted_.first(i); }
  void commit(std::uint32_t f) {
    committed_[f] = 1;
    uncommitted_.remove(position_[f]);
    for (int n = 0; n < 3; ++n)
      if (lead_position_[3 * std::size_t(f) + n] != kNoFace)
        uncommitted_leads_.remove(lead_position_[3 * std::size_t(f) + n]);
  }

  // Per vertex v, the faces around v (in faces_of_vertex order) that have a neighbour across an
  // edge at v: the only faces traversal() can start the next strip on. Faces without such a
  // neighbour are left out and committed faces are skipped by links, so a vertex in thousands of
  // faces that lead nowhere (an edge fan, whose faces have no oriented neighbours) is not
  // scanned again for every strip of every experiment: that scan made nvstrip quadratic there.
  void index_leads() {
    lead_offsets_.assign(std::size_t(topology_.vertex_count) + 1, 0);
    lead_position_.assign(3 * std::size_t(topology_.face_count), kNoFace);
    for (std::uint32_t v = 0; v < topology_.vertex_count; ++v) {
      for (const std::uint32_t h : topology_.faces_of_vertex(v)) {
        if (committed_[h]) continue;
        const std::uint32_t* c = corners(h);
        bool leads = false;
        for (unsigned e = 0; e < 3; ++e)
          leads |= (c[e] == v || c[(e + 1) % 3] == v) && topology_.neighbor(h, e) != kNoFace;
        if (!leads) continue;
        const int corner = c[0] == v ? 0 : (c[1] == v ? 1 : 2);
        lead_position_[3 * std::size_t(h) + corner] = static_cast<std::uint32_t>(leads_.size());
        leads_.push_back(h);
      }
      lead_offsets_[v + 1] = static_cast<std::uint32_t>(leads_.size());
    }
    uncommitted_leads_ = RemovablePositions(static_cast<std::uint32_t>(leads_.size()));
  }

  // One strip from `start`, forward then backward; faces in drawing order.
  std::vector<std::uint32_t> build(const Start& start) {
    ++strip_;
    mark(start.face);
    const std::uint32_t v2 = third(start.face, start.a, start.b);
    std::vector<std::uint32_t> forward{start.face};
    grow(start.face, start.b, v2, forward, false);
    std::vector<std::uint32_t> backward;
    grow(start.face, start.b, start.a, backward, true);
    std::reverse(backward.begin(), backward.end());
    backward.insert(backward.end(), forward.begin(), forward.end());
    return backward;
  }

  // Walks across (nv0, nv1) from `face`. When the face after the next would be a dead end but
  // the next face's other edge at nv0 leads on, the strip swaps to turn there. Backward growth
  // stops at a face whose three vertices are already in the strip (no wrap-around).
  void grow(std::uint32_t face, std::uint32_t nv0, std::uint32_t nv1, std::vector<std::uint32_t>& out, bool backward) {
    std::uint32_t next = across(face, nv0, nv1);
    while (next != kNoFace && !marked(next)) {
      const std::uint32_t* c = corners(next);
      if (backward && vertex_strip_[c[0]] == strip_ && vertex_strip_[c[1]] == strip_ && vertex_strip_[c[2]] == strip_)
        break;
      std::uint32_t t0 = nv1;
      const std::uint32_t t1 = third(next, nv0, nv1);
      const std::uint32_t after = across(next, t0, t1);
      if (after == kNoFace || marked(after)) {
        const std::uint32_t turn = across(next, nv0, t1);
        if (turn != kNoFace && !marked(turn)) t0 = nv0;
      }
      out.push_back(next);
      mark(next);
      nv0 = t0;
      nv1 = t1;
      face = next;
      next = across(face, nv0, nv1);
    }
  }

  // The next strip of an experiment starts at an unmarked face around the second vertex of the
  // previous strip's start edge, across an edge from a face outside that strip.
  std::optional<Start> traversal(const Start& previous, std::uint32_t previous_strip) {
    const std::uint32_t v = previous.b;
    for (std::uint32_t i = uncommitted_leads_.first(lead_offsets_[v]); i < lead_offsets_[v + 1];
         i = uncommitted_leads_.first(i + 1)) {
      const std::uint32_t h = leads_[i];
      if (marked(h)) continue;
      const std::uint32_t* c = corners(h);
      for (unsigned e = 0; e < 3; ++e) {
        if (c[e] != v && c[(e + 1) % 3] != v) continue;
        const std::uint32_t g = topology_.neighbor(h, e);
        if (g == kNoFace || strip_of_[g] == previous_strip) continue;
        const std::uint32_t other = c[e] == v ? c[(e + 1) % 3] : c[e];
        bool shares = false;
        for (unsigned s = 0; s < 3; ++s) {
          const std::uint32_t n = topology_.neighbor(h, s);
          shares |= n != kNoFace && strip_of_[n] == previous_strip;
        }
        return shares ? Start{h, v, other} : Start{h, other, v};
      }
    }
    return std::nullopt;
  }

  std::vector<std::vector<std::uint32_t>> experiment(const Start& start) {
    ++experiment_;
    std::vector<std::vector<std::uint32_t>> strips{build(start)};
    Start last = start;
    std::uint32_t last_strip = strip_;
    while (const std::optional<Start> next = traversal(last, last_strip)) {
      strips.push_back(build(*next));
      last = *next;
      last_strip = strip_;
    }
    return strips;
  }

  const Mesh& mesh_;
  const MeshTopology& topology_;
  std::vector<std::uint32_t> faces_;  // the non-degenerate faces, in input order
  std::vector<std::uint8_t> committed_;
  std::vector<std::uint32_t> position_;  // face -> its place in faces_
  RemovablePositions uncommitted_{0};    // places in faces_ of uncommitted faces
  // index_leads(): CSR vertex -> faces, the place of face f's corner n in leads_ (or kNoFace).
  std::vector<std::uint32_t> lead_offsets_, leads_, lead_position_;
  RemovablePositions uncommitted_leads_{0};
  // Stamps: the experiment and the strip that last took a face, the strip that last took a vertex.
  std::vector<std::uint32_t> experiment_of_, strip_of_, vertex_strip_;
  std::uint32_t experiment_ = 0, strip_ = 0;
  bool first_reset_ = true;
  float jump_ = 0.0f;  // the library's meshJump, in its float arithmetic
};

// Cuts strips into pieces of `length` faces (a remainder of 1-3 faces stays on the last piece).
std::vector<std::vector<std::uint32_t>> cut(const std::vector<std::vector<std::uint32_t>>& strips, std::size_t length) {
  std::vector<std::vector<std::uint32_t>> pieces;
  for (const auto& strip : strips) {
    const std::size_t n = strip.size(), whole = n / length, rest = n % length;
    if (n <= length) {
      pieces.push_back(strip);
      continue;
    }
    for (std::size_t p = 0; p < whole; ++p) {
      const bool last = p + 1 == whole;
      const std::size_t end = last && rest > 0 && rest < 4 ? n : (p + 1) * length;
      pieces.emplace_back(strip.begin() + std::ptrdiff_t(p * length), strip.begin() + std::ptrdiff_t(end));
    }
    if (rest >= 4) pieces.emplace_back(strip.begin() + std::ptrdiff_t(whole * length), strip.end());
  }
  return pieces;
}

// Orders the pieces greedily against a FIFO of `entries`: first the piece with the fewest
// neighbours per face, then always the piece with the most cache hits per face (the first on
// ties; with no hits at all, the first piece left).
//
// Each step looks at the pieces on the cached vertices. A piece's hits are kept up to date as
// vertices enter and leave the FIFO rather than recounted over its faces for every look, and
// taken pieces are dropped from the vertex lists as they are met (the tie rule compares piece
// numbers, so the lists' order does not matter): around a vertex shared by thousands of
// one-face pieces (an edge fan) each step otherwise re-read every piece ever placed there.
std::vector<std::size_t> order_pieces(const Mesh& mesh, const MeshTopology& topology,
                                      const std::vector<std::vector<std::uint32_t>>& pieces, std::uint32_t entries) {
  const std::size_t count = pieces.size();
  std::vector<std::size_t> order;
  if (count == 0) return order;
  const std::uint32_t* idx = mesh.indices.data();
  // vertex -> pieces (CSR, a piece once per corner).
  std::vector<std::uint32_t> offsets(topology.vertex_count + 1, 0);
  for (const auto& piece : pieces)
    for (const std::uint32_t f : piece)
      for (int n = 0; n < 3; ++n) ++offsets[idx[3 * std::size_t(f) + n] + 1];
  for (std::uint32_t v = 0; v < topology.vertex_count; ++v) offsets[v + 1] += offsets[v];
  std::vector<std::uint32_t> vertex_pieces(offsets.back()), fill(offsets.begin(), offsets.end() - 1);
  for (std::size_t p = 0; p < count; ++p)
    for (const std::uint32_t f : pieces[p])
      for (int n = 0; n < 3; ++n) vertex_pieces[fill[idx[3 * std::size_t(f) + n]]++] = std::uint32_t(p);
  std::vector<std::uint32_t>& live_end = fill;  // vertex v's untaken pieces: offsets[v]..live_end[v]

  // The FIFO as push serials: v is cached while pushes - serial[v] < entries.
  std::vector<std::uint32_t> serial(topology.vertex_count, 0), ring(entries, 0);
  std::uint32_t pushes = 0;
  const auto cached = [&](std::uint32_t v) { return serial[v] != 0 && pushes - serial[v] < entries; };
  std::vector<std::uint8_t> visited(count, 0);
  std::vector<std::uint32_t> hits(count, 0);  // corners of the piece on cached vertices
  const auto count_hits = [&](std::uint32_t v, bool entered) {
    for (std::uint32_t j = offsets[v]; j < live_end[v]; ++j) {
      std::uint32_t& h = hits[vertex_pieces[j]];
      h = entered ? h + 1 : h - 1;
    }
  };
  const auto take = [&](std::size_t p) {
    visited[p] = 1;
    order.push_back(p);
    for (const std::uint32_t f : pieces[p])
      for (int n = 0; n < 3; ++n) {
        const std::uint32_t v = idx[3 * std::size_t(f) + n];
        if (cached(v)) continue;
        ++pushes;
        if (pushes > entries) count_hits(ring[pushes % entries], false);  // push pushes - entries leaves
        serial[v] = pushes;
        ring[pushes % entries] = v;
        count_hits(v, true);
      }
  };

  std::size_t first = 0;
  double fewest = 1e30;
  for (std::size_t p = 0; p < count; ++p) {
    std::size_t neighbours = 0;
    for (const std::uint32_t f : pieces[p]) neighbours += topology.neighbor_count(f);
    const double per_face = double(neighbours) / double(pieces[p].size());
    if (per_face < fewest) {
      fewest = per_face;
      first = p;
    }
  }
  take(first);
  std::vector<std::uint32_t> seen(count, 0);
  std::uint32_t step = 0;
  std::size_t cursor = 0;
  while (order.size() < count) {
    ++step;
    std::size_t best = count, best_hits = 0, best_faces = 1;
    const std::uint32_t oldest = pushes >= entries ? pushes - entries + 1 : 1;
    for (std::uint32_t s = oldest; s <= pushes; ++s) {
      const std::uint32_t v = ring[s % entries];
      for (std::uint32_t j = offsets[v]; j < live_end[v];) {
        const std::uint32_t p = vertex_pieces[j];
        if (visited[p]) {
          vertex_pieces[j] = vertex_pieces[--live_end[v]];
          continue;
        }
        ++j;
        if (seen[p] == step) continue;
        seen[p] = step;
        const std::size_t piece_hits = hits[p], faces = pieces[p].size();
        // piece_hits / faces against best_hits / best_faces, exactly; lower index first on ties.
        if (best == count || piece_hits * best_faces > best_hits * faces ||
            (piece_hits * best_faces == best_hits * faces && p < best)) {
          best = p;
          best_hits = piece_hits;
          best_faces = faces;
        }
      }
    }
    if (best == count) {
      while (visited[cursor]) ++cursor;
      best = cursor;
    }
    take(best);
  }
  return order;
}

}  // namespace

Ordering reorder_nvstrip(const Mesh& mesh, const ReorderParams& params) {
  const MeshTopology topology = build_mesh_topology(mesh);
  const std::uint32_t cache = std::min(params.cache_size, kMaxCache);
  const std::uint32_t entries = cache > kCacheInefficiency ? cache - kCacheInefficiency : 1;
  Stripifier stripifier(mesh, topology);
  const std::vector<std::vector<std::uint32_t>> pieces = cut(stripifier.find_all_strips(), entries);
  std::vector<std::uint32_t> order;
  std::vector<std::uint8_t> restart_before;
  order.reserve(topology.face_count);
  restart_before.reserve(topology.face_count);
  for (const std::size_t p : order_pieces(mesh, topology, pieces, entries)) {
    for (std::size_t i = 0; i < pieces[p].size(); ++i) {
      order.push_back(pieces[p][i]);
      restart_before.push_back(i == 0);
    }
  }
  // The library drops degenerate faces; a permutation keeps them, each as its own strip at the end.
  for (std::uint32_t f = 0; f < topology.face_count; ++f) {
    if (degenerate(mesh.indices.data() + 3 * std::size_t(f))) {
      order.push_back(f);
      restart_before.push_back(1);
    }
  }
  return strip_ordering(mesh, topology, std::move(order), restart_before);
}

}  // namespace rastrace

#include "measure/crossings.hpp"

#include "parallel.hpp"
#include "spatial/columns.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <span>
#include <tuple>
#include <unordered_map>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/gtc/type_precision.hpp>

namespace knitc::measure {

namespace {

// A segment by where it is: its points are read from the pieces (a garment's copies of
// them were most of this check's memory).
struct Segment {
  std::uint32_t piece, index;
};

auto order(const Crossing& c) { return std::tie(c.piece_a, c.piece_b, c.segment_a, c.segment_b); }

}  // namespace

std::vector<Crossing> crossings(const std::vector<yarn_paths::Piece>& pieces, std::uint32_t near, int threads,
                                const std::vector<std::vector<std::uint8_t>>& looked_at) {
  assert(looked_at.empty() || looked_at.size() == pieces.size());
  auto looked = [&](const Segment& g) { return looked_at.empty() || looked_at[g.piece][g.index] != 0; };
  auto p_of = [&](const Segment& g) -> const glm::dvec3& { return pieces[g.piece].data_points[g.index]; };
  auto q_of = [&](const Segment& g) -> const glm::dvec3& { return pieces[g.piece].data_points[g.index + 1]; };
  // Every segment by one index: piece i's from first[i].
  std::vector<std::size_t> first(pieces.size() + 1, 0);
  double longest = 0.0;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const auto& points = pieces[i].data_points;
    first[i + 1] = first[i] + (points.size() > 1 ? points.size() - 1 : 0);
    for (std::size_t k = 0; k + 1 < points.size(); ++k)
      longest = std::max(longest, glm::distance(glm::dvec2(points[k]), glm::dvec2(points[k + 1])));
  }
  std::vector<Crossing> out;
  if (first.back() == 0 || longest <= 0.0) return out;
  // Each segment in the columns its box covers, seen from the face (at most four: a cell
  // is as long as the longest); the pairs that share a column are the candidates.
  const double cell = longest;
  spatial::Columns grid(cell);
  auto low_cell = [&](const Segment& g) {
    const glm::dvec2 lo = glm::min(glm::dvec2(p_of(g)), glm::dvec2(q_of(g))) / cell;
    return glm::i64vec2(static_cast<std::int64_t>(std::floor(lo.x)), static_cast<std::int64_t>(std::floor(lo.y)));
  };
  // The segment at an index, for indices asked in ascending runs (the mask's passes):
  // its piece found from the last one's.
  std::size_t piece_at = 0;
  auto segment = [&](std::size_t s) {
    if (s < first[piece_at]) piece_at = 0;
    while (s >= first[piece_at + 1]) ++piece_at;
    return Segment{static_cast<std::uint32_t>(piece_at), static_cast<std::uint32_t>(s - first[piece_at])};
  };
  // A segment not looked at is indexed only where it may share a column with one that is
  // (their boxes' low corners a column apart at most: a box spans two columns at most).
  // Only the segments indexed are listed (a tiled garment's few): `kept`.
  const spatial::ColumnMask beside_looked(
      first.back(), [&](std::size_t s) { return glm::i64vec3(low_cell(segment(s)), 0); },
      [&](std::size_t s) { return looked(segment(s)); });
  std::vector<Segment> kept;
  for (std::size_t i = 0; i < pieces.size(); ++i)
    for (std::size_t k = 0; k < first[i + 1] - first[i]; ++k) {
      const Segment g{static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(k)};
      if (!looked(g) && !beside_looked.holds(glm::i64vec3(low_cell(g), 0))) continue;
      const auto s = static_cast<std::uint32_t>(kept.size());
      kept.push_back(g);
      const glm::dvec2 lo = glm::min(glm::dvec2(p_of(g)), glm::dvec2(q_of(g))) / cell;
      const glm::dvec2 hi = glm::max(glm::dvec2(p_of(g)), glm::dvec2(q_of(g))) / cell;
      for (auto x = static_cast<std::int64_t>(std::floor(lo.x)); x <= static_cast<std::int64_t>(std::floor(hi.x)); ++x)
        for (auto y = static_cast<std::int64_t>(std::floor(lo.y)); y <= static_cast<std::int64_t>(std::floor(hi.y)); ++y)
          grid.add({x, y, 0}, s);
    }
  grid.index();
  // A pair may share several columns: it is tested in the first of them only (the lowest
  // x, then y, the two boxes share), so no list of every pair is kept: on a garment that
  // list was tens of millions of pairs, its sort most of the time and memory here.
  auto test = [&](std::uint32_t i, std::uint32_t j, std::vector<Crossing>& found) {
    const Segment &a = kept[i], &b = kept[j];
    if (!looked(a) && !looked(b)) return;
    if (a.piece == b.piece && (a.index > b.index ? a.index - b.index : b.index - a.index) < near) return;
    const glm::dvec3 &ap = p_of(a), &aq = q_of(a), &bp = p_of(b), &bq = q_of(b);
    const glm::dvec2 p(ap), r = glm::dvec2(aq) - p, q(bp), s = glm::dvec2(bq) - q;
    const double denom = r.x * s.y - r.y * s.x;
    if (std::abs(denom) < 1e-12 * (glm::dot(r, r) + glm::dot(s, s))) return;  // parallel
    const glm::dvec2 qp = q - p;
    const double t = (qp.x * s.y - qp.y * s.x) / denom, u = (qp.x * r.y - qp.y * r.x) / denom;
    // Half-open, so a crossing through a shared point counts once: on the segments that
    // start there, with a rounding's slack (two yarns laid through one point, as a twisted
    // stitch's legs are, would otherwise count twice or not at all).
    const double slack = 1e-9;
    if (t < -slack || t >= 1.0 - slack || u < -slack || u >= 1.0 - slack) return;
    const double za = ap.z + t * (aq.z - ap.z), zb = bp.z + u * (bq.z - bp.z);
    found.push_back({a.piece, a.index, b.piece, b.index, za - zb});
  };
  // The columns in blocks, each block's crossings its own list: sorted at the end, so
  // the same for any thread count.
  std::vector<std::span<const spatial::Columns::Entry>> columns;
  grid.each_column([&](std::span<const spatial::Columns::Entry> list) {
    if (list.size() >= 2) columns.push_back(list);
  });
  const std::size_t blocks = std::min<std::size_t>(columns.size(), 64);
  std::vector<std::vector<Crossing>> found(blocks);
  parallel_for(blocks, thread_count(threads), [&](std::size_t b) {
    for (std::size_t c = columns.size() * b / blocks; c < columns.size() * (b + 1) / blocks; ++c) {
      const auto list = columns[c];
      const std::uint64_t here = list.front().column;
      for (std::size_t e = 0; e < list.size(); ++e)
        for (std::size_t f = e + 1; f < list.size(); ++f) {
          const std::uint32_t i = std::min(list[e].item, list[f].item), j = std::max(list[e].item, list[f].item);
          const glm::i64vec2 shared = glm::max(low_cell(kept[i]), low_cell(kept[j]));
          if (spatial::Columns::column_key(shared.x, shared.y) == here) test(i, j, found[b]);
        }
    }
  });
  for (const auto& f : found) out.insert(out.end(), f.begin(), f.end());
  std::sort(out.begin(), out.end(), [](const Crossing& x, const Crossing& y) { return order(x) < order(y); });
  return out;
}

CrossingChanges compare(const std::vector<Crossing>& before, const std::vector<Crossing>& after, std::uint32_t window,
                        std::uint32_t pair_window, double touching, const std::vector<std::uint32_t>& segments,
                        const std::vector<char>& counted_before, const std::vector<char>& counted_after) {
  if (pair_window == 0) pair_window = window;
  assert(counted_before.empty() || counted_before.size() == before.size());
  assert(counted_after.empty() || counted_after.size() == after.size());
  auto counts_before = [&](std::size_t i) { return counted_before.empty() || counted_before[i] != 0; };
  auto counts_after = [&](std::size_t j) { return counted_after.empty() || counted_after[j] != 0; };
  CrossingChanges changes;
  auto gap = [](std::uint32_t x, std::uint32_t y) { return x > y ? x - y : y - x; };
  auto less = [](const Crossing& x, const Crossing& y) { return order(x) < order(y); };
  // The crossings of `list` between c's pieces within `w` segments on both.
  auto near = [&](const std::vector<Crossing>& list, const Crossing& c, std::uint32_t w, auto&& visit) {
    const Crossing low{c.piece_a, c.segment_a > w ? c.segment_a - w : 0, c.piece_b, 0, 0.0};
    for (auto it = std::lower_bound(list.begin(), list.end(), low, less);
         it != list.end() && it->piece_a == c.piece_a && it->piece_b == c.piece_b && it->segment_a <= c.segment_a + w; ++it)
      if (gap(it->segment_b, c.segment_b) <= w) visit(static_cast<std::size_t>(it - list.begin()));
  };
  auto tied = [](const Crossing& c) { return std::abs(c.depth) < 1e-3; };  // mm: both yarns at one height
  std::vector<char> left_out(before.size(), 0);
  for (std::size_t i = 0; i < before.size(); ++i) {
    if (tied(before[i])) {
      left_out[i] = 1;
      changes.ties += counts_before(i) ? 1 : 0;
      continue;
    }
  }
  // Every candidate match, the same yarn in front first, then nearest first (then in
  // order): taken when both ends are free. Where two yarns cross several times within the
  // window, a pair slid in beside a crossing (the other yarn in front at both) must not
  // take the crossing's place: matched by distance alone, the crossing would count as
  // flipped and its true match as new. A real flip still shows: its crossing matches the
  // other way, or its leftovers pair with nothing.
  struct Candidate {
    bool flips;
    std::uint32_t distance;
    std::size_t from, to;
  };
  std::vector<Candidate> candidates;
  for (std::size_t i = 0; i < before.size(); ++i) {
    near(after, before[i], window, [&](std::size_t j) {
      candidates.push_back({(before[i].depth > 0.0) != (after[j].depth > 0.0),
                            gap(after[j].segment_a, before[i].segment_a) + gap(after[j].segment_b, before[i].segment_b), i, j});
    });
  }
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& x, const Candidate& y) {
    return std::tie(x.flips, x.distance, x.from, x.to) < std::tie(y.flips, y.distance, y.from, y.to);
  });
  std::vector<char> matched_before(before.size(), 0), matched_after(after.size(), 0);
  for (const Candidate& c : candidates) {
    if (matched_before[c.from] || matched_after[c.to]) continue;
    matched_before[c.from] = matched_after[c.to] = 1;
    if (left_out[c.from]) continue;  // a tie: either way is its way
    if (!counts_before(c.from) && !counts_after(c.to)) continue;
    if ((before[c.from].depth > 0.0) == (after[c.to].depth > 0.0)) {
      ++changes.kept;
    } else {
      ++changes.flipped;
    }
  }
  // The unmatched, paired off two by two where the same yarn is in front at both.
  // A segment within the pair window of its piece's first or last.
  auto by_end = [&](std::uint32_t piece, std::uint32_t segment) {
    return piece < segments.size() && (segment < pair_window || segment + pair_window >= segments[piece]);
  };
  auto alone = [&](const std::vector<Crossing>& list, const std::vector<char>& skip, auto&& counts, std::vector<std::size_t>& at,
                   std::size_t& at_end) {
    std::vector<char> paired(list.size(), 0);
    std::size_t count = 0;
    for (std::size_t i = 0; i < list.size(); ++i) {
      if (skip[i] || paired[i]) continue;
      std::size_t partner = list.size();
      near(list, list[i], pair_window, [&](std::size_t j) {
        if (partner == list.size() && j != i && !skip[j] && !paired[j] && (list[j].depth > 0.0) == (list[i].depth > 0.0)) partner = j;
      });
      // A yarn's own kink, two stretches of one piece a few segments apart along it, may
      // twist out or in alone (Reidemeister's first move).
      const bool kink = list[i].piece_a == list[i].piece_b && gap(list[i].segment_a, list[i].segment_b) <= pair_window;
      const bool end = by_end(list[i].piece_a, list[i].segment_a) || by_end(list[i].piece_b, list[i].segment_b);
      if (partner == list.size() && !kink && end) {
        at_end += counts(i) ? 1 : 0;
      } else if (partner == list.size() && !kink) {
        if (counts(i)) {
          ++count;
          at.push_back(i);
        }
      } else if (partner != list.size()) {
        paired[i] = paired[partner] = 1;
      }
    }
    return count;
  };
  std::vector<char> skip_before(before.size()), skip_after(after.size());
  for (std::size_t i = 0; i < before.size(); ++i) {
    skip_before[i] = left_out[i] || matched_before[i];
    changes.lost += skip_before[i] || !counts_before(i) ? 0 : 1;
  }
  for (std::size_t j = 0; j < after.size(); ++j) {
    skip_after[j] = matched_after[j];
    changes.found += skip_after[j] || !counts_after(j) ? 0 : 1;
  }
  changes.lost_alone = alone(before, skip_before, counts_before, changes.lost_alone_at, changes.lost_at_end);
  changes.found_alone = alone(after, skip_after, counts_after, changes.found_alone_at, changes.found_at_end);
  for (std::size_t i : changes.lost_alone_at) changes.lost_alone_touching += std::abs(before[i].depth) < touching ? 1 : 0;
  for (std::size_t j : changes.found_alone_at) changes.found_alone_touching += std::abs(after[j].depth) < touching ? 1 : 0;
  return changes;
}

CrossingChanges relaxation_changes(const std::vector<yarn_paths::Piece>& laid, const std::vector<yarn_paths::Piece>& relaxed,
                                   double thickest, int threads, const std::vector<std::uint32_t>& same_as) {
  std::vector<std::uint32_t> segments;
  for (const auto& piece : laid) segments.push_back(piece.data_points.empty() ? 0 : static_cast<std::uint32_t>(piece.data_points.size() - 1));
  constexpr std::uint32_t window = 12, pair_window = 24;
  if (same_as.empty()) return compare(crossings(laid, 2, threads), crossings(relaxed, 2, threads), window, pair_window, thickest, segments);
  // Per segment: 2 where an end is its own (not a copy), 1 within `context` segments of
  // one along its piece (every match and partner of a counted crossing lies there), else 0.
  constexpr std::size_t context = 2 * (window + pair_window);
  std::vector<std::vector<std::uint8_t>> looked_at(laid.size());
  std::size_t at = 0;
  for (std::size_t i = 0; i < laid.size(); ++i) {
    const std::size_t n = laid[i].data_points.size();
    auto& looked = looked_at[i];
    looked.assign(n, 0);  // n - 1 segments, and one to spare
    for (std::size_t k = 0; k + 1 < n; ++k)
      looked[k] = same_as[at + k] == at + k || same_as[at + k + 1] == at + k + 1 ? 2 : 0;
    // Within `context` of an own segment, either way: two passes of the distance to one.
    std::size_t since = SIZE_MAX;
    for (std::size_t k = 0; k + 1 < n; ++k) {
      since = looked[k] == 2 ? 0 : since == SIZE_MAX ? since : since + 1;
      if (looked[k] == 0 && since <= context) looked[k] = 1;
    }
    since = SIZE_MAX;
    for (std::size_t k = n - 1; k-- > 0;) {
      since = looked[k] == 2 ? 0 : since == SIZE_MAX ? since : since + 1;
      if (looked[k] == 0 && since <= context) looked[k] = 1;
    }
    at += n;
  }
  assert(at == same_as.size());
  const auto before = crossings(laid, 2, threads, looked_at), after = crossings(relaxed, 2, threads, looked_at);
  auto counted = [&](const std::vector<Crossing>& list) {
    std::vector<char> out(list.size());
    for (std::size_t c = 0; c < list.size(); ++c)
      out[c] = looked_at[list[c].piece_a][list[c].segment_a] == 2 || looked_at[list[c].piece_b][list[c].segment_b] == 2;
    return out;
  };
  CrossingChanges changes = compare(before, after, window, pair_window, thickest, segments, counted(before), counted(after));
  for (std::size_t i = 0; i < same_as.size() && !changes.copies_left_out; ++i) changes.copies_left_out = same_as[i] != i;
  return changes;
}

}  // namespace knitc::measure

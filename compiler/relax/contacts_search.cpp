// Contacts::find: the close pairs of segments found in a grid of columns and filed by
// strips for push_apart (contacts.cpp).
#include "relax/contacts.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "parallel.hpp"
#include "spatial/columns.hpp"

namespace knitc::relax {

namespace {

glm::dvec3 midpoint(const Chains& c, std::size_t i) { return 0.5 * (c.pos[i] + c.pos[i + 1]); }

// Room for n in a list kept from one full search to the next, with a quarter to spare:
// the lists grow a little search by search as the yarns press together, and each grown
// to the count exactly was mapped afresh the next time (a hat's are hundreds of MB).
template <class T>
void room_for(std::vector<T>& list, std::size_t n) {
  if (list.capacity() < n) list.reserve(n + n / 4);
}
double along_mid(const Chains& c, std::size_t i) { return c.along[i] + 0.5 * c.rest_length[i]; }

}  // namespace

// The contactable segments' midpoints in the grid of columns (spatial/columns.hpp), their
// periodic images too.
struct Contacts::Grid {
  spatial::Columns columns{1.0};
  glm::dvec2 lo{1e300}, hi{-1e300};  // the box of the contactable segments' midpoints
  // The columns that hold a segment with a point free to move, sorted: a held segment
  // with none of them around it has no pair to push (a tiled interior's, most of a big
  // fabric's edge sweeps), so it is not looked at.
  std::vector<std::uint64_t> free_columns;
  // Segments longer than the cell allows for (twice the mean: a few, where the curve
  // swings wide between close data points, or a float), per segment; and how many cells
  // their pairs may reach. (None where the cell allows for the longest: see grid_of.)
  std::vector<std::uint8_t> long_segment;
  int long_reach = 1;
  // Each contactable segment's half length (0 for the others), measured once: a search
  // meets each segment as a candidate some 75 times, and its square root was most of a
  // candidate's cost.
  std::vector<double> half;
  double longest = 0.0;  // the longest contactable segment
  bool empty() const { return lo.x > hi.x; }
  bool free_near(const glm::i64vec3& cell) const {
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        if (std::binary_search(free_columns.begin(), free_columns.end(), spatial::Columns::column_key(cell.x + dx, cell.y + dy)))
          return true;
    return false;
  }
};

Contacts::Contacts(glm::dvec2 period, double margin, bool round, int threads)
    : period_(period), margin_(margin), round_(round), threads_(threads) {}
Contacts::~Contacts() = default;

namespace {
bool held_segment(const Chains& c, std::size_t i) { return c.inv_mass[i] == 0.0 && c.inv_mass[i + 1] == 0.0; }
}  // namespace

Contacts::Grid Contacts::grid_of(const Chains& c) const {
  Grid g;
  const std::size_t n = c.pos.size();
  double longest = 0.0, sum = 0.0;
  std::size_t counted = 0;
  g.half.assign(n, 0.0);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    if (!c.contactable[i]) continue;
    const double length = glm::distance(c.pos[i], c.pos[i + 1]);
    g.half[i] = 0.5 * length;
    longest = std::max(longest, length);
    sum += length;
    ++counted;
    const glm::dvec3 m = midpoint(c, i);
    g.lo = glm::min(g.lo, glm::dvec2(m));
    g.hi = glm::max(g.hi, glm::dvec2(m));
  }
  g.longest = longest;
  if (g.empty()) return g;
  // A pair's midpoints lie at most free diameters (the shells' reach), the margin and the
  // two half lengths apart: a cell that wide finds every pair in the cells round it. Sized
  // for the longest segment, a few long ones (a machine-knit hat's: 2.4 mm against a
  // 0.33 mm mean) made every cell twice as wide, eight times the volume, and each search
  // 6 s. Where the longest would make the cell half as wide again as twice the mean
  // allows for, the cell allows for that, and the longer ones search as far as they reach.
  // (Elsewhere the gain is small: the library's cables' longest widen it 5%.)
  const double allowed = 2.0 * sum / static_cast<double>(counted);
  const bool trimmed = c.thickest + margin_ + longest > 1.5 * (c.thickest + margin_ + allowed);
  const double cell = c.thickest + margin_ + (trimmed ? allowed : longest);
  if (trimmed) {
    g.long_segment.assign(n, 0);
    for (std::size_t i = 0; i + 1 < n; ++i)
      if (c.contactable[i] && glm::distance(c.pos[i], c.pos[i + 1]) > allowed) g.long_segment[i] = 1;
    g.long_reach = static_cast<int>(std::ceil((c.thickest + margin_ + longest) / cell));
  }
  g.columns = spatial::Columns(cell);
  g.columns.reserve(n);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    if (!c.contactable[i]) continue;
    const glm::dvec3 m = midpoint(c, i);
    // Periodic: a segment also stands in for its images a period on and back, every one
    // (a repeat is small, and a tuck's held loop reaches two courses past its own).
    for (int sx = -1; sx <= 1; ++sx) {
      if (sx != 0 && period_.x == 0.0) continue;
      for (int sy = -1; sy <= 1; ++sy) {
        if (sy != 0 && period_.y == 0.0) continue;
        const glm::i64vec3 at = g.columns.cell_of(m + glm::dvec3(sx * period_.x, sy * period_.y, 0.0));
        g.columns.add(at, static_cast<std::uint32_t>(i), static_cast<std::int8_t>(sx), static_cast<std::int8_t>(sy));
        if (!held_segment(c, i)) g.free_columns.push_back(spatial::Columns::column_key(at.x, at.y));
      }
    }
  }
  g.columns.index();
  std::sort(g.free_columns.begin(), g.free_columns.end());
  g.free_columns.erase(std::unique(g.free_columns.begin(), g.free_columns.end()), g.free_columns.end());
  return g;
}

// Inlined into each search, as the pair test it was: a call a candidate cost 6%.
template <class KnownSide>
[[gnu::always_inline]] inline bool Contacts::pair_of(const Chains& c, std::size_t a, const glm::dvec3& ma, double half_a,
                                                     std::size_t bs, double half_b, std::int8_t sx, std::int8_t sy,
                                                     double margin, KnownSide&& known_side, Pair& pair) const {
  // (The tests are all needed for a pair: the cheapest, the midpoints' distance, first.)
  const glm::dvec3 offset(sx * period_.x, sy * period_.y, 0.0);
  const glm::dvec3 between = ma - midpoint(c, bs) - offset;
  const double bound = c.shell[a] + c.shell[bs] + margin + half_a + half_b;
  if (glm::dot(between, between) > bound * bound) return false;
  // Two segments that share a point cannot be pushed apart: not a contact, however
  // long they are (where the curve through two close data points swings wide,
  // refine's segments along it are long enough to pass the test above).
  if (bs == a + 1 && sx == 0 && sy == 0 && c.segment[a] && c.piece[a] == c.piece[bs]) return false;
  // One stretch of yarn, not a contact: of one piece, close along it (or along its
  // image, a period on, when its yarn runs on into the next tile).
  if (sy == 0 && c.piece[a] == c.piece[bs] &&
      std::abs(along_mid(c, a) - along_mid(c, bs) - sx * c.along_period[c.piece[a]]) <= 1.8 * (c.shell[a] + c.shell[bs]))
    return false;
  const auto held = static_cast<std::uint8_t>((c.inv_mass[a] == 0.0 ? 1 : 0) | (c.inv_mass[a + 1] == 0.0 ? 2 : 0) |
                                              (c.inv_mass[bs] == 0.0 ? 4 : 0) | (c.inv_mass[bs + 1] == 0.0 ? 8 : 0));
  if (held == 15) return false;  // neither can move: nothing to push
  pair = Pair{static_cast<std::uint32_t>(a), static_cast<std::uint32_t>(bs), sx, sy, held, 0,
              static_cast<float>(c.radius[a] + c.radius[bs]), static_cast<float>(c.shell[a] + c.shell[bs])};
  const std::int8_t side = known_side(pair);
  pair.side = side != 0 ? side : side_of(c, pair);
  return gap(c, pair) + pair.reach - pair.shell < margin;
}

std::vector<std::vector<Contacts::Pair>> Contacts::close_pairs(const Chains& c, const Grid& grid,
                                                               const std::vector<Pair>& previous) const {
  const std::size_t n = c.pos.size();
  const bool any_long = !grid.long_segment.empty();
  auto is_long = [&](std::size_t s) { return any_long && grid.long_segment[s] != 0; };
  using Known = std::pair<std::vector<Pair>::const_iterator, std::vector<Pair>::const_iterator>;
  // The previous list's pairs of segment a: a few, looked up among themselves.
  auto known_of = [&](std::size_t a) {
    const auto mine_from = std::lower_bound(previous.begin(), previous.end(), a, [](const Pair& x, std::size_t y) { return x.a < y; });
    auto mine_to = mine_from;
    while (mine_to != previous.end() && mine_to->a == a) ++mine_to;
    return Known(mine_from, mine_to);
  };
  // The pair of segments a < b, b's image (sx, sy) periods on, if it is one to keep;
  // `mine`, a's previous pairs (null: looked up here, for a pair that is close).
  // (`ma`, `half_a`: a's midpoint and half length, made once for its many candidates.)
  auto pair_of = [&](std::size_t a, const glm::dvec3& ma, double half_a, std::size_t bs, std::int8_t sx, std::int8_t sy,
                     const Known* known_pairs, Pair& pair) __attribute__((always_inline)) {
    auto known_side = [&](const Pair& key) -> std::int8_t {
      const Known mine = known_pairs ? *known_pairs : known_of(a);
      const auto known = std::lower_bound(mine.first, mine.second, key, key_before);
      return known != mine.second && !key_before(key, *known) ? known->side : 0;
    };
    return this->pair_of(c, a, ma, half_a, bs, grid.half[bs], sx, sy, margin_, known_side, pair);
  };
  // Each block of segments its own list, joined in order: the same list for any thread count.
  const std::size_t blocks = std::max<std::size_t>(1, std::min<std::size_t>(64, n / 4096));
  std::vector<std::vector<Pair>> found(blocks);
  parallel_for(blocks, threads_, [&](std::size_t block) {
    const std::size_t from = n * block / blocks, to = n * (block + 1) / blocks;
    for (std::size_t a = from; a < to && a + 1 < n; ++a) {
      if (!c.contactable[a] || is_long(a)) continue;
      const glm::dvec3 ma = midpoint(c, a);
      const glm::i64vec3 cell = grid.columns.cell_of(ma);
      if (held_segment(c, a) && !grid.free_near(cell)) continue;
      const double half_a = grid.half[a];
      const Known mine = known_of(a);
      grid.columns.near(cell, [&](const spatial::Columns::Entry& b) {
        if (b.item <= a || is_long(b.item)) return;  // a long one finds its own pairs
        Pair pair;
        if (pair_of(a, ma, half_a, b.item, b.sx, b.sy, &mine, pair)) found[block].push_back(pair);
      });
    }
  });
  if (!any_long) return found;
  // The long segments' pairs, each searched as far as it reaches: with every shorter
  // segment, and with the long ones after it. Filed by their first segment into its
  // block's list, after that segment's other pairs, in (a, b, image) order.
  std::vector<std::size_t> longs;
  for (std::size_t s = 0; s + 1 < n; ++s)
    if (is_long(s)) longs.push_back(s);
  std::vector<std::vector<Pair>> long_found(longs.size());
  parallel_for(longs.size(), threads_, [&](std::size_t k) {
    const std::size_t a = longs[k];
    const Known mine = known_of(a);
    const glm::dvec3 ma = midpoint(c, a);
    const double half_a = grid.half[a];
    grid.columns.near(grid.columns.cell_of(ma), grid.long_reach, [&](const spatial::Columns::Entry& b) {
      if (b.item == a || (is_long(b.item) && b.item < a)) return;
      Pair pair;
      const std::size_t bs = b.item;
      const bool kept = bs > a ? pair_of(a, ma, half_a, bs, b.sx, b.sy, &mine, pair)
                               : pair_of(bs, midpoint(c, bs), grid.half[bs], a,
                                         static_cast<std::int8_t>(-b.sx), static_cast<std::int8_t>(-b.sy), nullptr, pair);
      if (kept) long_found[k].push_back(pair);
    });
  });
  std::vector<Pair> extra;
  for (const auto& list : long_found) extra.insert(extra.end(), list.begin(), list.end());
  std::sort(extra.begin(), extra.end(), key_before);
  auto next = extra.begin();
  for (std::size_t block = 0; block < blocks; ++block) {
    const std::size_t to = n * (block + 1) / blocks;
    auto last = next;
    while (last != extra.end() && (last->a < to || block + 1 == blocks)) ++last;
    if (last == next) continue;
    std::vector<Pair> merged;
    merged.reserve(found[block].size() + static_cast<std::size_t>(last - next));
    auto mine = found[block].begin();
    for (auto e = next; e != last; ++e) {
      while (mine != found[block].end() && mine->a <= e->a) merged.push_back(*mine++);
      merged.push_back(*e);
    }
    merged.insert(merged.end(), mine, found[block].end());
    found[block] = std::move(merged);
    next = last;
  }
  return found;
}

// Strips one cell high across the courses; a pair belongs to its first segment's strip
// when its second is in the same or the next one, else to the few worked alone.
void Contacts::file_by_strips(const Chains& c, const Grid& grid, const std::vector<std::vector<Pair>>& found) {
  const double cell = grid.columns.cell();
  const auto strips = static_cast<std::size_t>(std::floor((grid.hi.y - grid.lo.y) / cell)) + 1;
  auto strip_of = [&](std::uint32_t segment) {
    return std::min(strips - 1,
                    static_cast<std::size_t>(std::max(0.0, std::floor((midpoint(c, segment).y - grid.lo.y) / cell))));
  };
  std::vector<std::size_t> count(strips + 1, 0);
  std::size_t total = 0;
  for (const auto& list : found) total += list.size();
  std::vector<std::uint32_t>& strip_of_pair = strip_of_pair_;
  strip_of_pair.clear();
  room_for(strip_of_pair, total);
  for (const auto& list : found)
    for (const Pair& p : list) {
      const std::size_t ka = strip_of(p.a), kb = strip_of(p.b);
      const std::size_t k = p.sy == 0 && (ka > kb ? ka - kb : kb - ka) <= 1 ? ka : strips;
      strip_of_pair.push_back(static_cast<std::uint32_t>(k));
      ++count[k];
    }
  std::vector<std::size_t> start(strips + 2, 0);
  for (std::size_t k = 0; k <= strips; ++k) start[k + 1] = start[k] + count[k];
  across_first_ = start[strips];
  strip_first_.assign(start.begin(), start.begin() + static_cast<std::ptrdiff_t>(strips + 1));
  room_for(pairs_, total);
  pairs_.resize(total);
  std::vector<std::size_t> next = std::move(start);
  // The pairs come found in order of their first segment: each first segment's few put in
  // (a, b, image) order give the lookup order without sorting them all.
  room_for(by_segments_, total);
  by_segments_.resize(total);
  std::size_t i = 0;
  for (const auto& list : found)
    for (const Pair& p : list) {
      by_segments_[i] = static_cast<std::uint32_t>(next[strip_of_pair[i]]++);
      pairs_[by_segments_[i]] = p;
      ++i;
    }
  auto before = [&](std::uint32_t x, std::uint32_t y) { return key_before(pairs_[x], pairs_[y]); };
  for (std::size_t from = 0; from < total;) {
    std::size_t to = from + 1;
    while (to < total && pairs_[by_segments_[to]].a == pairs_[by_segments_[from]].a) ++to;
    std::sort(by_segments_.begin() + static_cast<std::ptrdiff_t>(from), by_segments_.begin() + static_cast<std::ptrdiff_t>(to), before);
    from = to;
  }
}

void Contacts::find(const Chains& c) {
  if (!built_at_.empty() && built_at_.size() == c.pos.size() && grid_ && refind(c)) return;
  ++full_finds_;
  built_at_ = c.pos;
  // The sides of the pairs listed so far, to look up by (a, b, image): the full list's
  // live pairs and those found again since (their keys apart), merged as they are read
  // (a hat's list is some 20 million pairs: a copy of them first doubled the memory).
  std::vector<Pair>& previous = previous_;
  previous.clear();
  room_for(previous, by_segments_.size() + extra_.size());
  auto again = extra_.cbegin();
  for (const std::uint32_t k : by_segments_) {
    const Pair& p = pairs_[k];
    if (p.held & dead) continue;
    while (again != extra_.cend() && key_before(*again, p)) previous.push_back(*again++);
    previous.push_back(p);
  }
  previous.insert(previous.end(), again, extra_.cend());
  pairs_.clear();
  extra_.clear();
  wandered_.clear();
  wanderers_.clear();
  pairs_of_first_.clear();
  pairs_of_.clear();
  grid_scale_ = glm::dvec3(1.0);
  grid_offset_ = glm::dvec3(0.0);
  grid_ = std::make_unique<Grid>(grid_of(c));
  if (grid_->empty()) {  // nothing takes part
    strip_first_.assign(1, 0);
    across_first_ = 0;
    by_segments_.clear();
    grid_.reset();
    return;
  }
  file_by_strips(c, *grid_, close_pairs(c, *grid_, previous));
}

// A long relaxation's late sweeps move few points half the margin (one to a few hundred
// of a machine program's 300,000 or a hat's 2.6 million), and a full search each time
// was most of such a sweep. So only the segments those points end are searched again:
// their pairs in the full list are marked dead and what is found goes to extra_.
//
// Why no pair that can touch is missed: each point's built_at is where it was when all
// its segments' pairs were last tested. A pair tested by the full search had every point
// within half the margin of there, and each point moves at most half the margin more
// before the list is stale: the margin holds. A pair tested again here has its moved
// segment's points at their new built_at, but the other's may be half the margin from
// theirs already, and each may go half the margin further: so it is kept up to twice the
// margin. The candidates: a segment not searched again since the full search lies within
// half the margin of its place in that search's grid (moved by the size's moves since),
// so that grid is asked, a cell further; the ones searched again are indexed afresh.
//
// False (nothing changed) when so many have moved that a full search is as cheap.
bool Contacts::refind(const Chains& c) {
  const std::size_t n = c.pos.size();
  const double limit = 0.25 * margin_ * margin_;  // half the margin, squared
  std::vector<std::uint32_t> moved_points;
  for (std::size_t i = 0; i < n; ++i) {
    const glm::dvec3 moved = c.pos[i] - built_at_[i];
    if (glm::dot(moved, moved) > limit) moved_points.push_back(static_cast<std::uint32_t>(i));
  }
  if (moved_points.empty()) return true;
  // The segments they end, each once, ascending.
  std::vector<std::uint32_t> segments;
  auto add = [&](std::uint32_t s) {
    if (s + 1 < n && c.contactable[s] && (segments.empty() || segments.back() < s)) segments.push_back(s);
  };
  for (const std::uint32_t i : moved_points) {
    if (i > 0) add(i - 1);
    add(i);
  }
  if (wandered_.empty()) wandered_.assign(n, 0);
  std::size_t fresh_wanderers = 0;
  for (const std::uint32_t s : segments) fresh_wanderers += wandered_[s] ? 0 : 1;
  if (wanderers_.size() + fresh_wanderers > std::max<std::size_t>(256, n / refind_share)) return false;

  if (pairs_of_first_.empty()) {  // each segment's pairs in the full list, as a or b
    pairs_of_first_.assign(n + 1, 0);
    for (const Pair& p : pairs_) ++pairs_of_first_[p.a + 1], ++pairs_of_first_[p.b + 1];
    for (std::size_t s = 0; s < n; ++s) pairs_of_first_[s + 1] += pairs_of_first_[s];
    pairs_of_.resize(pairs_of_first_[n]);
    std::vector<std::uint32_t> next(pairs_of_first_.begin(), pairs_of_first_.end() - 1);
    for (std::size_t k = 0; k < pairs_.size(); ++k) {
      pairs_of_[next[pairs_[k].a]++] = static_cast<std::uint32_t>(k);
      pairs_of_[next[pairs_[k].b]++] = static_cast<std::uint32_t>(k);
    }
  }
  std::vector<std::uint8_t> searched(n, 0);  // now
  for (const std::uint32_t s : segments) {
    searched[s] = 1;
    if (!wandered_[s]) wandered_[s] = 1, wanderers_.push_back(s);
  }
  // The sides as last listed (the old pairs go only after the search).
  auto known_side = [&](const Pair& key) -> std::int8_t {
    const Pair* q = listed(key);
    return q ? q->side : 0;
  };
  // The wandered segments where they are now, images too, in a grid of the full one's cell.
  const Grid& grid = *grid_;
  const double cell = grid.columns.cell();
  spatial::Columns near_again(cell);
  double longest_again = 0.0;
  for (const std::uint32_t s : wanderers_) {
    const glm::dvec3 m = midpoint(c, s);
    longest_again = std::max(longest_again, glm::distance(c.pos[s], c.pos[s + 1]));
    for (int sx = -1; sx <= 1; ++sx) {
      if (sx != 0 && period_.x == 0.0) continue;
      for (int sy = -1; sy <= 1; ++sy) {
        if (sy != 0 && period_.y == 0.0) continue;
        near_again.add(near_again.cell_of(m + glm::dvec3(sx * period_.x, sy * period_.y, 0.0)), s, static_cast<std::int8_t>(sx),
                       static_cast<std::int8_t>(sy));
      }
    }
  }
  near_again.index();
  const double wide = 2.0 * margin_;
  const double shrink = std::min({grid_scale_.x, grid_scale_.y, grid_scale_.z});
  const double grow = std::max({grid_scale_.x, grid_scale_.y, grid_scale_.z});
  constexpr std::size_t block = 64;
  std::vector<std::vector<Pair>> found((segments.size() + block - 1) / block);
  parallel_for(found.size(), threads_, [&](std::size_t k) {
    for (std::size_t i = k * block; i < std::min(segments.size(), (k + 1) * block); ++i) {
      const std::size_t a = segments[i];
      const glm::dvec3 ma = midpoint(c, a);
      const double half_a = 0.5 * glm::distance(c.pos[a], c.pos[a + 1]);
      auto visit = [&](const spatial::Columns::Entry& b) {
        const std::size_t bs = b.item;
        if (bs == a || (bs < a && searched[bs])) return;  // each pair once: from its first segment if both are searched
        const double half_b = 0.5 * glm::distance(c.pos[bs], c.pos[bs + 1]);
        Pair pair;
        const bool kept = bs > a ? pair_of(c, a, ma, half_a, bs, half_b, b.sx, b.sy, wide, known_side, pair)
                                 : pair_of(c, bs, midpoint(c, bs), half_b, a, half_a, static_cast<std::int8_t>(-b.sx),
                                           static_cast<std::int8_t>(-b.sy), wide, known_side, pair);
        if (kept) found[k].push_back(pair);
      };
      // Within reach now: shells, twice the margin, the two half lengths. An unwandered
      // segment is within half the margin of its place then, its half length too.
      const double reach_now = c.thickest + wide + half_a;
      const double then = (reach_now + 0.5 * grid.longest * grow + 1.5 * margin_) / shrink;
      grid.columns.near(grid.columns.cell_of((ma - grid_offset_) / grid_scale_), static_cast<int>(std::ceil(then / cell)),
                        [&](const spatial::Columns::Entry& b) {
                          if (!wandered_[b.item]) visit(b);
                        });
      near_again.near(near_again.cell_of(ma), static_cast<int>(std::ceil((reach_now + 0.5 * longest_again) / cell)), visit);
    }
  });
  std::vector<Pair> fresh;
  for (const auto& list : found) fresh.insert(fresh.end(), list.begin(), list.end());
  std::sort(fresh.begin(), fresh.end(), key_before);  // each key once: the same order always
  // The old pairs of the searched segments go.
  for (const std::uint32_t s : segments)
    for (std::uint32_t k = pairs_of_first_[s]; k < pairs_of_first_[s + 1]; ++k) pairs_[pairs_of_[k]].held |= dead;
  std::vector<Pair> kept;
  kept.reserve(extra_.size() + fresh.size());
  for (const Pair& p : extra_)
    if (!searched[p.a] && !searched[p.b]) kept.push_back(p);
  extra_.clear();
  std::merge(kept.begin(), kept.end(), fresh.begin(), fresh.end(), std::back_inserter(extra_), key_before);
  for (const std::uint32_t i : moved_points) built_at_[i] = c.pos[i];
  ++refinds_;
  return true;
}

bool Contacts::stale(const Chains& c) const {
  const double limit = 0.25 * margin_ * margin_;  // half the margin, squared
  for (std::size_t i = 0; i < c.pos.size(); ++i) {
    const glm::dvec3 moved = c.pos[i] - built_at_[i];
    if (glm::dot(moved, moved) > limit) return true;
  }
  return false;
}

}  // namespace knitc::relax

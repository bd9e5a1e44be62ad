#include "relax/press.hpp"

#include <algorithm>
#include <cassert>
#include <climits>
#include <cmath>

#include <glm/geometric.hpp>

#include "parallel.hpp"
#include "spatial/columns.hpp"

namespace knitc::relax {

namespace {

// The points of every piece by one index, with what a contact needs to know of each.
// The positions are read where they are, in the pieces: a garment's copy of them was
// most of this stage's fresh memory (docs/performance.md).
struct Points {
  std::vector<const glm::dvec3*> data;  // per piece, its first point
  std::vector<double> along;            // mm along its piece
  std::vector<double> piece_free_r, piece_shell;  // per piece: free radius, and free minus core radius, mm
  double free_r(std::size_t i) const { return piece_free_r[piece[i]]; }
  double shell(std::size_t i) const { return piece_shell[piece[i]]; }
  const glm::dvec3& pos(std::size_t i) const { return data[piece[i]][i - first[piece[i]]]; }
  std::vector<std::uint32_t> piece;
  std::vector<std::size_t> first;       // per piece, then the end
  std::size_t size() const { return along.size(); }
  double thickest = 0.0, longest = 0.0;  // the largest free diameter, and step along a piece, mm
};

Points points_of(const std::vector<yarn_paths::Piece>& pieces, const std::vector<yarn::Size>& sizes) {
  Points p;
  std::size_t n = 0;
  for (const auto& piece : pieces) n += piece.data_points.size();
  p.along.reserve(n);
  p.piece.reserve(n);
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    p.first.push_back(p.along.size());
    p.data.push_back(pieces[i].data_points.data());
    const yarn::Size& size = sizes[static_cast<std::size_t>(pieces[i].yarn)];
    p.piece_free_r.push_back(0.5 * size.free_diameter);
    p.piece_shell.push_back(0.5 * (size.free_diameter - size.core_diameter));
    if (!pieces[i].data_points.empty()) p.thickest = std::max(p.thickest, size.free_diameter);
    double s = 0.0;
    for (std::size_t k = 0; k < pieces[i].data_points.size(); ++k) {
      if (k > 0) {
        const double step = glm::distance(pieces[i].data_points[k - 1], pieces[i].data_points[k]);
        s += step;
        p.longest = std::max(p.longest, step);
      }
      p.along.push_back(s);
      p.piece.push_back(static_cast<std::uint32_t>(i));
    }
  }
  p.first.push_back(p.along.size());
  return p;
}

// The unit tangent at point k of the piece running over [from, to).
glm::dvec3 tangent(const Points& p, std::size_t k, std::size_t from, std::size_t to) {
  const std::size_t a = k > from ? k - 1 : k, b = k + 1 < to ? k + 1 : k;
  const glm::dvec3 d = p.pos(b) - p.pos(a);
  const double l = glm::length(d);
  return l > 0.0 ? d / l : glm::dvec3(0.0);
}

}  // namespace

void press(std::vector<yarn_paths::Piece>& pieces, const std::vector<yarn::Size>& sizes, int threads,
           const std::vector<std::uint32_t>& same_as) {
  const Points p = points_of(pieces, sizes);
  const std::size_t n = p.size();
  assert(same_as.empty() || same_as.size() == n);
  auto own = [&](std::size_t i) { return same_as.empty() || same_as[i] == i; };
  // Each point's direction, found in the pieces' own arrays and smoothed there in place:
  // a garment's second 43 MB array was most of this stage's fresh memory.
  for (auto& piece : pieces) piece.pressed.assign(piece.data_points.size(), glm::dvec3(0.0));
  auto pressed = [&](std::size_t i) -> glm::dvec3& { return pieces[p.piece[i]].pressed[i - p.first[p.piece[i]]]; };
  const double thickest = p.thickest, longest = p.longest;
  if (thickest > 0.0 && n > 1) {
    // Segments by their midpoints: a cell holds every segment a point's free surface can
    // reach from the next cell.
    spatial::Columns grid(thickest + longest);
    // Only the segments a pressed point looks at (its cell's 3 x 3 columns).
    const spatial::ColumnMask wanted(n, [&](std::size_t i) { return grid.cell_of(p.pos(i)); }, own);
    for (std::size_t piece = 0; piece < pieces.size(); ++piece) {
      const auto& points = pieces[piece].data_points;
      for (std::size_t k = 0; k + 1 < points.size(); ++k) {
        const glm::i64vec3 cell = grid.cell_of(0.5 * (points[k] + points[k + 1]));
        if (wanted.holds(cell)) grid.add(cell, static_cast<std::uint32_t>(p.first[piece] + k));
      }
    }
    grid.index();
    // By blocks of points, not by pieces: a garment is often one piece.
    constexpr std::size_t block = 4096;
    parallel_for((n + block - 1) / block, thread_count(threads), [&](std::size_t b) {
      for (std::size_t i = b * block; i < std::min(n, (b + 1) * block); ++i) {
        if (!own(i)) continue;
        const std::size_t from = p.first[p.piece[i]], to = p.first[p.piece[i] + 1];
        double deepest = 0.0;
        glm::dvec3 normal(0.0);
        const glm::dvec3& at = p.pos(i);
        // A segment whose midpoint lies farther than this reaches no free surface of i's
        // (most of the cells' candidates): passed over before the exact test.
        const double reach = p.free_r(i) + 0.5 * (thickest + longest), reach2 = reach * reach * (1.0 + 1e-6);
        grid.near(grid.cell_of(at), [&](const spatial::Columns::Entry& e) {
          const std::size_t j = e.item;
          const glm::dvec3& pj = p.pos(j);
          const glm::dvec3 off = at - 0.5 * (pj + (&pj)[1]);  // a segment's two points are one piece's
          if (glm::dot(off, off) > reach2) return;
          const double along_j = 0.5 * (p.along[j] + p.along[j + 1]);
          if (p.piece[j] == p.piece[i] && std::abs(along_j - p.along[i]) <= 1.8 * (p.free_r(i) + p.free_r(j))) return;
          const glm::dvec3 seg = (&pj)[1] - pj;
          const double len2 = glm::dot(seg, seg);
          const double t = len2 > 0.0 ? std::clamp(glm::dot(at - pj, seg) / len2, 0.0, 1.0) : 0.0;
          const glm::dvec3 away = at - (pj + t * seg);
          const double dist = glm::length(away);
          const double overlap = p.free_r(i) + p.free_r(j) - dist;
          if (overlap <= 0.0 || dist <= 0.0) return;
          // This yarn's share of the overlap, as its shell's share of the two shells.
          const double shells = p.shell(i) + p.shell(j);
          const double share = shells > 0.0 ? overlap * p.shell(i) / shells : 0.5 * overlap;
          if (share > deepest) {
            deepest = share;
            normal = away / dist;
          }
        });
        if (deepest <= 0.0) continue;
        const glm::dvec3 t = tangent(p, i, from, to);
        glm::dvec3 across = normal - glm::dot(normal, t) * t;
        const double l = glm::length(across);
        if (l < 1e-6) continue;
        const double minor = std::max(p.free_r(i) - deepest, p.free_r(i) - p.shell(i));
        const double aspect = std::max(flattest_aspect, (minor / p.free_r(i)) * (minor / p.free_r(i)));
        pressed(i) = (1.0 - aspect) * across / l;
      }
    });
  }
  // An ellipse is the same turned half a turn: each piece's directions turned to agree
  // with the last pressed one before it, then smoothed along the piece (twice by 1/4,
  // 1/2, 1/4, the ends repeated) and made across the yarn again.
  // A copy takes its first copy's direction as pressed (its first copy, before it, has
  // been turned already: `flipped` says whether), and is turned as its own would be; so
  // it ends as its first copy or that turned half a turn (turn: +1 or -1; 2 where both
  // are 0, either way; 0 at a point of its own).
  std::vector<std::int8_t> turn(same_as.empty() ? 0 : n, 0);
  std::vector<std::uint8_t> flipped(same_as.empty() ? 0 : n, 0);
  for (std::size_t piece = 0; piece < pieces.size(); ++piece) {
    glm::dvec3 last(0.0);
    auto& v = pieces[piece].pressed;
    for (std::size_t k = 0; k < v.size(); ++k) {
      const std::size_t i = p.first[piece] + k;
      glm::dvec3& d = v[k];
      const std::size_t f = own(i) ? i : same_as[i];
      if (f != i) d = flipped[f] ? -pressed(f) : pressed(f);
      bool flip = false;
      if (glm::dot(d, d) != 0.0) {
        flip = glm::dot(d, last) < 0.0;
        if (flip) d = -d;
        last = d;
      }
      if (same_as.empty()) continue;
      if (f == i) flipped[i] = flip ? 1 : 0;
      else turn[i] = glm::dot(d, d) == 0.0 ? 2 : flip == (flipped[f] != 0) ? 1 : -1;
    }
  }
  // The two passes by blocks: each block reads the directions as they were before the
  // passes (its own into a buffer, the two either side of it kept before the blocks
  // start, since its neighbours overwrite them), makes the first pass over its points
  // and one either side, then the second, and writes its own points. The same sums, in
  // the same order, as two passes over two whole arrays.
  constexpr std::size_t block = 16384, halo = 2;
  const std::size_t blocks = (n + block - 1) / block;
  std::vector<glm::dvec3> edges(blocks * 2 * halo);
  for (std::size_t b = 0; b < blocks; ++b)
    for (std::size_t h = 0; h < halo; ++h) {
      const std::size_t lo = b * block, hi = std::min(n, lo + block);
      if (lo >= halo - h) edges[(b * 2) * halo + h] = pressed(lo - (halo - h));
      if (hi + h < n) edges[(b * 2 + 1) * halo + h] = pressed(hi + h);
    }
  // A copy whose two neighbours either side are copies of its first copy's, all turned
  // alike, comes out of the passes as its first copy does, turned as they are: taken
  // from it after the passes (derived: that turn; 0 where made here). Most of a tiled
  // garment's points. Found rolling along the points (the window's last point k).
  std::vector<std::int8_t> derived(n, 0);
  auto derive = [&](std::size_t lo, std::size_t hi) {
    if (same_as.empty()) return;
    constexpr long none = LONG_MIN / 2;
    // run: how many points in a row follow the point before them as their first copies do;
    // last_plus, last_minus: the last point turned +1, -1 against its first copy.
    long run = 0, last_plus = none, last_minus = none;
    std::size_t piece = p.piece[lo >= 2 * halo ? lo - 2 * halo : 0];
    for (std::size_t k = lo >= 2 * halo ? lo - 2 * halo : 0; k < std::min(n, hi + halo); ++k) {
      while (k >= p.first[piece + 1]) ++piece;
      const bool follows = k > p.first[piece] && !own(k) && !own(k - 1) && same_as[k] == same_as[k - 1] + 1;
      run = follows ? run + 1 : 0;
      if (turn[k] == 1) last_plus = static_cast<long>(k);
      if (turn[k] == -1) last_minus = static_cast<long>(k);
      if (k < lo + halo) continue;
      const std::size_t i = k - halo;  // the window [i - 2, i + 2], all copies in one piece following each other
      if (run < static_cast<long>(2 * halo)) continue;
      const auto window = static_cast<long>(i - halo);
      if (last_plus >= window && last_minus >= window) continue;
      if (p.piece[same_as[i - halo]] != p.piece[same_as[k]]) continue;  // the first copies' window in one piece
      derived[i] = last_minus >= window ? -1 : 1;
    }
  };
  parallel_for(blocks, thread_count(threads), [&](std::size_t b) {
    const std::size_t lo = b * block, hi = std::min(n, lo + block);
    derive(lo, hi);
    // before[k - lo + halo]: the direction before the passes at k, for k in [lo - 2, hi + 2)
    // within the points; once[k - lo + 1]: the first pass at k, for k in [lo - 1, hi + 1).
    std::vector<glm::dvec3> before(hi - lo + 2 * halo), once(hi - lo + 2);
    for (std::size_t h = 0; h < halo; ++h) {
      before[h] = edges[(b * 2) * halo + h];
      before[hi - lo + halo + h] = edges[(b * 2 + 1) * halo + h];
    }
    for (std::size_t k = lo; k < hi; ++k) before[k - lo + halo] = pressed(k);
    auto at = [&](std::size_t k) -> const glm::dvec3& { return before[k + halo - lo]; };
    // A pass reads its neighbours in the piece, the ends repeated.
    const std::size_t first = lo > 0 ? lo - 1 : lo, last = std::min(n, hi + 1);
    std::size_t piece = p.piece[first];
    for (std::size_t k = first; k < last; ++k) {
      while (k >= p.first[piece + 1]) ++piece;
      const std::size_t from = p.first[piece], to = p.first[piece + 1];
      once[k + 1 - lo] = 0.25 * at(k > from ? k - 1 : k) + 0.5 * at(k) + 0.25 * at(k + 1 < to ? k + 1 : k);
    }
    piece = p.piece[lo];
    for (std::size_t i = lo; i < hi; ++i) {
      while (i >= p.first[piece + 1]) ++piece;
      const std::size_t from = p.first[piece], to = p.first[piece + 1];
      if (derived[i] != 0) continue;
      const glm::dvec3& a = once[(i > from ? i - 1 : i) + 1 - lo];
      const glm::dvec3& c = once[(i + 1 < to ? i + 1 : i) + 1 - lo];
      const glm::dvec3 twice = 0.25 * a + 0.5 * once[i + 1 - lo] + 0.25 * c;
      const glm::dvec3 t = tangent(p, i, from, to);
      const double amount = glm::length(twice);
      glm::dvec3 across = twice - glm::dot(twice, t) * t;
      const double l = glm::length(across);
      pressed(i) = amount > 1e-9 && l > 1e-9 ? amount * across / l : glm::dvec3(0.0);
    }
  });
  if (same_as.empty()) return;
  parallel_for(blocks, thread_count(threads), [&](std::size_t b) {
    for (std::size_t i = b * block; i < std::min(n, (b + 1) * block); ++i)
      if (derived[i] != 0) pressed(i) = static_cast<double>(derived[i]) * pressed(same_as[i]);
  });
}

}  // namespace knitc::relax

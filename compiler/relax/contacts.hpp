// Contacts between yarn segments, as capsules of the yarn's radius. Internal to relax/.
// (contacts_search.cpp finds the pairs; contacts.cpp pushes them apart.)
//
// The pairs of segments closer than their radii plus a margin are found with a grid
// and kept (a Verlet list) until some point has moved half the margin. Pushing them
// apart goes strip by strip across the courses: strips four apart share no point, so
// the strips of one of four classes are worked at once, and the result is the same for
// any number of threads.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "relax/chains.hpp"

namespace knitc::relax {

// How much a sweep's constraints would stretch the fabric, per axis (x, y): the sum of
// each correction's change of a pair's separation times that separation, and the sum of
// the separations squared. Their ratio is the mean strain asked for: > 0, wider.
struct Strain {
  glm::dvec2 stretch{0.0}, lever{0.0};
  void add(const glm::dvec3& change, const glm::dvec3& separation) {
    stretch += glm::dvec2(change) * glm::dvec2(separation);
    lever += glm::dvec2(separation) * glm::dvec2(separation);
  }
  void add(const Strain& o) {
    stretch += o.stretch;
    lever += o.lever;
  }
};

class Contacts {
 public:
  // period: the swatch's repeat in x and y, mm (0: not periodic that way). margin, mm.
  // round: the fabric is a tube (work in the round), whose crossings are not kept by side.
  // threads: how many to use, >= 1.
  Contacts(glm::dvec2 period, double margin, bool round, int threads);
  ~Contacts();

  // Finds every pair of contactable segments whose free surfaces are less than the margin
  // apart: of different pieces, or of one piece more than 1.8 free diameters apart along it
  // (a little inside the two of measure::deepest_penetration, so that every pair it counts
  // is kept apart). Where few points have moved, only their segments are searched again
  // (see refind in contacts_search.cpp): the pairs that can touch are the same.
  void find(const Chains& chains);
  // Whether a point has moved half the margin since find(), so a pair may be missing.
  bool stale(const Chains& chains) const;
  // One sweep: every pair whose cores overlap pushed to its core radii plus `skin` (a
  // fraction) apart, times `scale` (at most 1: a ramp); with `shells` > 0 (at most 1: how
  // far the shells have grown from the cores to the free radii), every pair closer than
  // its shells' surfaces pushed apart by their pressure (see relax.hpp). Returns the
  // deepest overlap of cores met (before its push, of the full radii), mm, 0 if none.
  double push_apart(Chains& chains, double skin, double scale, double shells, Strain* strain = nullptr);
  // The deepest overlap of the pairs' cores, mm, without moving anything.
  double deepest(const Chains& chains) const;
  // The mean squeeze of the pairs whose shells are pressed, 1 - h / h0 (h the shells'
  // thickness left between the cores, h0 the free one), 0 if none.
  double compression(const Chains& chains) const;
  // The whole fabric was moved by `move` (a change of size): so are the positions the
  // list was built at, and the period grows by `growth` (1 + fraction, per axis).
  void moved(const std::function<void(glm::dvec3&)>& move, glm::dvec2 growth);

  glm::dvec2 period() const { return period_; }
  // How many finds searched only the moved segments again (refind), and how many searched all.
  std::size_t refinds() const { return refinds_; }
  std::size_t full_finds() const { return full_finds_; }

 private:
  struct Pair {
    std::uint32_t a, b;    // segments
    std::int8_t sx, sy;    // b's image: shifted by (sx, sy) periods
    std::uint8_t held;     // bit k: point k of (a, a + 1, b, b + 1) does not move
    // Which passes in front where the two cross seen from the face: 1 a, -1 b; 0 not
    // known (they have not crossed while listed, or the fabric is a tube). Set the first
    // time they cross, and kept while the pair is listed, and on into the next list.
    std::int8_t side;
    float reach;           // mm, the sum of the two core radii
    float shell;           // mm, the sum of the two free radii
  };
  // In Pair::held: a pair of the full search's list whose segment has been searched
  // again since (refind): no longer worked, its successor is in extra_.
  static constexpr std::uint8_t dead = 16;
  // Pairs in (a, b, image) order: how a pair is looked up.
  static bool key_before(const Pair& x, const Pair& y) {
    return x.a != y.a ? x.a < y.a : x.b != y.b ? x.b < y.b : x.sx != y.sx ? x.sx < y.sx : x.sy < y.sy;
  }
  // The distance between the pair's centrelines, mm, negative when a has passed to the
  // wrong side of b; and the way to push a (away from b).
  double separation(const Chains& c, const Pair& p, glm::dvec3& push, double& s, double& t) const;
  bool crossing(const Chains& c, const Pair& p, double& s, double& t) const;
  std::int8_t neighbours_side(const Pair& p) const;  // the side of a listed pair a segment away, or 0
  std::int8_t side_of(const Chains& c, const Pair& p) const;
  glm::dvec3 shift(const Pair& p) const { return {p.sx * period_.x, p.sy * period_.y, 0.0}; }
  // find()'s passes: the segments in a grid of columns, the close pairs found in it
  // (one list per block of segments), the pairs filed by strips.
  struct Grid;
  Grid grid_of(const Chains& c) const;
  std::vector<std::vector<Pair>> close_pairs(const Chains& c, const Grid& grid, const std::vector<Pair>& previous) const;
  // Whether segments a and bs (b's image sx, sy on) make a pair to list within `margin`
  // (a < bs, each half length given), filling `pair`; known_side(pair): its side as last
  // listed, 0 if none.
  template <class KnownSide>
  bool pair_of(const Chains& c, std::size_t a, const glm::dvec3& ma, double half_a, std::size_t bs, double half_b,
               std::int8_t sx, std::int8_t sy, double margin, KnownSide&& known_side, Pair& pair) const;
  bool refind(const Chains& c);
  // refind searches again while the segments searched again since the full search are at
  // most this share of the points (or 256).
  static constexpr std::size_t refind_share = 64;
  const Pair* listed(const Pair& key) const;  // the live pair of that key, or null
  void file_by_strips(const Chains& c, const Grid& grid, const std::vector<std::vector<Pair>>& found);
  double gap(const Chains& c, const Pair& p) const;

  glm::dvec2 period_;
  double margin_;
  bool round_;
  int threads_;
  std::vector<Pair> pairs_;                        // strip by strip, then the ones across
  std::vector<std::size_t> strip_first_;           // pairs_[strip_first_[k] .. strip_first_[k + 1]) in strip k
  std::size_t across_first_ = 0;                   // pairs_[across_first_ ..) join distant strips: worked alone
  std::vector<glm::dvec3> built_at_;
  std::vector<std::uint32_t> by_segments_;  // pairs_ indices in (a, b, image) order
  // Since the last full search (refind):
  std::unique_ptr<Grid> grid_;                     // its grid, of the segments where they were then
  glm::dvec3 grid_scale_{1.0}, grid_offset_{0.0};  // where a point then is now: scale * p + offset (the size's moves)
  std::vector<std::uint8_t> wandered_;             // per segment: searched again (its place in grid_ is stale)
  std::vector<std::uint32_t> wanderers_;           // the same, listed
  std::vector<std::uint32_t> pairs_of_first_, pairs_of_;  // each segment's pairs_ (as a or b)
  std::vector<Pair> extra_;                        // the pairs found again, in (a, b, image) order: worked after the rest
  // find()'s scratch, kept from one full search to the next: a hat's lists are hundreds
  // of megabytes, and each mapped afresh was zero-filled by the kernel page by page
  // (docs/knitout.md, "Speed").
  std::vector<Pair> previous_;
  std::vector<std::uint32_t> strip_of_pair_;
  std::size_t refinds_ = 0, full_finds_ = 0;
};

// The closest points of segments p0p1 and q0q1: parameters s, t in [0, 1] (Ericson,
// Real-Time Collision Detection, 5.1.9).
void closest_points(const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& q0, const glm::dvec3& q1, double& s,
                    double& t);

}  // namespace knitc::relax

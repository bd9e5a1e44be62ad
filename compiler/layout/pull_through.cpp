// Each loop pulled through its parents: the others meeting their parents' heads halfway,
// a decrease's gathered with one head on top; a cable's crossed stitches leaning to their
// new needles, in front of or behind the stitches they cross.
#include "layout/passes.hpp"

#include "layout/courses.hpp"

#include <algorithm>
#include <cmath>

namespace knitc::layout {

namespace {
// A child's leg weights, the other way round from a parent's head (head_weights), also 0
// at P0 and P16 so that loops of a course keep sharing their end points.
constexpr std::array<double, loop_points> legs = {0.0, 0.6, 0.9, 0.8, 0.6, 0.4, 0.2, 0.05, 0.0,
                                                  0.05, 0.2, 0.4, 0.6, 0.8, 0.9, 0.6, 0.0};
// A crossed stitch leans from where it was knitted to the needle it was moved to: its
// feet keep their places in its course, its head (P7..P9, as a whole) moves to the loop
// knitted through it, its legs in between.
constexpr std::array<double, loop_points> to_new_needle = {0.0, 0.0, 0.0, 0.1, 0.25, 0.45, 0.7, 1.0, 1.0,
                                                           1.0, 0.7, 0.45, 0.25, 0.1, 0.0, 0.0, 0.0};
// Where crossed stitches' legs pass in front of or behind each other: most at mid-leg,
// none at the feet, which the stitch shares with its neighbours in the course.
constexpr std::array<double, loop_points> crossing = {0.0, 0.5, 0.8, 1.0, 1.0, 0.8, 0.5, 0.2, 0.0,
                                                      0.2, 0.5, 0.8, 1.0, 1.0, 0.8, 0.5, 0.0};
// How far in front of the fabric's middle a stitch crossing in front passes at mid-leg,
// and one crossing behind behind it, in its yarn's diameters.
constexpr double crossed_depth = 0.6;

// A decrease's heads under the top one lie this far (of d) lower at the head: enough that
// the heads are not on one line seen from the face (tests/lace_test.cpp); at 0.2 more
// yarns passed through in eyelet_lace (8, none at 0.05).
constexpr double gathered_drop = 0.05;

// A loop pulled along its course further than a loop width (a stitch a program's
// transfers moved needles away from the loop knitted through it) shears until its two
// legs cross, 0.2 mm apart at one depth in CMU's hyperbolic plane, where which is in
// front was undecided: 12 crossings flipped relaxed. Its legs pass this much (of d)
// in front and behind at mid-leg, a yarn's diameter apart.
constexpr double sheared_legs = 0.5;

// Of a gathered stitch's parents, the one lying on top: k2tog's left stitch (it leans
// right), ssk's and sk2p's right one (they lean left), the centre of a cdd.
std::size_t top_parent(const StitchDef& s, std::size_t parents) {
  switch (s.lean) {
    case Lean::left: return parents - 1;
    case Lean::centre: return parents / 2;
    default: return 0;
  }
}

}  // namespace

// Each loop pulled through its parents. Other loops meet their parents halfway: the
// parents' heads and the loop's legs, so that decreases gather with one parent on top. A
// cable's loop is knitted upright at its needle through its parent, the crossed stitch,
// which leans there from where it was knitted, in front of or behind the stitches it
// crosses. A parent whose child is more than one course up (slipped, tucked) is stretched
// up to it.
void pull_through(Layout& out, const Pattern& pattern, const std::vector<std::vector<int>>& parents) {
  const double W = out.loop_width, C = out.course_spacing;
  const std::vector<char> bobbled = in_bobbles(out);
  auto rise = [&](const Loop& child, const Loop& parent) {  // how far above a course up the child stands
    return !out.column_y.empty() ? foot_y(out, child.course, child.wale) - foot_y(out, parent.course, parent.wale) - C
           : out.heights.empty()  ? (child.course - parent.course - 1) * C
                                  : out.heights[child.course] - out.heights[parent.course] - C;
  };
  for (std::size_t i = 0; i < out.loops.size(); ++i) {
    if (parents[i].empty() || bobbled[i]) continue;
    Loop& child = out.loops[i];
    const StitchDef& s = stitch(child.stitch);
    const double d = pattern.yarns[child.yarn].diameter;
    const double cx = centre_x(out, child.course, child.wale);
    if (s.family == StitchFamily::cable) {
      // In F cables the stitches moving left cross in front, in B those moving right; a
      // three-part cross's middle stays where it is. The crossing is in the moved
      // stitches, as on the needles: the new loops are knitted in needle order, and their
      // yarn runs along the course as a plain row's does. (Until 2026-12-07 the new loop
      // leaned instead, its feet in the moved stitch's head: its yarn ran back behind the
      // block from the last crossed foot to the first, on one line with the block's other
      // floats and feet, where which crossed which was undecided.)
      Loop& parent = out.loops[parents[i].front()];
      const double lean = centre_x(out, parent.course, parent.wale) - cx;  // mm, the parent's centre less its child's
      const bool travels = std::abs(lean) >= 0.25 * W;
      const bool in_front = s.cable.front ? lean > 0.0 : lean < 0.0;
      const double dz = travels ? (in_front ? crossed_depth : -crossed_depth) * d : 0.0;
      const glm::dvec3 head(-lean, rise(child, parent), 0.0);
      for (int j = 0; j < loop_points; ++j)
        parent.data_points[j] += to_new_needle[j] * head + glm::dvec3(0.0, 0.0, crossing[j] * dz);
      continue;
    }
    double mean = 0.0;
    for (int p : parents[i]) mean += centre_x(out, out.loops[p].course, out.loops[p].wale);
    mean /= static_cast<double>(parents[i].size());
    // The legs move at most 0.4 W (of their own width), or their sinker loops would double back on the
    // neighbours' (P15 lies 0.25 W inside P16); the parents' heads take the rest.
    const double reach = 0.4 * width_of(out, child);
    const double meet = cx + std::clamp(0.5 * (mean - cx), -reach, reach);
    for (std::size_t k = 0; k < parents[i].size(); ++k) {
      Loop& parent = out.loops[parents[i][k]];
      const double px = centre_x(out, parent.course, parent.wale);
      // A decrease's top head in front, the others behind it and a little lower (as a
      // tuck's is), or two gathered to one x lie on one line seen from the face, where
      // which crosses which is undecided.
      const bool gathered = s.family == StitchFamily::decrease && parents[i].size() > 1;
      const bool under = gathered && k != top_parent(s, parents[i].size());
      double dz = gathered ? (under ? -0.5 : 0.5) * d : 0.0;
      const double dy = under ? -gathered_drop * d : 0.0;
      // Three or more gathered (a double decrease, a nupp's five): the heads only halfway
      // to the meet, and the ones below the top alternating in depth, or they would lie on
      // one line (a k3tog's two lower heads on each other, parted either way by the
      // relaxation: 16 yarns through another in horseshoe lace, tests/lace_test.cpp).
      const bool many = gathered && parents[i].size() > 2;
      if (many && under) dz = (k % 2 ? -0.5 : -1.1) * d;
      const glm::dvec3 shift(many ? 0.5 * (meet - px) : meet - px, rise(child, parent) + dy, dz);
      // Pulled further than a loop width: the leg on the side it goes to in front (sheared_legs).
      const double sheared = std::abs(meet - px) > W ? sheared_legs * d * (meet > px ? 1.0 : -1.0) : 0.0;
      for (int j = 0; j < loop_points; ++j) {
        const double leg = j < loop_points / 2 ? -sheared : j > loop_points / 2 ? sheared : 0.0;  // P0.. the left leg
        parent.data_points[j] += head_weights[j] * shift + glm::dvec3(0.0, 0.0, leg * crossing[j]);
      }
    }
    for (int j = 0; j < loop_points; ++j) child.data_points[j].x += legs[j] * (meet - cx);
  }
}

}  // namespace knitc::layout

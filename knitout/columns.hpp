// Knitout in: the needle columns across the two beds, where a course's live stitches lie
// (courses.cpp says the stitches). Internal to knitout/.
#pragma once

#include <algorithm>
#include <vector>

#include "cut.hpp"
#include "pattern.hpp"

namespace knitc::knitout {

// The needle column a position lies in, across the beds: a back needle at a fractional
// racking (a quarter or half a pitch, for knitting both beds at once) lies in the column
// of the front needle it nearly faces.
long column_of(const Position& q);

// The gauge's spacing, in needle pitches: the gap most often seen between the needles a
// course holds loops on. Flat work's across both beds, whose loops lie in one sheet (a
// rib on alternate needles of each bed is full gauge); a tube's on the front bed, its
// layer's. 1 where no course holds two loops within three needles.
long spacing_of(const std::vector<RawCourse>& courses, bool round);

// Each live stitch's needle position's width, in loop widths: the cast-on's and each
// course's after it (Course::widths), flat work's courses with their positions sorted
// along the beds, `worked[c][j]` where course c made a loop at position j; and, for two
// layers, each position's layer (Course::layers). Where courses hold both beds' loops in
// a needle column:
// - they knit both (at least nine times in ten: a full-needle rib, a Milano rib, a rib
//   on every needle), or exactly one of them (as often: an interlock, whose beds take
//   turns): the column's width shared by its loops, side by side;
// - the two mix (a spacer fabric, a double jacquard, half-Milano): two layers, the back
//   bed's loop of each column behind the front's, each at the column's whole width; or,
//   where one yarn knits the two one after the other (a rib's stitches), side by side,
//   half each. Sharing a column at one depth put these over each other, and more yarns
//   passed through (docs/knitout.md).
// All empty where no course holds both beds' loops in a column. A course's vectors are
// empty where every width is one and there is one layer.
struct ColumnWidths {
  std::vector<double> cast_on;
  std::vector<signed char> cast_on_layers;
  std::vector<std::vector<double>> courses;  // courses[c - 1]: after RawCourse c
  std::vector<std::vector<signed char>> layers;
  bool in_turn = false;  // the beds knit in turn (an interlock): each bed's loops span two courses
  bool layered() const { return !cast_on_layers.empty() || std::any_of(layers.begin(), layers.end(), [](const auto& l) { return !l.empty(); }); }
};
ColumnWidths column_widths(const std::vector<RawCourse>& courses, const std::vector<std::vector<char>>& worked,
                           const std::vector<Loop>& loops, int spacing);

// How far each course lies above the one before, in course spacings (Course::rise), for
// two layers: each bed's knitted loops ask to lie a course above the loops they were
// pulled through, and the bed asking less sets the height, so that the layer knitted
// less often (a double jacquard's face, once for its two colours' passes) keeps whole
// courses and the other's loops are shorter (its back, knitted in each). At least half
// a course, a quarter where the course knits no loop through another (a spacer's tucks).
// `rises[c - 1]` for RawCourse c; `course_of` per loop.
std::vector<double> layer_rises(const std::vector<Loop>& loops, const std::vector<int>& course_of,
                                const std::vector<RawCourse>& courses);

// A loop made in the needle column of the stitch worked just before it (a split
// bind-off's loop, over the stitch bound off, or the chain's last loop) shares the column,
// half of it each: the course's widths set per column (Course::widths: its live stitches
// and those it bound off), where the needles set none. `shared`: the ops (indexes, in
// order) of such loops, each after the op it shares with.
void share_columns(Course& course, const std::vector<std::size_t>& shared);

}  // namespace knitc::knitout

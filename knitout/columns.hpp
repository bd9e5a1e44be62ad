// Knitout in: the needle columns across the two beds, where a course's live stitches lie
// (courses.cpp says the stitches). Internal to knitout/.
#pragma once

#include <vector>

#include "cut.hpp"

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
// along the beds, `worked[c][j]` where course c made a loop at position j. Set only where
// a course holding both beds' loops in a needle column knits both (at least nine times
// in ten: a full-needle rib, a Milano rib, a rib on every needle), or knits exactly one
// of them (as often: an interlock, whose beds take turns); else all empty. Where the two
// mix (spacer fabrics, double-bed jacquard, half-Milano), the two layers are drawn side
// by side a whole position each: sharing their columns put them over each other at one
// depth, and more yarns passed through (docs/knitout.md). A course's vector is empty
// where every width is one.
struct ColumnWidths {
  std::vector<double> cast_on;
  std::vector<std::vector<double>> courses;  // courses[c - 1]: after RawCourse c
};
ColumnWidths column_widths(const std::vector<RawCourse>& courses, const std::vector<std::vector<char>>& worked, int spacing);

}  // namespace knitc::knitout

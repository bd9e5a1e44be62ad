// Knitout in, its first half: the machine run over the program and what it knitted cut
// into courses (courses.cpp says each course as stitches). Internal to knitout/.
#pragma once

#include <string>
#include <vector>

#include "machine.hpp"
#include "program.hpp"

namespace knitc::knitout {

struct Position {
  Needle needle;
  double x = 0.0;          // across the beds, in needle pitches
  std::vector<int> pile;   // loops, bottom to top
};

struct Crossing {  // a carrier at a needle
  int carrier;
  double x;
  int direction;
  bool front;
};

// Where a carrier went in one direction without turning: the span it passed, and the
// beds it stitched or missed on. A course keeps these, not every stitch, so a program of
// a million misses costs a million steps.
struct Run {
  int carrier;
  int direction;
  double low, high;
  bool front = false, back = false;
  bool on(bool side) const { return side ? front : back; }
  bool passes(double x) const { return low < x - 1e-6 && high > x + 1e-6; }
};

// Adds where a carrier went to a course's runs: the carrier's last run grows, or a new
// one starts where it turned.
inline void add(std::vector<Run>& runs, const Crossing& c) {
  for (auto r = runs.rbegin(); r != runs.rend(); ++r) {
    if (r->carrier != c.carrier) continue;
    if (r->direction == c.direction) {
      r->low = std::min(r->low, c.x);
      r->high = std::max(r->high, c.x);
      (c.front ? r->front : r->back) = true;
      return;
    }
    break;
  }
  Run r{c.carrier, c.direction, c.x, c.x};
  (c.front ? r.front : r.back) = true;
  runs.push_back(r);
}

struct RawCourse {
  int first_operation = 0;
  double racking = 0.0;
  std::vector<int> made;             // loops made, in order
  std::vector<Run> went;             // where its carriers went
  std::vector<Position> positions;   // at its end, unordered
};

// Across the beds, in needle pitches: at racking R back needle n lies at n + R, just
// right of the front needle it faces.
inline double across(Needle n, double racking) { return front(n.bed) ? n.index : n.index + racking + 1e-3; }


// What the machine knitted, in courses: a course ends where a needle would be worked
// twice, where a carrier turns back onto loops along the bed it came, or where it reaches
// a stitch it already passed; a bind-off's steps are one course, and so are a tube's two
// passes when transfers between them cut it in two (each a layer, the second not
// knitted through the first). In flat work a pass along one bed and back along the
// other (a Milano rib's) is two courses.
struct Cut {
  std::vector<RawCourse> courses;
  std::vector<int> course_of;  // per loop: its course
  bool round = false;          // knitted as a tube
  // Per loop: whether it is of the tube's front layer, were the fabric a tube (its wale's:
  // the top loop it was pulled through, else the bed it was made on).
  std::vector<char> front_layer;
  int last_drop_line = 0;      // the last drop after the last course
  long long front_loops = 0, back_loops = 0;
  std::vector<std::string> warnings;
};

// Runs every operation on `machine` (fresh, for `program`). Throws KnitoutError for what
// the machine refuses, and for a program that makes no loops.
Cut cut_courses(const Program& program, Machine& machine);

}  // namespace knitc::knitout

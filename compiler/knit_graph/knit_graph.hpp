// The knit graph: every loop of the fabric, the loops it is pulled through (its
// parents), its yarn and its place along that yarn. Plain data from the Pattern; the
// layout places these loops in space.
//
// The needle holds live stitches; a live stitch is the loops held together on one needle
// (one, or more when tucks stack on it). Working a course, each op takes its stitches'
// worth of live stitches in face order:
//   knit, purl, decreases, cables  a new loop through all the loops they take; worked under
//                                  the floats (k under float), it takes them too: the loose
//                                  floats over its stitch from the rows below, on its side;
//   yarn over                      a new loop with no parent;
//   tuck                           a new loop held on the needle with the old ones;
//   slip                           no new loop: the old stitch moves across, the yarn floats;
//   drop                           no new loop: the old stitch is let off the needle and its
//                                  wale unravels down to the yarn over (or cast-on) it grew
//                                  from, each loop of it left as a straight rung;
//   wrap                           a new loop through each stitch, then the yarn wound round them;
//   bind off (bo)                  a new loop through it, off the needle: bound, a column of its own;
//   bobble (MB)                    n loops through it, rows of n worked back and forth over
//                                  them (each through the one below), and one loop through
//                                  the last n: the stitch it leaves;
//   no stitch                      nothing.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "pattern.hpp"

namespace knitc::knit_graph {

// A course the graph cannot work as written: `course` is its number (pattern course i is
// i + 1), what() says why and what to do, without a location (the caller has the rows').
class RowError : public std::invalid_argument {
 public:
  RowError(int row, const std::string& what) : std::invalid_argument(what), course(row) {}
  int course;
};

struct Loop {
  int course = 0;         // 0 is the cast-on; pattern course i is course i + 1
  int position = 0;       // left to right in face view among the loops its course makes
  // Its column in its course, left to right in face view: the needle position it is on
  // after its course, counting the stitches the course binds off (they stand where they
  // were knitted) among them.
  int slot = 0;
  StitchId stitch = 0;    // the op that made it (the cast-on's loops say k)
  int yarn = 0;           // index into Pattern::yarns
  int order = 0;          // place along its yarn, in working order, from 0
  std::vector<int> parents;  // loops it is pulled through, in face order: indices into Graph::loops
  bool held = false;         // a tuck loop: caught on the needle, knitted off with the next loop
  bool unravelled = false;   // let off by a drop: no parents, no children, a rung across its wale
  bool bound = false;        // bound off within its course: passed over the next, off the needle
  // Plating: the second yarn's loop of a stitch knitted with two (Op::plated), made just
  // after the first yarn's, through the same parents, in the same column; both are the
  // stitch the next course pulls its loop through.
  bool plating = false;
};

// A stretch of yarn that passes stitches by without making a loop: a slipped stitch's
// float, over the needle positions [first, last] (face view) after its course.
struct Float {
  int course = 0;
  int first = 0, last = 0;
  int yarn = 0;
  bool in_front = false;  // on the face side (slip wyif), else behind
  int caught_by = -1;     // the loop worked under it that lifts it (quilting), or -1: index into Graph::loops
};

// Yarn wound round a group of stitches after they are worked (wrap 3): the loops
// [first, last] (indices into Graph::loops, face order) of one course, `turns` times.
struct Wrap {
  int course = 0;
  int first = 0, last = 0;
  int yarn = 0;
  int turns = 0;
};

// A bobble worked in one stitch of a course: `rows` rows of `loops` loops, indices
// first + row * loops + lane (rows from 0, the row that made them; lanes left to right in
// face view), then the loop that gathers the last row, first + rows * loops, which stays
// on the needle. Row 0 is worked in its course's direction, each next row turned back.
struct Bobble {
  int course = 0;
  int first = 0;
  int loops = 0, rows = 0;
  int gathered() const { return first + rows * loops; }
};

// How many rows below a float can still be caught: a strand slipped further down is no
// longer loose enough to lift (real patterns catch them 2 to 8 rows up).
inline constexpr int float_reach = 10;

// A column of a course (a needle position after it, as Loop::slot numbers them): the
// columns of the course below its stitch stands on, [below, below + across), none for a
// new stitch (a yarn over); whether the course's yarn reached it (a `held` stitch is not:
// a short row turned before it); and whether the course pulled a loop through it (not
// where it slipped the stitch or tucked on it).
struct Column {
  int below = -1;
  int across = 0;
  bool reached = true;
  bool pulled = true;
};

struct Graph {
  std::vector<Loop> loops;        // the cast-on's, then course by course in face order
  std::vector<int> course_first;  // index of each course's first loop; one more entry at the end
  std::vector<Float> floats;      // course by course
  std::vector<Wrap> wraps;        // course by course
  std::vector<Bobble> bobbles;    // course by course
  std::vector<int> needle;        // live stitches after each course (the cast-on's first)
  std::vector<int> columns;       // each course's columns: its live stitches and those it bound off
  // Per course, each of its columns (the cast-on's empty): what it stands on.
  std::vector<std::vector<Column>> stands_on;
  // After the last course: the live stitches, each the loops its needle holds, and the
  // column each is in.
  std::vector<std::vector<int>> live;
  std::vector<int> live_columns;
};

// Builds the graph. The runtime checks stitch counts as the script runs; the graph checks
// them again, so the language and the compiler cannot disagree: a course that does not
// work exactly the live stitches throws RowError naming the row. So does a drop whose
// wale cannot unravel as one (through a decrease, an increase or a held tuck).
Graph build(const Pattern& pattern);

}  // namespace knitc::knit_graph

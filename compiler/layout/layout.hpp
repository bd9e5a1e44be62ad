// Layout: a loop instance for every loop of the knit graph, placed on the fabric by a
// template per stitch derived from the plain loop of the seed paper.
//
// Millimetres. Loops are laid out in course-local flat coordinates: +X along a course
// (needle position grows, face view), +Y up the wales (course index grows), +Z out of the
// technical face. Flat knitting stays flat; knitting in the round is wrapped onto a tube
// by to_fabric(), the face outside, each course rising one course spacing as it goes
// round so that the yarn spirals.
#pragma once

#include <array>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "knit_graph/knit_graph.hpp"
#include "pattern.hpp"

namespace knitc::layout {

// The plain loop of the seed paper (Table 1): 17 data points from one sinker loop (P0)
// up a leg, over the needle loop (P8) and down to the next sinker loop (P16), as
// fractions of loop width W (x), loop height H (y) and thickness T (z).
inline constexpr int loop_points = 17;
std::span<const glm::dvec3, loop_points> plain_loop_fractions();

// The plain loop's data points in mm for a gauge, with P0 at the origin.
std::array<glm::dvec3, loop_points> plain_loop(const Gauge& gauge);

// How a loop is drawn, chosen from its stitch (and, for cables, its place in the cross).
enum class Template : std::uint8_t {
  knit,      // the plain loop: pulled through from the back, a V on the face
  purl,      // the plain loop seen from the back: z mirrored, a bump on the face
  tuck,      // held, not knitted: lies behind the old loop, caught by the loop above
  bind_off,  // a low loop lying over toward the next one along the top edge
  rung,      // unravelled by a drop: the yarn lies straight across its wale, a ladder's rung
};

struct Loop {
  int course = 0;  // 0 is the cast-on; pattern course i is course i + 1; a bind-off is one more
  int wale = 0;    // needle position after its course (or column it was bound off in), left to right in face view
  StitchId stitch = 0;
  int yarn = 0;    // index into Pattern::yarns
  int order = 0;   // place along its yarn, in working order
  Template shape = Template::knit;
  // Worked against its course's direction: a bobble's turned rows.
  bool against = false;
  // The second yarn of a plated stitch (knit_graph::Loop::plating), drawn on the first's
  // technical face.
  bool plating = false;
  // mm, course-local flat coordinates, P0 at the left (face view) whichever way it is worked
  std::array<glm::dvec3, loop_points> data_points;
};

struct Layout {
  int courses = 0;  // including the cast-on (and the bind-off when there is one)
  int wales = 0;    // the widest course's needle positions
  Knitting knitting = Knitting::flat;
  double loop_width = 0.0, course_spacing = 0.0;
  std::vector<Loop> loops;        // course by course, left to right within a course
  std::vector<int> needle;        // needle positions per course, and the columns of stitches it bound off
  std::vector<double> origin_x;   // x of needle position 0 per course (flat work: its plain loops over their parents)
  // Per course: the x of each needle position's left edge, and of the last one's right
  // edge (needle + 1 values from origin_x). A position is one loop width, a cluster's
  // loops (the nupp's) narrower, and so are the two beds' loops of a needle column in a
  // machine's full-needle knitting (Course::widths).
  std::vector<std::vector<double>> slot_x;
  // Per course: 1 where a machine's needles set its positions' widths (Course::widths),
  // so that every loop there takes its position's width.
  std::vector<char> needle_widths;
  // Per course where a machine knitted two layers (Course::layers): each position's
  // layer, +1 in front, -1 behind, a position 0 wide lying over the one before it; else
  // empty. And the y of each course, mm, where its layer's courses are fewer than the
  // fabric's (Course::rise); empty where each lies a course spacing above the one before.
  std::vector<std::vector<signed char>> layers;
  std::vector<double> heights;
  // Per course where short rows turn (a course leaving stitches unreached, `held`:
  // knit_graph::Column::reached): the y of each needle position's loops' feet, mm. A
  // column rises a course, over the highest column it stands on, where its course pulls
  // a loop through it, and keeps its height where the course does not reach it (the
  // exceptions, a whole row among them: docs/stitches.md, "Placement"); a yarn over
  // stands beside its neighbour. Empty for every other fabric, for one whose loops all
  // lie at their courses' heights after all, and for one laid by its layers' heights.
  std::vector<std::vector<double>> column_y;
  // How far in front of the fabric's middle the front layer's loops lie, and the back
  // layer's behind it, mm.
  double layer_depth = 0.0;
  std::vector<int> direction;     // per course: -1 worked right to left (face view), +1 left to right
  std::vector<knit_graph::Float> floats;  // slipped stitches' floats, course by course
  // Per float: the points (course-local, left to right) a caught float is lifted through,
  // under the legs of the loop that catches it and over its parent's head; empty if loose.
  std::vector<std::vector<glm::dvec3>> float_lifts;
  std::vector<knit_graph::Wrap> wraps;  // yarn wound round groups of loops, course by course
  std::vector<knit_graph::Bobble> bobbles;  // bobbles, course by course: their rows stand out of the face on a ring
  // The z of yarn floating behind and in front of the fabric: clear of the loops' legs.
  double float_behind = 0.0, float_in_front = 0.0;
};

// Lays out every loop of the pattern's knit graph, and a bind-off course when the
// pattern binds off. Throws std::invalid_argument (from the graph) on a course that does
// not work the needle's live stitches.
Layout lay_out(const Pattern& pattern);
Layout lay_out(const Pattern& pattern, const knit_graph::Graph& graph);

// The way loop `index` is worked, face view: -1 right to left, +1 left to right.
int way(const Layout& layout, std::size_t index);

// Per loop: 1 for a bobble's loops (its rows and the loop that gathers them), else 0.
std::vector<char> in_bobbles(const Layout& layout);

// The y of a course's loops' feet, mm: `course` course spacings up, or its layer's
// height (Layout::heights).
double course_y(const Layout& layout, int course);

// The y of the feet of a course's loops at needle position `slot`, mm: course_y, or its
// column's height where short rows turn (Layout::column_y).
double foot_y(const Layout& layout, int course, int slot);

// How tall the fabric is laid, mm: `courses` course spacings, or its tallest column's
// top where short rows turn.
double laid_height(const Layout& layout);

// Whether a course's loops lie in two layers (Layout::layers).
bool layered(const Layout& layout, int course);

// Needle position `slot` of a course, mm: from its left edge to its right, a layer's
// position over the one before it spanning that one's.
struct Span {
  double left = 0.0, right = 0.0;
};
Span span_of(const Layout& layout, int course, int slot);

// The width of a course, mm: from its first needle position's left edge to its last's right.
double course_width(const Layout& layout, int course);

// A course-local point in fabric coordinates: the same point for flat work, wrapped onto
// the tube (circumference: the course's width) for work in the round.
glm::dvec3 to_fabric(const Layout& layout, const glm::dvec3& local, int course);

// The tube's wrapping itself (to_fabric's for work in the round): `local` rolled onto a
// tube of `circumference` (mm, > 0) whose courses climb `climb` (mm) a round. Unrolled,
// the fabric point's local point whose x is the nearest to `near_x` of those a round
// apart (each rolls back onto it: roll(unroll(p, c, h, x), c, h) == p for any x).
glm::dvec3 roll(const glm::dvec3& local, double circumference, double climb);
glm::dvec3 unroll(const glm::dvec3& fabric, double circumference, double climb, double near_x);

}  // namespace knitc::layout

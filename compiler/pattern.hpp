// The Pattern: what a pattern script means, as plain data. The runtime builds it from
// Lua; the compiler reads it and knows nothing of Lua.
#pragma once

#include <string>
#include <vector>

#include "stitches/stitches.hpp"
#include "yarn/colour.hpp"
#include "yarn/fibres.hpp"
#include "yarn/size.hpp"

namespace knitc {

// Where a thing was said in a pattern script, for error messages: "file:line".
struct SourceLocation {
  std::string file;
  int line = 0;
};

// Fabric dimensions in millimetres, as in the seed paper: loop width W, loop height H,
// fabric thickness T. Course spacing C = 0.86 H.
struct Gauge {
  double loop_width = 4.0;
  double loop_height = 4.2;
  double thickness = 2.0;
  static constexpr double course_spacing_ratio = 0.86;  // C / H, the seed paper's value
  double course_spacing() const { return course_spacing_ratio * loop_height; }
  bool operator==(const Gauge&) const = default;
};

// How a yarn's cross-section is drawn.
enum class Section {
  circle,   // a round yarn of the yarn's diameter
  ellipse,  // a flattened yarn: the same area, minor/major = aspect, flat against the fabric
  plied,    // `plies` round plies twisted about the centreline, the bundle as wide as the yarn
};

struct Yarn {
  std::string id;         // the name the script gives it, e.g. "A"
  double diameter = 1.0;  // mm: the free diameter, at which the tube is drawn
  std::string color;      // CSS hex, "#rrggbb"
  double grams_per_metre = 1.0 / 2.3;  // its weight per length: grams used (a DK's 230 m per 100 g)
  Section section = Section::circle;
  double aspect = 1.0;    // ellipse: minor / major, in (0, 1]
  int plies = 1;          // plied: 2 to 6
  double twist = 0.0;     // plied: turns per 10 cm
  bool z_twist = false;   // plied: Z twist (plies slant like the middle of a Z), else S
  double core_diameter = 1.0 / yarn::free_per_core;  // mm: the compact core, < diameter
  // Dyed along its length (else empty: `color` throughout): runs repeated end to end, the
  // ball starting `colour_start` mm into them (yarn/colour.hpp).
  std::vector<yarn::ColourRun> colours{};
  double colour_start = 0.0;
  // Heathered (else empty): fibres of these colours in these shares, blended.
  std::vector<yarn::FibreColour> heather{};
  // Its fibres, drawn by --section fibres: the fibre's preset, fields overriding it.
  yarn::FibreModel fibres{};
  bool operator==(const Yarn&) const = default;
};

// One stitch of a course, as it shows on the face.
struct Op {
  StitchId stitch = 0;
  int yarn = 0;  // index into Pattern::yarns
  // Plating: a second yarn knitted into the same loops with it, lying on their technical
  // face (a machine's stitch made with two carriers), or -1. Index into Pattern::yarns.
  int plated = -1;
  bool operator==(const Op&) const = default;
};

enum class Side { right, wrong };  // the side facing the knitter while the row is worked

// One course in face view, left to right: ops[0] is at the left edge seen from the face.
// Each op works stitch(op).consumes live stitches of the course below, in order, and
// leaves stitch(op).produces loops.
struct Course {
  std::vector<Op> ops;
  Side side = Side::right;  // wrong-side rows are worked left to right, seen from the back
  SourceLocation where;     // not part of the fabric: equality ignores it
  // Per column after the course (its live stitches and those it bound off, in order), the
  // width of its needle position in loop widths, where a machine's needles set it
  // (knitout/: a full-needle rib's two beds' loops share one position's width, a split
  // bind-off's loop the column of the stitch it bound off); empty where each is one loop
  // width.
  std::vector<double> widths;
  // Per live stitch after the course, where a machine knits two layers over each other
  // (a spacer fabric, a double jacquard): +1 a front-bed loop, drawn in front, -1 a
  // back-bed loop, behind, each at its needle column's whole width (a position 0 wide
  // lies over the one before it, in its column); empty for one layer.
  std::vector<signed char> layers;
  // How far the course lies above the one before, in course spacings: less than one
  // where its loops were pulled through loops of courses further down, a layer's courses
  // being fewer than the fabric's (knitout/: a spacer's tucks between its layers'
  // courses, a double jacquard's colours' passes).
  double rise = 1.0;
  bool operator==(const Course& o) const {
    return ops == o.ops && side == o.side && widths == o.widths && layers == o.layers && rise == o.rise;
  }
};

enum class Knitting { round, flat };

struct Pattern {
  std::string name;
  Gauge gauge;
  std::vector<Yarn> yarns;  // sorted by id, so no script table order leaks out
  Knitting knitting = Knitting::round;
  int cast_on = 0;          // live stitches before the first course
  int cast_on_yarn = 0;
  std::vector<double> cast_on_widths;  // the cast-on's, as Course::widths
  std::vector<signed char> cast_on_layers;  // and as Course::layers
  std::vector<Course> courses;
  bool bound_off = false;   // the last course's loops are bound off
  bool operator==(const Pattern&) const = default;
};

// What knitc takes, declared once. The runtime refuses a script past the first two; the
// compiler refuses to lay out a fabric past the third or mesh one past the fourth (knitc
// check and chart take what the runtime does).
namespace limits {
inline constexpr long long stitches_on_needle = 100'000;   // after any course
inline constexpr long long script_loops = 20'000'000;      // in a pattern a script makes
inline constexpr long long fabric_loops = 2'000'000;       // in a fabric the compiler lays out
inline constexpr long long mesh_vertices = 80'000'000;     // in its mesh: about 14 GB at peak on the way to the file
}  // namespace limits

// Live stitches after the course: the loops it leaves on the needle.
int produced(const Course& course);
// The loops of the whole fabric: the cast-on's and every course's. The one count the
// limits are checked against.
long long loops_of(const Pattern& pattern);
// Live stitches the course works.
int consumed(const Course& course);

}  // namespace knitc

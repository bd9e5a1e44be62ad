// The Pattern: what a pattern script means, as plain data. The runtime builds it from
// Lua; the compiler reads it and knows nothing of Lua.
#pragma once

#include <string>
#include <vector>

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
};

struct Yarn {
  std::string id;        // the name the script gives it, e.g. "A"
  double diameter = 1.0; // mm
  std::string color;     // CSS hex, "#rrggbb"
};

enum class Stitch { knit };

// One course, in face view, left to right: stitches[i] is worked on wale i.
struct Course {
  std::vector<Stitch> stitches;
  int yarn = 0;  // index into Pattern::yarns
  SourceLocation where;
};

enum class Knitting { round, flat };

struct Pattern {
  std::string name;
  Gauge gauge;
  std::vector<Yarn> yarns;  // sorted by id, so no script table order leaks out
  Knitting knitting = Knitting::round;
  int cast_on = 0;          // live stitches before the first course
  std::vector<Course> courses;
};

}  // namespace knitc

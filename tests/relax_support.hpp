// What the relaxation's tests share (relax_test.cpp, repeat_test.cpp): library patterns at
// the seed paper's gauge, the yarns' sizes, and a jersey swatch relaxed within a boundary.
#pragma once

#include <regex>
#include <string>
#include <vector>

#include "layout/layout.hpp"
#include "relax/relax.hpp"
#include "support.hpp"
#include "yarn/size.hpp"
#include "yarn_paths/yarn_paths.hpp"

namespace knitc::test {

// A library pattern knitted at the seed paper's proportions, loop width 4, loop height
// 4.2, thickness 2 mm, in yarn 1 mm thick: a loop some 16 diameters long, which round
// yarn that does not squash can take. (The library's own gauges with yarns given by
// weight are tighter, about 10 to 12 diameters a loop: see docs/geometry.md.)
inline Pattern at_paper_gauge(const std::string& name) {
  const std::string path = std::string(KNITC_SOURCE_DIR) + "/patterns/" + name + ".lua";
  std::string source = read_text(path);
  source = std::regex_replace(source, std::regex(R"(gauge = \{[^}]*\})"), "gauge = { loop_width = 4.0, loop_height = 4.2, thickness = 2.0 }");
  source = std::regex_replace(source, std::regex(R"(weight = "[^"]*")"), "diameter = 1.0");
  return runtime::run_pattern(source, path).pattern;
}

// The cores' diameters: the relaxation's chains are refined by them.
inline std::vector<double> cores(const Pattern& p) {
  std::vector<double> d;
  for (const Yarn& y : p.yarns) d.push_back(y.core_diameter);
  return d;
}

// The pattern's yarns' sizes, as the relaxation takes them.
inline std::vector<yarn::Size> yarn_sizes(const Pattern& p) {
  std::vector<yarn::Size> s;
  for (const Yarn& y : p.yarns) s.push_back({y.diameter, y.core_diameter});
  return s;
}

// A jersey swatch laid out, its chains, and those chains relaxed within `boundary`.
struct Swatch {
  layout::Layout layout;
  std::vector<yarn_paths::Piece> chains;
  relax::Relaxed out;
};
inline Swatch relaxed_jersey(int stitches, int rows, relax::Boundary boundary) {
  const Pattern pattern = test::jersey(stitches, rows);
  Swatch s;
  s.layout = layout::lay_out(pattern);
  s.chains = relax::refine(yarn_paths::trace(s.layout, yarn_paths::LoopModel::smooth), cores(pattern), relax::Options{}.spacing);
  relax::Options o;
  o.boundary = boundary;
  s.out = relax::relax(s.layout, s.chains, yarn_sizes(pattern), o);
  return s;
}

}  // namespace knitc::test

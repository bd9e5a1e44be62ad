// Knitout in: fabrics whose two beds knit two layers, each needle column's back loop
// behind its front loop (a spacer fabric, a double jacquard), each layer with courses
// of its own height.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <string_view>

#include <glm/vec3.hpp>

#include "compile.hpp"
#include "knit_graph/knit_graph.hpp"
#include "knitout.hpp"
#include "layout/layout.hpp"
#include "measure/crossings.hpp"
#include "yarn_paths/yarn_paths.hpp"
#include "support.hpp"

using namespace knitc;
using namespace knitc::knitout;

namespace {

// Alternate tucks casting `n` needles of one bed on with carrier `c`.
std::string cast_on(char bed, int n, int c) {
  std::string k;
  for (int i = n; i >= 1; --i)
    if (i % 2 == 0) k += std::string("tuck - ") + bed + std::to_string(i) + " " + std::to_string(c) + "\n";
  for (int i = 1; i <= n; ++i)
    if (i % 2 == 1) k += std::string("tuck + ") + bed + std::to_string(i) + " " + std::to_string(c) + "\n";
  return k;
}

// A spacer fabric on `n` needles a bed at racking 0: each row a pass of carrier 1 on the
// front bed, one of carrier 2 on the back, and carrier 3 tucking between them, on the
// front and back needles in turn.
std::string spacer(int n, int rows) {
  std::string k = ";!knitout-2\n;;Carriers: 1 2 3\ninhook 1\n" + cast_on('f', n, 1) + "inhook 2\n" + cast_on('b', n, 2) + "inhook 3\n";
  for (int r = 0; r < rows; ++r) {
    const std::string way = r % 2 == 0 ? "- " : "+ ";
    auto needle = [&](int j) { return r % 2 == 0 ? n + 1 - j : j; };
    for (int j = 1; j <= n; ++j) k += "knit " + way + "f" + std::to_string(needle(j)) + " 1\n";
    for (int j = 1; j <= n; ++j) k += "knit " + way + "b" + std::to_string(needle(j)) + " 2\n";
    for (int j = 1; j <= n; ++j)
      k += "tuck " + way + (needle(j) % 2 == r % 2 ? "f" : "b") + std::to_string(needle(j)) + " 3\n";
  }
  return k + "outhook 1\nouthook 2\nouthook 3\n";
}

// A two-colour double jacquard on `n` needles a bed at racking 0: a checkerboard of four
// by four on the face, each row a pass of each colour knitting its squares' front needles
// and, behind, every back needle (a striped back: each back needle knits twice a row).
std::string striped_back_jacquard(int n, int rows) {
  std::string k = ";!knitout-2\n;;Carriers: 1 2\ninhook 1\n" + cast_on('f', n, 1);
  for (int i = 1; i <= n; ++i) k += "knit + b" + std::to_string(i) + " 1\n";
  k += "inhook 2\n";
  for (int r = 0; r < rows; ++r)
    for (int c = 1; c <= 2; ++c) {
      const bool right = (2 * r + c) % 2 == 0;
      for (int j = 1; j <= n; ++j) {
        const int i = right ? j : n + 1 - j;
        const bool first = ((i - 1) / 4 + r / 4) % 2 == 0;
        const std::string f = first == (c == 1) ? "knit " + std::string(right ? "+ f" : "- f") + std::to_string(i) + " " + std::to_string(c) + "\n" : "";
        const std::string b = "knit " + std::string(right ? "+ b" : "- b") + std::to_string(i) + " " + std::to_string(c) + "\n";
        k += right ? f + b : b + f;  // the back needle lies just right of the front one
      }
    }
  return k + "outhook 1\nouthook 2\n";
}

// Half-Milano rib on `n` needles a bed at racking +0.25: rows of full-needle rib, each
// followed by a pass on the front bed alone.
std::string half_milano(int n, int rows) {
  std::string k = ";!knitout-2\n;;Carriers: 1\ninhook 1\n" + cast_on('f', n, 1) + "rack 0.25\n";
  for (int r = 0; r < rows; ++r)
    if (r % 2 == 0)
      for (int i = n; i >= 1; --i) k += "knit - b" + std::to_string(i) + " 1\nknit - f" + std::to_string(i) + " 1\n";
    else
      for (int i = 1; i <= n; ++i) k += "knit + f" + std::to_string(i) + " 1\n";
  return k + "rack 0\nouthook 1\n";
}

// Milano rib on `n` needles a bed at racking +0.25: rows of full-needle rib, each
// followed by a pass back along the front bed and one on along the back, the yarn
// turning onto the other bed between them as a tube's does.
std::string milano(int n, int rows) {
  std::string k = ";!knitout-2\n;;Carriers: 1\ninhook 1\n" + cast_on('f', n, 1) + "rack 0.25\n";
  for (int r = 0; r < rows; ++r) {
    const bool left = r % 2 == 0;
    const std::string there = left ? "- " : "+ ", back = left ? "+ " : "- ";
    for (int j = 1; j <= n; ++j) {
      const int i = left ? n + 1 - j : j;
      const std::string b = "knit " + there + "b" + std::to_string(i) + " 1\n", f = "knit " + there + "f" + std::to_string(i) + " 1\n";
      k += left ? b + f : f + b;  // the back needle lies just right of the front one
    }
    for (int j = 1; j <= n; ++j) k += "knit " + back + "f" + std::to_string(left ? j : n + 1 - j) + " 1\n";
    for (int j = 1; j <= n; ++j) k += "knit " + there + "b" + std::to_string(left ? n + 1 - j : j) + " 1\n";
  }
  return k + "rack 0\nouthook 1\n";
}

double middle_x(const layout::Loop& l) { return 0.5 * (l.data_points.front().x + l.data_points.back().x); }

}  // namespace

TEST(KnitoutLayers, ASpacerFabricsLayersLieOverEachOtherWithTheTucksBetween) {
  const Pattern spaced = import_text(spacer(12, 6), "spacer.k").pattern;
  // Each row is a course of the two layers' passes and one of the tucks: the front pass
  // turning after the tucks starts the next course (its first loop was drawn with the
  // tucks, a course low).
  for (const Course& c : spaced.courses) {
    bool tucks = false, knits = false;
    for (const Op& op : c.ops) {
      const std::string name(stitch(op.stitch).name);
      tucks = tucks || name == "tuck";
      knits = knits || name == "k" || name == "p";
    }
    EXPECT_FALSE(tucks && knits) << "a course both tucks and knits, at line " << c.where.line;
  }
  const layout::Layout laid = layout::lay_out(spaced);
  const double C = laid.course_spacing;
  EXPECT_GE(laid.layer_depth, spaced.gauge.thickness);
  int over = 0;
  for (int c = 1; c < laid.courses; ++c) {
    std::map<long, const layout::Loop*> front;  // by the middle's x, in hundredths of a mm
    for (const layout::Loop& l : laid.loops)
      if (l.course == c && l.shape == layout::Template::knit) front[std::lround(100 * middle_x(l))] = &l;
    for (const layout::Loop& l : laid.loops) {
      if (l.course != c || l.shape != layout::Template::purl) continue;
      // The back loop behind the front one of its needle column, as wide, a layer apart.
      const auto f = front.find(std::lround(100 * middle_x(l)));
      ASSERT_NE(f, front.end()) << "course " << c << ": no front loop over the back loop at wale " << l.wale;
      EXPECT_NEAR(f->second->data_points.back().x - f->second->data_points.front().x,
                  l.data_points.back().x - l.data_points.front().x, 1e-9);
      EXPECT_DOUBLE_EQ(f->second->data_points[layout::loop_points / 2].z, laid.layer_depth);
      EXPECT_DOUBLE_EQ(l.data_points[layout::loop_points / 2].z, -laid.layer_depth);
      ++over;
    }
  }
  EXPECT_EQ(over, 6 * 12);
  // Each layer's loops a course above the ones they were pulled through; the tucks a
  // quarter course above the layers' course.
  const knit_graph::Graph graph = knit_graph::build(spaced);
  int pulled = 0;
  for (std::size_t i = 0; i < graph.loops.size(); ++i) {
    const auto& k = graph.loops[i];
    if (k.held) continue;
    const knit_graph::Loop* parent = nullptr;  // the wale's: not the tuck held with it
    for (int q : k.parents)
      if (!graph.loops[static_cast<std::size_t>(q)].held) parent = &graph.loops[static_cast<std::size_t>(q)];
    if (parent == nullptr || parent->course < 1) continue;  // the cast-on's
    EXPECT_NEAR(layout::course_y(laid, k.course) - layout::course_y(laid, parent->course), C, 1e-9) << "loop " << i;
    ++pulled;
  }
  EXPECT_EQ(pulled, 5 * 2 * 12);
  int tuck_courses = 0;
  for (std::size_t c = 0; c < spaced.courses.size(); ++c) {
    bool tucks = false, knits = false;
    for (const Op& op : spaced.courses[c].ops) {
      tucks = tucks || stitch(op.stitch).name == std::string_view("tuck");
      knits = knits || stitch(op.stitch).name == std::string_view("k") || stitch(op.stitch).name == std::string_view("p");
    }
    if (!tucks || knits) continue;
    EXPECT_DOUBLE_EQ(spaced.courses[c].rise, 0.25) << "course " << c + 1;
    ++tuck_courses;
  }
  EXPECT_EQ(tuck_courses, 6);

  // Relaxed, no yarn passes through another (drawn side by side, a whole position a
  // loop, 10 of 4,495 crossings on 20 needles).
  const Pattern wide = import_text(spacer(20, 12), "spacer.k").pattern;
  const Fabric f = compile(wide, test::centrelines(true));
  ASSERT_TRUE(f.crossings_checked);
  EXPECT_EQ(measure::passed_through(f.crossings), 0u);
}

TEST(KnitoutLayers, ADoubleJacquardsFaceKeepsItsCoursesAndItsBackIsBehindIt) {
  const Pattern jacquard = import_text(striped_back_jacquard(16, 8), "jacquard.k").pattern;
  const layout::Layout laid = layout::lay_out(jacquard);
  const double C = laid.course_spacing;
  const knit_graph::Graph graph = knit_graph::build(jacquard);
  // The face's loops (each front needle knits once a row, in one colour's pass) a course
  // above the loops they were pulled through; the back's (each back needle knits in both
  // passes) half a course: each colour's pass rises half a course, and the eight rows of
  // the face stand eight courses tall, not sixteen. Where the checkerboard turns, a
  // front needle's loop spans one pass or three, the pass after it a whole course.
  int face = 0, back = 0, face_one = 0, back_half = 0;
  for (std::size_t i = 0; i < graph.loops.size(); ++i) {
    const auto& k = graph.loops[i];
    const auto& l = laid.loops[i];
    if (k.held || k.parents.size() != 1 || k.course < 4) continue;
    const auto& parent = graph.loops[static_cast<std::size_t>(k.parents.front())];
    const double up = layout::course_y(laid, k.course) - layout::course_y(laid, parent.course);
    if (l.shape == layout::Template::knit) {
      EXPECT_GE(up, C - 1e-9) << "loop " << i;
      ++face;
      face_one += std::abs(up - C) < 1e-9;
    }
    if (l.shape == layout::Template::purl) {
      EXPECT_LE(up, C + 1e-9) << "loop " << i;
      ++back;
      back_half += std::abs(up - 0.5 * C) < 1e-9;
    }
  }
  EXPECT_GT(face, 5 * 16);
  EXPECT_GE(back, 2 * face);
  EXPECT_GE(4 * face_one, 3 * face);
  EXPECT_GE(4 * back_half, 3 * back);
  const int last = laid.courses - 1;
  EXPECT_NEAR(layout::course_y(laid, last) - layout::course_y(laid, 1), 8 * C, 1.5 * C);
  // Behind each front loop, the back loop of its needle column lies at its width.
  for (const layout::Loop& l : laid.loops) {
    if (l.course < 2 || laid.layers[static_cast<std::size_t>(l.course)].empty()) continue;
    const int layer = laid.layers[static_cast<std::size_t>(l.course)][static_cast<std::size_t>(l.wale)];
    EXPECT_EQ(layer, l.shape == layout::Template::purl ? -1 : 1);
    EXPECT_DOUBLE_EQ(l.data_points[layout::loop_points / 2].z, layer * laid.layer_depth);
  }
}

TEST(KnitoutLayers, AYarnGoesFromLayerToLayerBetweenThemNotStraightThrough) {
  // Where a colour's pass goes from its front loops to the back ones, the two loops' shared
  // end lies between the layers. At each loop's own layer, the yarn went straight through
  // the fabric's thickness there: a segment seen from the face as a point, beside the head
  // of the loop below, where which yarn crosses which is undecided.
  const Pattern jacquard = import_text(striped_back_jacquard(24, 16), "jacquard.k").pattern;
  const layout::Layout laid = layout::lay_out(jacquard);
  const auto pieces = yarn_paths::trace(laid, yarn_paths::LoopModel::smooth);
  const double d = jacquard.yarns.front().diameter;
  int through = 0, between = 0;
  for (const auto& piece : pieces)
    for (std::size_t k = 0; k + 1 < piece.data_points.size(); ++k) {
      const glm::dvec3 step = piece.data_points[k + 1] - piece.data_points[k];
      const bool cast_on = piece.data_points[k].y == 0.0 && piece.data_points[k + 1].y == 0.0;  // one yarn's, see layout/templates.cpp
      if (!cast_on && std::hypot(step.x, step.y) < 0.05 * d && std::abs(step.z) > d) ++through;
    }
  for (std::size_t i = 0; i + 1 < laid.loops.size(); ++i) {
    const layout::Loop &a = laid.loops[i], &b = laid.loops[i + 1];
    if (a.course < 1 || a.course != b.course || a.yarn != b.yarn || b.wale != a.wale + 1 ||
        laid.layers[static_cast<std::size_t>(a.course)].empty())
      continue;
    const auto& layers = laid.layers[static_cast<std::size_t>(a.course)];
    if (layers[static_cast<std::size_t>(a.wale)] == layers[static_cast<std::size_t>(b.wale)]) continue;
    EXPECT_EQ(a.data_points.back(), b.data_points.front());
    EXPECT_NEAR(a.data_points.back().z, 0.0, 1e-9);
    ++between;
  }
  EXPECT_EQ(through, 0);  // 767 before
  EXPECT_GT(between, 16 * 24 / 4);
  // Relaxed, fewer yarns pass through another: 30 (54 before).
  const Fabric f = compile(jacquard, test::centrelines(true));
  ASSERT_TRUE(f.crossings_checked);
  EXPECT_LT(measure::passed_through(f.crossings), 40u);
}

TEST(KnitoutLayers, HalfMilanosRibCoursesKeepTheirStitchesSideBySide) {
  // Its rib courses knit both beds of every column with one yarn, one after the other:
  // side by side, half a column each; its front passes knit the front loop of each
  // column over the back one left from the rib course.
  const Pattern rib = import_text(half_milano(24, 12), "halfmilano.k").pattern;
  int side_by_side = 0;
  for (const Course& c : rib.courses) {
    if (c.layers.empty()) continue;
    ASSERT_EQ(c.widths.size(), c.layers.size());
    bool halves = true;
    for (double w : c.widths) halves = halves && std::abs(w - 0.5) < 1e-12;
    side_by_side += halves;
  }
  // All six but the first, whose first back loop, knitted on an empty needle, was cast on.
  EXPECT_EQ(side_by_side, 5);
  // Relaxed, no yarn passes through another (a whole position a loop: 13 of 2,074).
  const Fabric f = compile(rib, test::centrelines(true));
  ASSERT_TRUE(f.crossings_checked);
  EXPECT_EQ(measure::passed_through(f.crossings), 0u);
}

TEST(KnitoutLayers, AMilanoRibsPassesAreACourseOnEachBedStackedOverTheirRibRows) {
  // Between its rib rows the yarn goes along the front bed and back along the back, as a
  // tube's round does; in a flat fabric those are two courses, one a layer, or the
  // course's yarn would run the width and back (and no repeat could hold it).
  const Pattern rib = import_text(milano(24, 12), "milano.k").pattern;
  EXPECT_EQ(rib.knitting, Knitting::flat);
  const knit_graph::Graph graph = knit_graph::build(rib);
  std::map<int, std::pair<int, int>> beds;  // per course: its knit and purl loops
  for (const auto& k : graph.loops)
    if (!k.held) {
      const std::string name(stitch(k.stitch).name);
      if (name == "k") ++beds[k.course].first;
      if (name == "p") ++beds[k.course].second;
    }
  int front = 0, back = 0, both = 0;
  for (const auto& [course, n] : beds) {
    if (course == 0) continue;
    front += n.first == 24 && n.second == 0;
    back += n.first == 0 && n.second == 24;
    both += n.first == 24 && n.second == 24;
  }
  // The first rib row's back loops, made on empty needles, are yarn overs: its 24 front
  // loops count with the 12 front passes.
  EXPECT_EQ(front, 12 + 1);
  EXPECT_EQ(back, 12);
  EXPECT_EQ(both, 11);
  // Each loop over the one it was pulled through, whichever course that lies in: the
  // back pass, pulled through the rib row two courses down, lines up over it, not
  // centred over the front pass (each such course off by a column, the fabric leaned).
  const layout::Layout laid = layout::lay_out(rib);
  int over = 0;
  for (std::size_t i = 0; i < graph.loops.size(); ++i) {
    const auto& k = graph.loops[i];
    if (k.held || k.parents.size() != 1 || k.course < 2) continue;
    const layout::Loop& parent = laid.loops[static_cast<std::size_t>(k.parents.front())];
    EXPECT_LE(std::abs(middle_x(laid.loops[i]) - middle_x(parent)), 0.5 * laid.loop_width) << "loop " << i << ", course " << k.course;
    ++over;
  }
  EXPECT_GT(over, 24 * 30);
  // Relaxed, no yarn passes through another.
  const Fabric f = compile(rib, test::centrelines(true));
  ASSERT_TRUE(f.crossings_checked);
  EXPECT_EQ(measure::passed_through(f.crossings), 0u);
}

// A yarn dyed along its length: the rule for which run colours which millimetre, the
// declaration that gives the runs, the mesh's colours by the yarn's length, and the
// stripes and pooling a knitter sees when the same yarn is knitted at two widths.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <numeric>

#include "support.hpp"
#include "tubes/tubes.hpp"
#include "writers/writers.hpp"
#include "yarn/colour.hpp"

namespace knitc {
namespace {

const std::vector<yarn::ColourRun> red_cream = {{"#b5302a", 500.0}, {"#efe6d2", 500.0}};

TEST(ColourRuns, RunsRepeatEndToEndFromTheBallsStart) {
  EXPECT_DOUBLE_EQ(yarn::colour_repeat(red_cream), 1000.0);
  EXPECT_EQ(yarn::run_at(red_cream, 0.0, 0.0), 0u);
  EXPECT_EQ(yarn::run_at(red_cream, 0.0, 499.9), 0u);
  EXPECT_EQ(yarn::run_at(red_cream, 0.0, 500.0), 1u);  // a boundary takes the run that begins there
  EXPECT_EQ(yarn::run_at(red_cream, 0.0, 999.9), 1u);
  EXPECT_EQ(yarn::run_at(red_cream, 0.0, 1000.0), 0u);
  EXPECT_EQ(yarn::run_at(red_cream, 0.0, 123456.0 + 600.0 - 456.0), 1u);  // 123 repeats on, 600 mm in
  EXPECT_EQ(yarn::run_at(red_cream, 700.0, 0.0), 1u);                     // a ball started in the cream
  EXPECT_EQ(yarn::run_at(red_cream, 700.0, 300.0), 0u);
  const std::vector<yarn::ColourRun> three = {{"#000000", 10.0}, {"#ffffff", 20.0}, {"#ff0000", 5.0}};
  EXPECT_EQ(yarn::run_at(three, 0.0, 29.0), 1u);
  EXPECT_EQ(yarn::run_at(three, 0.0, 33.0), 2u);
  EXPECT_EQ(yarn::run_at(three, 0.0, 35.0), 0u);
}

Pattern run(const std::string& source) { return runtime::run_pattern(source, "t.lua").pattern; }

std::string tube(const std::string& yarn, int stitches, int rounds) {
  return "pattern { gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = \"dk\", " + yarn +
         " } }, knitting = \"round\" }\ncast_on(" + std::to_string(stitches) + ")\nrows(" + std::to_string(rounds) +
         ", \"k\")\nbind_off()\n";
}

TEST(ColourRuns, DeclaredInCentimetresAsAKnitterMeasuresThem) {
  const Pattern p = run(tube("colors = { {\"#B5302A\", 40}, {\"#eee\", 25} }, color_start = 12.5", 8, 2));
  ASSERT_EQ(p.yarns[0].colours.size(), 2u);
  EXPECT_EQ(p.yarns[0].colours[0].color, "#b5302a");
  EXPECT_DOUBLE_EQ(p.yarns[0].colours[0].length, 400.0);
  EXPECT_EQ(p.yarns[0].colours[1].color, "#eeeeee");
  EXPECT_DOUBLE_EQ(p.yarns[0].colours[1].length, 250.0);
  EXPECT_DOUBLE_EQ(p.yarns[0].colour_start, 125.0);
  EXPECT_EQ(p.yarns[0].color, "#b5302a");  // the first run's, for whatever shows one colour
  EXPECT_TRUE(run(tube("color = \"#123456\"", 8, 2)).yarns[0].colours.empty());
}

std::string error_of(const std::string& source) {
  try {
    runtime::run_pattern(source, "t.lua");
  } catch (const runtime::PatternError& e) {
    return e.what();
  }
  return "no error";
}

TEST(ColourRuns, BadRunsAreRefusedAtTheirLine) {
  const struct {
    const char* yarn;
    const char* message;
  } cases[] = {
      {"color = \"#fff\", colors = { {\"#000\", 10} }",
       "t.lua:1: yarns.A gives both color and colors; give color for one colour, colors for a dyed sequence"},
      {"colors = {}", "t.lua:1: yarns.A.colors is empty; e.g. colors = { {\"#b03030\", 40}, {\"#efe6d2\", 25} } (cm of yarn each)"},
      {"colors = \"#fff\"",
       "t.lua:1: yarns.A.colors must be a list of {colour, cm} pairs, e.g. colors = { {\"#b03030\", 40}, {\"#efe6d2\", 25} } (cm "
       "of yarn each)"},
      {"colors = { {\"#fff\", 10, 3} }",
       "t.lua:1: yarns.A.colors[1] must be a pair {colour, cm}, e.g. colors = { {\"#b03030\", 40}, {\"#efe6d2\", 25} } (cm of yarn "
       "each)"},
      {"colors = { {\"#fff\", 10}, {\"red\", 5} }",
       "t.lua:1: yarns.A.colors[2]'s colour is \"red\"; give a CSS hex colour such as \"#b03030\""},
      {"colors = { {10, \"#fff\"} }", "t.lua:1: yarns.A.colors[1]'s colour must be a CSS hex string such as \"#b03030\""},
      {"colors = { {\"#fff\", 0} }",
       "t.lua:1: yarns.A.colors[1]'s length is 0 cm; a run of colour is more than 0 cm and at most 100000 cm"},
      {"colors = { {\"#fff\", 0/0} }",
       "t.lua:1: yarns.A.colors[1]'s length is NaN; a run of colour is more than 0 cm and at most 100000 cm"},
      {"colors = { {\"#fff\", \"10\"} }", "t.lua:1: yarns.A.colors[1]'s length must be a number of cm, such as 40"},
      {"color_start = 5", "t.lua:1: yarns.A.color_start is for a yarn with colors"},
      {"colors = { {\"#fff\", 10} }, color_start = -1",
       "t.lua:1: yarns.A.color_start is -1 cm; it must be 0 to 100000 cm"},
  };
  for (const auto& c : cases) {
    EXPECT_EQ(error_of(tube(c.yarn, 8, 2)), c.message) << c.yarn;
  }
  std::string many = "colors = {";
  for (int i = 0; i < 257; ++i) many += "{\"#fff\", 1},";
  many += "}";
  EXPECT_EQ(error_of(tube(many, 8, 2)), "t.lua:1: yarns.A.colors has 257 runs; knitc takes at most 256");
}

// The mesh's colour at every vertex is the run at that vertex's length along the yarn,
// counted over the yarn's pieces in working order.
TEST(ColourRuns, EveryVertexTakesTheRunAtItsLengthAlongTheYarn) {
  // Stripes of A and B: A is cut into two pieces, its second continuing the first's yarn.
  const Pattern p = run(
      "pattern { gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = \"dk\", colors = { {\"#ff0000\", 7}, {\"#0000ff\", 3} } "
      "}, B = { weight = \"dk\", color = \"#00ff00\" } }, knitting = \"flat\" }\ncast_on(6)\nrow \"k\"\nrow \"p\"\nyarn \"B\"\n"
      "row \"k\"\nrow \"p\"\nyarn \"A\"\nrow \"k\"\nrow \"p\"\nbind_off()\n");
  CompileOptions o;
  o.threads = 2;
  const Fabric f = compile(p, o);
  const std::vector<double> before = tubes::yarn_before(f.pieces);
  int a_pieces = 0;
  double a_length = 0.0;
  for (std::size_t i = 0; i < f.pieces.size(); ++i) {
    if (f.pieces[i].path.yarn != 0) continue;
    EXPECT_NEAR(before[i], a_length, 1e-9);
    a_length += f.pieces[i].arc_length.back();
    ++a_pieces;
  }
  EXPECT_EQ(a_pieces, 2);
  int dyed = 0;
  for (const mesh::Primitive& prim : f.mesh.primitives) {
    const mesh::Material& m = f.mesh.materials[static_cast<std::size_t>(prim.material)];
    if (m.name == "B") {
      EXPECT_TRUE(prim.colors.empty());
      continue;
    }
    ++dyed;
    EXPECT_EQ(m.base_color, glm::vec3(1.0f));  // the vertex colours carry the yarn's
    ASSERT_EQ(prim.colors.size(), prim.positions.size());
    std::size_t red = 0;
    for (const auto& c : prim.colors) {
      ASSERT_TRUE(c == glm::vec3(1, 0, 0) || c == glm::vec3(0, 0, 1));
      red += c.r > 0.5f;
    }
    // 7 cm red to 3 cm blue: the vertices (evenly spread along the yarn) follow.
    EXPECT_NEAR(static_cast<double>(red) / static_cast<double>(prim.colors.size()), 0.7, 0.05);
  }
  EXPECT_EQ(dyed, 1);
  // The second piece of A goes on where the first stopped: its first vertex's colour is the
  // run at the first piece's length, not at 0.
  const double at = a_length - f.pieces.back().arc_length.back();
  EXPECT_GT(at, 0.0);
  const tubes::YarnColours rgb = tubes::yarn_colours(p.yarns[0]);
  EXPECT_EQ(tubes::colour_along(p.yarns[0], rgb, at), tubes::colour_along(p.yarns[0], rgb, at + 1e-6));
}

TEST(ColourRuns, WrittenAsCOLOR_0SoAnyReaderShowsThem) {
  const Pattern p = run(tube("colors = { {\"#ff0000\", 10}, {\"#0000ff\", 10} }", 8, 3));
  const Fabric f = compile(p, CompileOptions{});
  const std::string glb = writers::glb(f.mesh, "knitc test");
  EXPECT_NE(glb.find("\"COLOR_0\""), std::string::npos);
  const auto path = test::glb_dir() / "dyed_yarn.glb";
  test::write_text(path, glb);  // the validator test checks it
}

// Each loop's colour: the run at the middle of its stretch of yarn (its head).
struct LoopColours {
  std::map<std::pair<int, int>, std::size_t> run;  // (course, wale) -> run index
  int courses = 0, wales = 0;
};

LoopColours loop_colours(const Pattern& p, const Fabric& f) {
  LoopColours out;
  out.courses = f.layout.courses;
  out.wales = f.layout.wales;
  const std::vector<double> before = tubes::yarn_before(f.pieces);
  for (std::size_t i = 0; i < f.pieces.size(); ++i) {
    const auto& piece = f.pieces[i];
    const Yarn& y = p.yarns[static_cast<std::size_t>(piece.path.yarn)];
    for (std::size_t j = 0; j < piece.path.loops.size(); ++j) {
      const auto [first, last] = piece.loop_samples[j];
      const double s = before[i] + piece.arc_length[(first + last) / 2];
      const layout::Loop& loop = f.layout.loops[static_cast<std::size_t>(piece.path.loops[j])];
      out.run[{loop.course, loop.wale}] = yarn::run_at(y.colours, y.colour_start, s);
    }
  }
  return out;
}

// Mean over the pattern's rounds of the share of its loops in the round's commonest colour.
double row_purity(const LoopColours& c) {
  double sum = 0.0;
  int rows = 0;
  for (int course = 1; course + 1 < c.courses; ++course) {
    std::map<std::size_t, int> count;
    int n = 0;
    for (int w = 0; w < c.wales; ++w) {
      if (auto it = c.run.find({course, w}); it != c.run.end()) ++count[it->second], ++n;
    }
    if (n == 0) continue;
    int most = 0;
    for (const auto& [_, k] : count) most = std::max(most, k);
    sum += static_cast<double>(most) / n;
    ++rows;
  }
  return sum / rows;
}

// The share of loops with the colour of the loop `shift` wales along in the round above
// (wrapping round the tube).
double agreement_above(const LoopColours& c, int course, int shift) {
  int same = 0, n = 0;
  for (int w = 0; w < c.wales; ++w) {
    const auto a = c.run.find({course, w});
    const auto b = c.run.find({course + 1, ((w + shift) % c.wales + c.wales) % c.wales});
    if (a == c.run.end() || b == c.run.end()) continue;
    same += a->second == b->second;
    ++n;
  }
  return n == 0 ? 0.0 : static_cast<double>(same) / n;
}

LoopColours library_colours(const std::string& name) {
  const Pattern p = runtime::run_pattern_file(std::string(KNITC_SOURCE_DIR) + "/patterns/" + name + ".lua").pattern;
  // The layout's yarn lengths: relaxation keeps them within 1.3% here (the snapshots), a
  // centimetre a round, well under the two-stitch drift measured below.
  return loop_colours(p, compile(p, CompileOptions{}));
}

// The same self-striping yarn (50 cm red, 50 cm cream) at two widths: 12 stitches take
// about 24 cm a round, so each colour covers two rounds: stripes. 48 stitches take about
// 96 cm, just under the 100 cm repeat: each colour comes back two stitches earlier every
// round, and the colours stack into a diagonal spiral (pooling).
TEST(ColourRuns, ANarrowTubeStripesAndAWideOnePoolsDiagonally) {
  const LoopColours narrow = library_colours("self_striping");
  const LoopColours wide = library_colours("self_striping_pooled");
  const double narrow_purity = row_purity(narrow), wide_purity = row_purity(wide);
  EXPECT_GT(narrow_purity, 0.85);  // a round is (nearly) one colour: stripes
  EXPECT_LT(wide_purity, 0.75);    // every round holds both colours
  // Stripes: a loop's colour changes every two rounds or so, so the loop above often differs.
  double narrow_above = 0.0;
  for (int course = 1; course + 2 < narrow.courses; ++course) narrow_above += agreement_above(narrow, course, 0);
  narrow_above /= narrow.courses - 3;
  EXPECT_LT(narrow_above, 0.7);
  // Pooling: each round's colours sit on the round below's, shifted the same way every
  // round: the best shift is the same and not zero (a diagonal, not a vertical column).
  std::map<int, int> best_shifts;
  double best_sum = 0.0;
  int rounds = 0;
  for (int course = 1; course + 2 < wide.courses; ++course) {
    int best = 0;
    double best_agreement = -1.0;
    for (int shift = -6; shift <= 6; ++shift) {
      const double a = agreement_above(wide, course, shift);
      if (a > best_agreement) best_agreement = a, best = shift;
    }
    ++best_shifts[best];
    best_sum += best_agreement;
    ++rounds;
  }
  const auto commonest = std::max_element(best_shifts.begin(), best_shifts.end(),
                                          [](const auto& a, const auto& b) { return a.second < b.second; });
  EXPECT_NE(commonest->first, 0);
  EXPECT_GE(std::abs(commonest->first), 1);
  EXPECT_GE(commonest->second, rounds * 8 / 10) << "the colours drift the same way every round";
  EXPECT_GT(best_sum / rounds, 0.9) << "each round's colours stack on the round below's";
  std::printf("purity %.3f narrow, %.3f wide; above %.3f narrow; wide: shift %d in %d of %d rounds, agreement %.3f\n", narrow_purity,
              wide_purity, narrow_above, commonest->first, commonest->second, rounds, best_sum / rounds);
}

}  // namespace
}  // namespace knitc

namespace knitc {
namespace {

TEST(Heather, FibresOfMixedColoursInTheirShares) {
  const Pattern p = runtime::run_pattern(
                        "pattern { gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = \"dk\", heather = { "
                        "{\"#ff0000\", 3}, {\"#0000ff\", 1} } } }, knitting = \"flat\" }\ncast_on(8)\nrow \"k\"\nrow \"p\"\n"
                        "row \"k\"\nrow \"p\"\nbind_off()\n",
                        "t.lua")
                        .pattern;
  ASSERT_EQ(p.yarns[0].heather.size(), 2u);
  EXPECT_EQ(p.yarns[0].heather[1], (yarn::FibreColour{"#0000ff", 1.0}));
  EXPECT_EQ(yarn::fibre_colour_at(p.yarns[0].heather, 0.74), 0u);
  EXPECT_EQ(yarn::fibre_colour_at(p.yarns[0].heather, 0.76), 1u);
  // The material's sheen is the blend; the vertices carry the fibres' colours in their shares.
  CompileOptions o;
  o.threads = 2;
  const Fabric tube = compile(p, o);
  const mesh::Primitive& prim = tube.mesh.primitives.at(0);
  ASSERT_EQ(prim.colors.size(), prim.positions.size());
  const auto red_share = [](const std::vector<glm::vec3>& colours) {
    std::size_t red = 0;
    for (const auto& c : colours) red += c == glm::vec3(1, 0, 0);
    return static_cast<double>(red) / static_cast<double>(colours.size());
  };
  EXPECT_NEAR(red_share(prim.colors), 0.75, 0.01);
  EXPECT_NEAR(tube.mesh.materials[0].sheen_color.r, 0.75f, 1e-6f);
  EXPECT_NEAR(tube.mesh.materials[0].sheen_color.b, 0.25f, 1e-6f);
  // With fibres: each fibre one colour, the fibres in their shares; the cores the blend.
  o.fibres = true;
  const Fabric fibres = compile(p, o);
  for (const mesh::Primitive& q : fibres.mesh.primitives) {
    ASSERT_EQ(q.colors.size(), q.positions.size());
    if (q.mode == mesh::Mode::lines) {
      EXPECT_NEAR(red_share(q.colors), 0.75, 0.06);
    } else {
      for (const auto& c : q.colors) EXPECT_EQ(c, glm::vec3(0.75f, 0.0f, 0.25f));
    }
  }
}

TEST(Heather, BadBlendsAreRefused) {
  const auto error_of = [](const std::string& yarn) {
    try {
      runtime::run_pattern("pattern { gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = \"dk\", " + yarn +
                               " } } }\ncast_on(4)\nrow \"k\"\n",
                           "t.lua");
    } catch (const runtime::PatternError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(error_of("heather = { {\"#fff\", 1} }, colors = { {\"#000\", 5} }"),
            "t.lua:1: yarns.A gives both colors and heather; knitc dyes a yarn along its length or blends its fibres, not both yet");
  EXPECT_EQ(error_of("heather = { {\"#fff\", 1} }, color = \"#000\""),
            "t.lua:1: yarns.A gives both color and heather; give color for one colour, heather for fibres of mixed colours");
  EXPECT_EQ(error_of("heather = { {\"#fff\", -1} }"),
            "t.lua:1: yarns.A.heather[1]'s share is -1; a share is more than 0 and at most 1000000");
  EXPECT_EQ(error_of("heather = { {\"#fff\", \"x\"} }"), "t.lua:1: yarns.A.heather[1]'s share must be a number, such as 3");
  EXPECT_EQ(error_of("heather = {}"),
            "t.lua:1: yarns.A.heather is empty; e.g. heather = { {\"#6b7b8c\", 3}, {\"#d8d2c4\", 1} } (each colour's share of the "
            "fibres)");
}

}  // namespace
}  // namespace knitc

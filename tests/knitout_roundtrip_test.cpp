// Knitout out: every library pattern a machine can knit exports, the program passes the
// checker (legal for the profile, read back exactly, no loop dropped unsecured), and
// reading it back gives the same knit graph as the pattern: the same loops, parents,
// yarn order, floats and crossing order.
#include <gtest/gtest.h>

#include "knit_graph/knit_graph.hpp"
#include "knitout.hpp"
#include "support.hpp"

namespace fs = std::filesystem;
using namespace knitc;

namespace {

// The knit graph as text: every loop's course, slot, stitch, yarn id, order along the
// yarn, parents and flags; the floats; the live stitches at the end.
std::string graph_text(const Pattern& p) {
  const knit_graph::Graph g = knit_graph::build(p);
  std::string s = p.knitting == Knitting::round ? "round\n" : "flat\n";
  s += p.bound_off ? "bound off\n" : "";
  for (const auto& c : p.courses) s += c.side == Side::right ? "R" : "W";
  s += "\n";
  for (const auto& l : g.loops) {
    s += std::to_string(l.course) + " " + std::to_string(l.slot) + " " + std::string(stitch(l.stitch).name) + " " +
         p.yarns[static_cast<std::size_t>(l.yarn)].color + " " + std::to_string(l.order) + " [";
    for (int q : l.parents) s += std::to_string(q) + ",";
    s += "]" + std::string(l.held ? " held" : "") + (l.unravelled ? " unravelled" : "") + (l.bound ? " bound" : "") + (l.plating ? " plating" : "") + "\n";
  }
  for (const auto& f : g.floats)
    s += "float " + std::to_string(f.course) + " " + std::to_string(f.first) + "-" + std::to_string(f.last) + (f.in_front ? " front" : "") + "\n";
  return s;
}

// The imported pattern's yarns are its carriers; give them the pattern's colours by index
// so that the two graphs name yarns alike.
void colour_like(Pattern& imported, const Pattern& original) {
  for (std::size_t y = 0; y < imported.yarns.size() && y < original.yarns.size(); ++y) imported.yarns[y].color = original.yarns[y].color;
}

}  // namespace

TEST(KnitoutRoundTrip, EveryLibraryPatternAMachineCanKnitComesBackAsTheSameKnitGraph) {
  int exported = 0, refused = 0;
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(fs::path(KNITC_SOURCE_DIR) / "patterns")) {
    if (entry.path().extension() != ".lua") continue;
    names.push_back(entry.path().string());
  }
  std::sort(names.begin(), names.end());
  for (const std::string& path : names) {
    SCOPED_TRACE(path);
    const Pattern pattern = runtime::run_pattern_file(path).pattern;
    for (const char* machine : {"swg", "kniterate"}) {
      const knitout::Profile profile = knitout::profile_named(machine);
      knitout::Exported out;
      try {
        out = knitout::export_pattern(pattern, profile);
      } catch (const knitout::KnitoutError& e) {
        // Refused at the pattern's own line, naming what it cannot write.
        EXPECT_EQ(std::string(e.what()).rfind(path + ":", 0), 0u) << e.what();
        ++refused;
        continue;
      }
      ++exported;
      knitout::Imported back;
      const auto problems = knitout::check_program(out.text, "out.k", profile, &back);
      EXPECT_TRUE(problems.empty()) << machine << ": " << (problems.empty() ? "" : problems.front());
      if (!problems.empty()) continue;
      colour_like(back.pattern, pattern);
      // A tube is bound off with sliders: on a machine without them the loops stay live (said).
      Pattern expected = pattern;
      if (!out.warnings.empty() && out.warnings.front().find("has no sliders") != std::string::npos) expected.bound_off = false;
      EXPECT_EQ(graph_text(back.pattern), graph_text(expected)) << machine;
      EXPECT_NE(out.text.find(";!source: " + path + ":"), std::string::npos);
    }
  }
  // The library's flat fabrics of knit, purl, lace, cables, slips and colour export;
  // what the writer cannot do yet is refused, counted here so a change is seen.
  EXPECT_GE(exported, 30);
  std::printf("exported %d, refused %d (pattern x machine)\n", exported, refused);
}

TEST(KnitoutRoundTrip, AStitchOrARackingTheProfileCannotDoIsAnErrorAtItsLine) {
  const auto pattern = [](const std::string& body) {
    return runtime::run_pattern("pattern { name = \"t\", gauge = { stitches = 22, rows = 30 }, yarns = { A = { diameter = 1.0, color = \"#d9c8a9\" } }, knitting = \"flat\" }\n" + body,
                                "t.lua")
        .pattern;
  };
  const auto error = [](const Pattern& p, const char* machine) {
    try {
      knitout::export_pattern(p, knitout::profile_named(machine));
    } catch (const knitout::KnitoutError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(error(pattern("cast_on(8)\nrow \"k\"\nrow \"p\"\nrow \"k2, MB, k5\"\n"), "swg").find("t.lua:5: knitc cannot yet write 'bobble 5x4' for a knitting machine"), std::string::npos);
  // An 8-stitch cable racks 4 needles: the SWG-like reaches it, a 3-needle racking would not.
  const Pattern c8 = pattern("cast_on(10)\nrow \"k\"\nrow \"p\"\nrow \"k1, C8F, k1\"\nrow \"p\"\n");
  EXPECT_EQ(error(c8, "swg"), "");
  knitout::Profile narrow = knitout::profile_named("kniterate");
  narrow.max_racking = 3;
  try {
    knitout::export_pattern(c8, narrow);
    ADD_FAILURE() << "a 4-needle racking on a 3-needle machine";
  } catch (const knitout::KnitoutError& e) {
    EXPECT_NE(std::string(e.what()).find("t.lua:5: 'C8F' needs a racking of -4 and the kniterate reaches 3"), std::string::npos) << e.what();
  }
  // Wider than the bed.
  EXPECT_NE(error(pattern("cast_on(300)\nrow \"k\"\n"), "kniterate").find("the kniterate bed has 252"), std::string::npos);
}

TEST(KnitoutCli, ReadsAProgramByNameOrFirstLineAndWritesOneFromAPattern) {
  const auto dir = test::scratch_dir("knitout-cli");
  // A machine program without the usual extension is known by its first line.
  test::write_text(dir / "sheet.txt", ";!knitout-2\n;;Carriers: 1\ninhook 1\ntuck - f2 1\ntuck + f1 1\nknit - f2 1\nknit - f1 1\nreleasehook 1\nouthook 1\n");
  const auto check = test::run_knitc("check '" + (dir / "sheet.txt").string() + "'");
  EXPECT_EQ(check.exit_code, 0) << check.err;
  EXPECT_NE(check.err.find("1 rows, 2 stitches cast on"), std::string::npos) << check.err;
  // Export, then build what was written.
  const std::string out = (dir / "jersey.k").string();
  const auto exported = test::run_knitc("knitout patterns/jersey.lua -o '" + out + "' --machine kniterate");
  ASSERT_EQ(exported.exit_code, 0) << exported.err;
  const std::string program = test::read_text(out);
  EXPECT_EQ(program.rfind(";!knitout-2\n;;Machine: Kniterate\n;;Gauge: 7\n", 0), 0u);
  const auto built = test::run_knitc("build '" + out + "' -q --relax off -o '" + (test::glb_dir() / "knitout-export-jersey.glb").string() + "'");
  EXPECT_EQ(built.exit_code, 0) << built.err;
  fs::remove_all(dir);
}

TEST(KnitoutCli, BadProgramsExitOneAtTheirLineAndMisuseExitsTwo) {
  const auto dir = test::scratch_dir("knitout-bad");
  test::write_text(dir / "bad.k", ";!knitout-2\n;;Carriers: 1\ninhook 1\nknit + f1 1\nrack 1\nxfer f1 b1\n");
  const auto bad = test::run_knitc("build '" + (dir / "bad.k").string() + "' -o '" + (dir / "bad.glb").string() + "'");
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.err.find("bad.k:6: xfer from f1 to b1: the needles are not aligned at racking 1"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(dir / "bad.glb"));
  test::write_text(dir / "noise.k", std::string("\x7f" "ELF\x01\x02", 6));
  const auto noise = test::run_knitc("check '" + (dir / "noise.k").string() + "'");
  EXPECT_EQ(noise.exit_code, 1);
  EXPECT_NE(noise.err.find("noise.k:1: the first line is not ';!knitout-N'"), std::string::npos) << noise.err;
  // A program of one course (its cast-on) has no course after it: check said so by
  // reading past the end of an empty list (a crash, found 2026-12-06).
  test::write_text(dir / "one.k", ";!knitout-2\n;;Carriers: 1\ninhook 1\nknit + f1 1\n");
  const auto one = test::run_knitc("check '" + (dir / "one.k").string() + "'");
  EXPECT_EQ(one.exit_code, 0) << one.err;
  EXPECT_NE(one.err.find("1 stitches cast on, 1 live at the end"), std::string::npos) << one.err;
  EXPECT_EQ(test::run_knitc("knitout patterns/jersey.lua").exit_code, 2);
  EXPECT_EQ(test::run_knitc("knitout patterns/jersey.lua -o x.k --machine loom").exit_code, 2);
  const auto refused = test::run_knitc("knitout patterns/brioche.lua -o '" + (dir / "b.k").string() + "'");
  EXPECT_EQ(refused.exit_code, 1);
  EXPECT_NE(refused.err.find("patterns/brioche.lua:"), std::string::npos) << refused.err;
  EXPECT_FALSE(fs::exists(dir / "b.k"));
  fs::remove_all(dir);
}

// The knitc command line, end to end: outputs, views, exit codes, and no file left
// behind by a failure. The .glb files written to the glb directory are checked by the
// gltf_validator test afterwards.
#include <cmath>
#include <cstdlib>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "reference_nurbs.hpp"
#include "support.hpp"

namespace knitc {
namespace {

namespace fs = std::filesystem;

std::string quoted(const fs::path& p) { return "'" + p.string() + "'"; }

TEST(Cli, BuildsTheDefaultPatternInEveryViewAndLoopModel) {
  const fs::path dir = test::glb_dir();
  const std::pair<const char*, const char*> cases[] = {
      {"jersey-surface.glb", ""},
      {"jersey-surface-paper.glb", "--loop-model paper"},
      {"jersey-wireframe.glb", "--view wireframe --relax off"},
      {"jersey-centreline.glb", "--view centreline --relax off"},
      {"jersey-centreline-paper.glb", "--view centreline --loop-model paper"},
      {"jersey-centripetal-coarse.glb", "--parameters centripetal --sides 5 --tolerance 0.1 --relax off"},
      {"jersey-compressed.glb", "--compress"},
      {"jersey-compressed-wireframe.glb", "--compress --view wireframe --relax off"},
  };
  for (const auto& [name, options] : cases) {
    const auto r = test::run_knitc("build patterns/jersey.lua -q -o " + quoted(dir / name) + " " + options);
    EXPECT_EQ(r.exit_code, 0) << name << ": " << r.err;
    EXPECT_EQ(r.err, "") << name;
    ASSERT_TRUE(fs::exists(dir / name)) << name;
    const std::string glb = test::read_text(dir / name);
    ASSERT_GT(glb.size(), 20u);
    EXPECT_EQ(glb.substr(0, 4), "glTF");
    EXPECT_NE(glb.find("\"generator\":\"knitc 0."), std::string::npos);
  }
}

TEST(Cli, BuildsEllipticalAndPliedYarnsAtEveryQuality) {
  const fs::path dir = test::glb_dir();
  const fs::path src = test::scratch_dir("sections");
  test::write_text(src / "sections.lua",
                   "pattern { gauge = { stitches = 22, rows = 30 }, yarns = {\n"
                   "  A = { weight = \"dk\", color = \"#b5523b\", section = \"plied\", plies = 3, twist = 20, direction = \"Z\" },\n"
                   "  B = { weight = \"dk\", color = \"#3b7fb5\", section = \"ellipse\", aspect = 0.5 } } }\n"
                   "cast_on(8)\nrows(2, \"k\")\nyarn \"B\"\nrows(2, \"k2, p2\")\n");
  std::size_t previous = 0;
  for (const char* quality : {"draft", "normal", "fine"}) {
    const fs::path out = dir / (std::string("sections-") + quality + ".glb");
    const auto r = test::run_knitc("build " + quoted(src / "sections.lua") + " -q --relax off --quality " + quality + " -o " + quoted(out));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto size = fs::file_size(out);
    EXPECT_GT(size, previous) << quality;  // finer is bigger
    previous = size;
    EXPECT_NE(test::read_text(out).find("KHR_materials_sheen"), std::string::npos);
  }
  // --sides wins over --quality.
  const auto a = test::run_knitc("build " + quoted(src / "sections.lua") + " -q --relax off --quality fine --sides 4 -o " + quoted(src / "a.glb"));
  const auto b = test::run_knitc("build " + quoted(src / "sections.lua") + " -q --relax off --tolerance 0.0025 --sides 4 -o " + quoted(src / "b.glb"));
  ASSERT_EQ(a.exit_code, 0);
  ASSERT_EQ(b.exit_code, 0);
  EXPECT_EQ(test::read_text(src / "a.glb"), test::read_text(src / "b.glb"));
  EXPECT_EQ(test::run_knitc("build patterns/jersey.lua -o " + quoted(src / "c.glb") + " --quality ultra").exit_code, 2);
  fs::remove_all(src);
}

// The worst distance of a loop's samples from the paper's curve through its data points,
// computed independently, over a spread of the file's loops (to its rounding of 1e-6 mm);
// each loop's samples start at its first data point and end at its last.
double worst_sample_off_curve(const nlohmann::json& doc, std::size_t stride) {
  double worst = 0.0;
  std::size_t index = 0;
  for (const auto& loop : doc["loops"]) {
    if (index++ % stride != 0) continue;  // the search below is slow
    std::vector<glm::dvec3> q;
    for (const auto& p : loop["data_points"]) q.emplace_back(p[0].get<double>(), p[1].get<double>(), p[2].get<double>());
    EXPECT_EQ(q.size(), 17u);
    const auto& samples = loop["samples"];
    EXPECT_GE(samples.size(), 17u);
    if (q.size() != 17u || samples.size() < 17u) return 1e9;
    auto at = [&](std::size_t i) { return glm::dvec3(samples[i][0].get<double>(), samples[i][1].get<double>(), samples[i][2].get<double>()); };
    EXPECT_LT(glm::distance(at(0), q[0]), 2e-6);
    EXPECT_LT(glm::distance(at(samples.size() - 1), q[16]), 2e-6);
    const auto ref = reference::interpolate(q, false);
    // Nearest point on the reference curve by dense search and a few bisections.
    for (std::size_t i = 0; i < samples.size(); ++i) {
      const glm::dvec3 s = at(i);
      double best_u = 0.0, best = 1e9;
      for (int k = 0; k <= 500; ++k) {
        const double dist = glm::distance(reference::point(ref, k / 500.0), s);
        if (dist < best) best = dist, best_u = k / 500.0;
      }
      double lo = std::max(0.0, best_u - 1.0 / 500), hi = std::min(1.0, best_u + 1.0 / 500);
      for (int it = 0; it < 60; ++it) {
        const double a = lo + (hi - lo) / 3, b = hi - (hi - lo) / 3;
        if (glm::distance(reference::point(ref, a), s) < glm::distance(reference::point(ref, b), s)) hi = b;
        else lo = a;
      }
      worst = std::max(worst, glm::distance(reference::point(ref, 0.5 * (lo + hi)), s));
    }
  }
  return worst;
}

TEST(Cli, WritesTheCentrelineJson) {
  const fs::path dir = test::scratch_dir("json");
  const auto r = test::run_knitc("build patterns/jersey.lua -q -o " + quoted(dir / "j.glb") + " --loop-model paper --centreline " +
                                 quoted(dir / "j.json"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto doc = nlohmann::json::parse(test::read_text(dir / "j.json"));
  EXPECT_EQ(doc["units"], "mm");
  EXPECT_EQ(doc["loop_model"], "paper");
  ASSERT_EQ(doc["yarns"].size(), 1u);
  EXPECT_EQ(doc["yarns"][0]["id"], "A");
  EXPECT_EQ(doc["yarns"][0]["color"], "#d9c8a9");
  ASSERT_EQ(doc["loops"].size(), 520u);  // jersey: 20 stitches, the cast-on, 24 rows and the bind-off
  std::size_t pieces_points = 0;
  for (const auto& piece : doc["yarns"][0]["pieces"]) pieces_points += piece[1].get<std::size_t>();
  EXPECT_EQ(pieces_points, doc["yarns"][0]["points"].size());
  for (const auto& loop : doc["loops"]) {
    EXPECT_EQ(loop["stitch"], "k");
    EXPECT_EQ(loop["yarn"], "A");
    // The row's script line: jersey's right-side rows are line 11, its wrong-side rows 12.
    const int course = loop["course"].get<int>();
    if (course >= 1 && course <= 24) {
      EXPECT_EQ(loop["file"], "patterns/jersey.lua");
      EXPECT_EQ(loop["line"], course % 2 == 1 ? 11 : 12) << course;
    } else {
      EXPECT_EQ(loop["line"], 0) << course;
    }
  }
  EXPECT_LT(worst_sample_off_curve(doc, 29), 1e-5);
  fs::remove_all(dir);
}

// In the round the data points are written wrapped onto the tube, as the samples are:
// a loop's curve can be checked against its own data points from the file alone.
TEST(Cli, TheCentrelineJsonIsInOneSpaceInTheRound) {
  const fs::path dir = test::scratch_dir("json-round");
  const auto r = test::run_knitc("build patterns/jersey_in_the_round.lua -q -o " + quoted(dir / "j.glb") +
                                 " --loop-model paper --centreline " + quoted(dir / "j.json"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto doc = nlohmann::json::parse(test::read_text(dir / "j.json"));
  EXPECT_LT(worst_sample_off_curve(doc, 23), 1e-5);
  // The tube: every data point lies near the cylinder the loops were wrapped onto.
  double r_min = 1e9, r_max = 0.0;
  for (const auto& loop : doc["loops"]) {
    for (const auto& p : loop["data_points"]) {
      const double radius = std::hypot(p[0].get<double>(), p[2].get<double>());
      r_min = std::min(r_min, radius), r_max = std::max(r_max, radius);
    }
  }
  EXPECT_GT(r_min, 0.5 * r_max) << "the data points are flat, not on the tube";
  fs::remove_all(dir);
}

TEST(Cli, PatternProblemsExitOneAndWriteNothing) {
  const fs::path dir = test::scratch_dir("bad");
  test::write_text(dir / "bad.lua", "pattern { gauge = { stitches = 20, rows = 30 }, yarns = { A = { diameter = 1 } } }\n"
                                    "cast_on(10)\nrows(4, \"k3\")\n");
  test::write_text(dir / "keep.glb", "an older file");
  const auto r = test::run_knitc("build " + quoted(dir / "bad.lua") + " -o " + quoted(dir / "keep.glb") +
                                 " --centreline " + quoted(dir / "c.json"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, (dir / "bad.lua").string() +
                       ":3: row 1 \"k3\" repeats every 3 stitches and does not fit 10 live stitches (1 left over); "
                       "make the count a multiple of 3 or end the row with fixed stitches (*...; rep from * to last 1 st, ...)\n");
  EXPECT_EQ(test::read_text(dir / "keep.glb"), "an older file");
  EXPECT_FALSE(fs::exists(dir / "c.json"));
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 2u);  // no temporaries left
  fs::remove_all(dir);
}

TEST(Cli, FabricsTooBigToMeshAreRefusedBeforeMemoryRunsOut) {
  const fs::path dir = test::scratch_dir("huge");
  const std::string header = "pattern { gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1 } } }\n";
  test::write_text(dir / "loops.lua", header + "cast_on(100000)\nrows(199, \"k\")\n");  // 20 million loops in all
  test::write_text(dir / "fine.lua", header + "cast_on(1000)\nrows(1500, \"k\")\n");
  // 20 million stitches take the script a while in an unoptimised build: past the default deadline.
  const auto loops = test::run_knitc("build " + quoted(dir / "loops.lua") + " --max-seconds 120 -o " + quoted(dir / "x.glb"));
  EXPECT_EQ(loops.exit_code, 1);
  EXPECT_NE(loops.err.find("knitc lays out at most 2000000"), std::string::npos) << loops.err;
  EXPECT_EQ(loops.err.rfind((dir / "loops.lua").string() + ":3: the fabric has 20000000 loops", 0), 0u) << loops.err;
  const auto fine = test::run_knitc("build " + quoted(dir / "fine.lua") + " --quality fine -o " + quoted(dir / "x.glb"));
  EXPECT_EQ(fine.exit_code, 1);
  EXPECT_NE(fine.err.find("over knitc's limit of 80 million vertices"), std::string::npos) << fine.err;
  EXPECT_EQ(test::run_knitc("check --max-seconds 120 " + quoted(dir / "loops.lua")).exit_code, 0);  // the pattern itself is fine
  EXPECT_FALSE(fs::exists(dir / "x.glb"));
  fs::remove_all(dir);
}

TEST(Cli, CommandLineMisuseExitsTwo) {
  const fs::path dir = test::scratch_dir("usage");
  const std::string out = " -o " + quoted(dir / "x.glb");
  for (const std::string& args :
       {std::string(""), std::string("build"), std::string("build patterns/jersey.lua"), std::string("frobnicate"),
        "build patterns/jersey.lua" + out + " --view hologram", "build patterns/jersey.lua" + out + " --sides 2",
        "build patterns/jersey.lua" + out + " --tolerance 0", "build patterns/jersey.lua" + out + " --loop-model lumpy",
        "build patterns/jersey.lua" + out + " --relax maybe", "build patterns/jersey.lua" + out + " --edges sticky",
        "build patterns/jersey.lua" + out + " --centreline " + quoted(dir / "x.glb"),
        std::string("build patterns/jersey.lua -o patterns/jersey.lua"),
        std::string("render patterns/jersey.lua -o ./patterns/../patterns/jersey.lua"),
        "build patterns/jersey.lua" + out + " --tolerance nan", "build patterns/jersey.lua" + out + " --tolerance inf",
        "render patterns/jersey.lua -o " + quoted(dir / "x.png") + " --size 4294967312x4294967312",
        "render patterns/jersey.lua -o " + quoted(dir / "x.png") + " --size 64x48x", std::string("bench --swatch 10x-5"),
        "build patterns/jersey.lua" + out + " --max-seconds nan",
        "build patterns/jersey.lua" + out + " --centreline " + quoted(dir / "sub/../x.glb"),
        "build patterns/jersey.lua -o " + quoted(dir / "x.json"), "build patterns/jersey.lua -o " + quoted(dir / "x.GLTF"),
        "build patterns/jersey.lua -o " + quoted(dir / "x.png"), "build patterns/jersey.lua -o " + quoted(dir / "x.k")}) {
    const auto r = test::run_knitc(args);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
    EXPECT_FALSE(r.err.empty()) << args;
  }
  for (const char* name : {"x.glb", "x.json", "x.GLTF", "x.png", "x.k"}) EXPECT_FALSE(fs::exists(dir / name)) << name;
  fs::remove_all(dir);
}

// The number after `label` in a snapshot or --stats text, or NaN.
double figure(const std::string& text, const std::string& label) {
  const auto at = text.find(label);
  if (at == std::string::npos) return std::nan("");
  return std::strtod(text.c_str() + at + label.size(), nullptr);
}

TEST(Cli, RelaxOnClearsTheOverlapAndSaysSo) {
  const auto off = test::run_knitc("snapshot patterns/jersey.lua --relax off");
  const auto on = test::run_knitc("snapshot patterns/jersey.lua");  // on: the smooth model's default
  ASSERT_EQ(off.exit_code, 0) << off.err;
  ASSERT_EQ(on.exit_code, 0) << on.err;
  EXPECT_NE(off.out.find("relaxation  off"), std::string::npos);
  // The figures as numbers: the seed paper's loops overlap by about 0.85 d (and their
  // cores, 1/1.91 of it, by 0.7 core d); relaxed, the cores by under 0.1 core d, and the
  // written tubes (their shells pressed) by under 0.1 d.
  EXPECT_NEAR(figure(off.out, "penetration "), 0.85, 0.03) << off.out;
  EXPECT_LT(figure(on.out, "penetration "), 0.1) << on.out;
  EXPECT_GT(figure(on.out, " iterations, overlap "), 0.6) << on.out;
  EXPECT_LT(figure(on.out, " -> "), 0.1) << on.out;
  const auto stats = test::run_knitc("build patterns/jersey.lua -o " + quoted(test::scratch_dir("relax") / "j.glb") +
                                     " --relax on --edges held --stats");
  ASSERT_EQ(stats.exit_code, 0) << stats.err;
  EXPECT_NE(stats.err.find("relaxation  "), std::string::npos);
  EXPECT_NE(stats.err.find(" s; cores overlap"), std::string::npos) << stats.err;  // the time, in --stats only
  EXPECT_NE(stats.err.find("loop shape  l "), std::string::npos);
  // Each yarn's two diameters: the free one drawn, the core 1/1.91 of it when not given.
  const double free = figure(stats.err, "free diameter "), core = figure(stats.err, " mm, core ");
  EXPECT_GT(free, 0.0) << stats.err;
  EXPECT_NEAR(free / core, 1.9125, 0.01) << stats.err;
  EXPECT_EQ(stats.err.find("measured on the mesh's centrelines"), std::string::npos) << stats.err;  // normal quality
}

// A coarse mesh cuts the yarn's bends by up to its chord error, so the overlaps --stats
// measures on it say so, and how to measure the curves.
TEST(Cli, StatsSayWhenTheOverlapsAreACoarseMeshs) {
  const auto coarse = test::run_knitc("build patterns/jersey.lua -o " + quoted(test::scratch_dir("coarse") / "j.glb") +
                                      " --relax off --tolerance 0.3 --stats");
  ASSERT_EQ(coarse.exit_code, 0) << coarse.err;
  EXPECT_NE(coarse.err.find("both measured on the mesh's centrelines, which cut the curves' bends by up to 0.30 d at this "
                            "density; --quality normal measures the curves within 0.01 d"),
            std::string::npos)
      << coarse.err;
}

TEST(Cli, RendersAPreviewPng) {
  const fs::path dir = test::scratch_dir("render");
  const auto r = test::run_knitc("render patterns/jersey.lua -q --relax off --size 64x48 --side both -o " + quoted(dir / "j.png"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string png = test::read_text(dir / "j.png");
  ASSERT_GT(png.size(), 24u);
  EXPECT_EQ(png.substr(1, 3), "PNG");
  // The IHDR chunk: width and height, big-endian, at bytes 16 and 20.
  auto be32 = [&](std::size_t at) {
    return (static_cast<unsigned char>(png[at]) << 24) | (static_cast<unsigned char>(png[at + 1]) << 16) |
           (static_cast<unsigned char>(png[at + 2]) << 8) | static_cast<unsigned char>(png[at + 3]);
  };
  EXPECT_EQ(be32(16), 128u);  // face and back side by side
  EXPECT_EQ(be32(20), 48u);
  // Traced by default; --light flat and a close-up give other pictures of the same size.
  const auto flat = test::run_knitc("render patterns/jersey.lua -q --relax off --size 64x48 --side both --light flat -o " +
                                    quoted(dir / "f.png"));
  ASSERT_EQ(flat.exit_code, 0) << flat.err;
  EXPECT_NE(test::read_text(dir / "f.png"), png);
  const auto close = test::run_knitc("render patterns/jersey.lua -q --relax off --size 64x48 --close-up 4 --samples 4 -o " +
                                     quoted(dir / "c.png"));
  ASSERT_EQ(close.exit_code, 0) << close.err;
  for (const char* bad : {"--size 64", "--size 0x10", "--side sideways", "--light dim", "--samples 0", "--samples 5000",
                          "--close-up 0", "--close-up x"}) {
    EXPECT_EQ(test::run_knitc(std::string("render patterns/jersey.lua -o ") + quoted(dir / "x.png") + " " + bad).exit_code, 2)
        << bad;
  }
  EXPECT_FALSE(fs::exists(dir / "x.png"));
  fs::remove_all(dir);
}

// The density follows the picture asked for: a fabric seen whole is meshed for its full
// view, a close-up of a few loops for the loops it shows.
TEST(Cli, ACloseUpIsMeshedForTheLoopsItShows) {
  const fs::path dir = test::scratch_dir("close_up");
  const std::string script = (dir / "wide.lua").string();
  test::write_text(script, test::jersey_source(100, 40));
  const auto whole = test::run_knitc("render '" + script + "' --relax off --size 200x150 --samples 1 --stats -o " + quoted(dir / "w.png"));
  ASSERT_EQ(whole.exit_code, 0) << whole.err;
  EXPECT_NE(whole.err.find("8 sides, tolerance 0.025 d; from the view: a loop spans 19 px of a 1920 x 1080 px full view"),
            std::string::npos) << whole.err;
  const auto close = test::run_knitc("render '" + script + "' --relax off --size 200x150 --samples 1 --close-up 4 --stats -o " +
                                     quoted(dir / "c.png"));
  ASSERT_EQ(close.exit_code, 0) << close.err;
  EXPECT_NE(close.err.find("12 sides, tolerance 0.01 d; from the view: a loop spans 50 px of the close-up"), std::string::npos)
      << close.err;
  fs::remove_all(dir);
}

TEST(Cli, ChartCheckAndReference) {
  const auto chart = test::run_knitc("chart patterns/jersey.lua");
  ASSERT_EQ(chart.exit_code, 0) << chart.err;
  EXPECT_EQ(chart.out.rfind("# jersey: 24 rows on 20 stitches, flat", 0), 0u);
  EXPECT_NE(chart.out.find("24  | | | | | | | | | | | | | | | | | | | |\n"), std::string::npos);
  const auto check = test::run_knitc("check patterns/jersey.lua");
  EXPECT_EQ(check.exit_code, 0);
  EXPECT_EQ(check.err, "patterns/jersey.lua: 24 rows, 20 stitches cast on, 20 live at the end (bound off)\n");
  const auto dir = test::scratch_dir("check");
  test::write_text(dir / "loop.lua", "pattern { gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1 } } }\n"
                                     "while true do end\n");
  const auto loop = test::run_knitc("check --max-instructions 5 " + quoted(dir / "loop.lua"));
  EXPECT_EQ(loop.exit_code, 1);
  EXPECT_NE(loop.err.find("loop.lua:2: pattern ran too long (over 5 million"), std::string::npos) << loop.err;
  EXPECT_EQ(test::run_knitc("check --max-memory 0 " + quoted(dir / "loop.lua")).exit_code, 2);
  fs::remove_all(dir);
  const auto reference = test::run_knitc("reference");
  EXPECT_EQ(reference.exit_code, 0);
  EXPECT_TRUE(reference.out == test::read_text(fs::path(KNITC_SOURCE_DIR) / "docs/language.md"))
      << "docs/language.md is stale: run ./build/cli/knitc reference > docs/language.md";
}

TEST(Cli, VersionAndHelpExitZero) {
  const auto v = test::run_knitc("--version");
  EXPECT_EQ(v.exit_code, 0);
  EXPECT_EQ(v.out.rfind("knitc 0.", 0), 0u);
  EXPECT_EQ(test::run_knitc("build --help").exit_code, 0);
}

TEST(Cli, SameScriptGivesByteIdenticalFilesOnAnyThreadCount) {
  const fs::path dir = test::scratch_dir("determinism");
  // Two yarns and plies, so every path of the mesh builder runs.
  test::write_text(dir / "p.lua",
                   "pattern { gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = \"dk\" },\n"
                   "  B = { weight = \"dk\", section = \"plied\", plies = 3 } } }\n"
                   "cast_on(12)\nrows(3, \"k2, p2\")\nyarn \"B\"\nrows(3, \"k\")\n");
  // The jersey unrelaxed; the small pattern at the default, relaxed and pressed.
  for (const char* pattern : {"patterns/jersey.lua", "P"}) {
    const std::string source = std::string(pattern) == "P" ? quoted(dir / "p.lua") : std::string(pattern) + " --relax off";
    std::vector<std::string> glb, json, snap;
    for (const char* threads : {"", "--threads 1", "--threads 2", "--threads 7"}) {
      const auto r = test::run_knitc("build " + source + " -q " + threads + " -o " + quoted(dir / "a.glb") + " --centreline " +
                                     quoted(dir / "a.json"));
      ASSERT_EQ(r.exit_code, 0) << r.err;
      const auto s = test::run_knitc("snapshot " + source + " " + threads);
      ASSERT_EQ(s.exit_code, 0) << s.err;
      glb.push_back(test::read_text(dir / "a.glb"));
      json.push_back(test::read_text(dir / "a.json"));
      snap.push_back(s.out);
    }
    for (std::size_t i = 1; i < glb.size(); ++i) {
      EXPECT_TRUE(glb[i] == glb[0]) << pattern << " run " << i;
      EXPECT_TRUE(json[i] == json[0]) << pattern << " run " << i;
      EXPECT_EQ(snap[i], snap[0]) << pattern << " run " << i;
    }
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace knitc

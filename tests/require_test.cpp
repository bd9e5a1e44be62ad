// require: modules are found in the -I folders, the pattern's own lib/ and the library
// (patterns/lib), in that order; each runs once and reaches nothing else; a bad name, a
// missing or failing module, or a cycle is an error at the pattern's line.
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "runtime.hpp"
#include "support.hpp"

namespace knitc {
namespace {

namespace fs = std::filesystem;

const char* header = "pattern { name = \"m\", gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1.0 } } }\n";

TEST(ModulesRequire, AMissingModuleSaysWhereItLooked) {
  const std::string message = test::script_error(std::string(header) + "cast_on(4)\nlocal x = require \"nope\"\n");
  EXPECT_EQ(message.rfind("t.lua:3: module \"nope\" not found", 0), 0u) << message;
  EXPECT_NE(message.find((fs::path(KNITC_SOURCE_DIR) / "patterns" / "lib" / "nope.lua").string()), std::string::npos)
      << message;
}

TEST(ModulesRequire, NamesThatLeaveTheLibraryAreRefused) {
  for (const char* name : {"../secret", "a/b", "/etc/passwd", "a..b", ".hidden", "trailing.", "a\\\\b", ""}) {
    const std::string message = test::script_error(std::string(header) + "require \"" + name + "\"\n");
    EXPECT_EQ(message.rfind("t.lua:2: module name \"", 0), 0u) << name << " -> " << message;
    EXPECT_NE(message.find("must be letters, digits, _ and -, with dots between folders"), std::string::npos) << message;
  }
  EXPECT_EQ(test::script_error(std::string(header) + "require(42)\n"),
            "t.lua:2: require takes a module name, e.g. require \"cables\"");
}

// A scratch folder with some files in it.
fs::path folder_with(const std::string& name, const std::vector<std::pair<std::string, std::string>>& files) {
  const fs::path dir = test::scratch_dir(name);
  for (const auto& [path, text] : files) {
    fs::create_directories((dir / path).parent_path());
    test::write_text(dir / path, text);
  }
  return dir;
}

TEST(ModulesRequire, AnIncludeFolderWinsOverTheLibrary) {
  const fs::path first = folder_with("modules-first", {{"ribs.lua", "return { k2p2 = function(n) rows(n, \"k\") end, mine = 1 }\n"},
                                                       {"sub/deeper.lua", "return { depth = 2 }\n"}});
  const fs::path second = folder_with("modules-second", {{"ribs.lua", "return { mine = 2 }\n"},
                                                         {"only_here.lua", "return { here = true }\n"}});
  runtime::RunOptions options;
  options.module_dirs = {first.string(), second.string()};
  const std::string source = std::string(header) +
                             "local ribs = require \"ribs\"\n"
                             "assert(ribs.mine == 1, \"the first -I folder should win\")\n"
                             "assert(require(\"sub.deeper\").depth == 2, \"dots are folders\")\n"
                             "assert(require(\"only_here\").here, \"later folders are searched too\")\n"
                             "assert(require(\"cables\").rope, \"the library is still there\")\n"
                             "cast_on(12)\nribs.k2p2(3)\n";
  const Pattern p = runtime::run_pattern(source, "t.lua", options).pattern;
  EXPECT_EQ(p, test::run_with_library("round", 12, "rows(3, \"k\")"));
  fs::remove_all(first);
  fs::remove_all(second);
}

TEST(ModulesRequire, ThePatternsOwnLibFolderIsSearched) {
  const fs::path dir = folder_with(
      "modules-own-lib",
      {{"lib/stripes.lua", "return { band = function(n) rows(n, \"p\") end }\n"},
       {"lib/ribs.lua", "return { own = true }\n"},
       {"lib/trims/edge.lua", "return { edge = function() row \"k1, p1\" end }\n"},
       {"scarf.lua", std::string(header) +
                         "local stripes = require \"stripes\"\n"
                         "assert(require(\"ribs\").own, \"the pattern's lib/ wins over knitc's library\")\n"
                         "cast_on(6)\nstripes.band(2)\nrequire(\"trims.edge\").edge()\n"}});
  const Pattern p = runtime::run_pattern_file((dir / "scarf.lua").string()).pattern;
  EXPECT_EQ(p, test::run_with_library("round", 6, "rows(2, \"p\") row \"k1, p1\""));
  // -I folders come before the pattern's lib/.
  const fs::path include = folder_with("modules-include", {{"stripes.lua", "return { band = function(n) rows(n, \"k\") end }\n"}});
  runtime::RunOptions options;
  options.module_dirs = {include.string()};
  EXPECT_EQ(runtime::run_pattern_file((dir / "scarf.lua").string(), options).pattern,
            test::run_with_library("round", 6, "rows(2, \"k\") row \"k1, p1\""));
  // A script elsewhere does not see that lib/.
  const fs::path elsewhere = test::scratch_dir("modules-elsewhere");
  const std::string message = test::script_error(std::string(header) + "require \"stripes\"\n", (elsewhere / "other.lua").string());
  EXPECT_NE(message.find("module \"stripes\" not found"), std::string::npos) << message;
  fs::remove_all(elsewhere);
  fs::remove_all(dir);
  fs::remove_all(include);
}

TEST(ModulesRequire, AModuleRunsOnceAndRequireReturnsItsValue) {
  const fs::path dir = folder_with("modules-once", {{"counted.lua", "counter = (counter or 0) + 1\nreturn { n = counter }\n"},
                                                    {"silent.lua", "loaded_silent = true\n"}});
  runtime::RunOptions options;
  options.module_dirs = {dir.string()};
  const std::string source = std::string(header) +
                             "local a = require \"counted\"\nlocal b = require \"counted\"\n"
                             "assert(a == b and a.n == 1, \"the same table both times\")\n"
                             "assert(require \"silent\" == true and loaded_silent, \"a module returning nothing gives true\")\n"
                             "cast_on(4)\nrows(counter, \"k\")\n";
  EXPECT_EQ(runtime::run_pattern(source, "t.lua", options).pattern.courses.size(), 1u);
  fs::remove_all(dir);
}

TEST(ModulesRequire, AModuleThatRequiresItselfIsAClearError) {
  const fs::path dir = folder_with("modules-cycle", {{"selfish.lua", "local me = require \"selfish\"\nreturn {}\n"},
                                                     {"ping.lua", "require \"pong\"\nreturn {}\n"},
                                                     {"pong.lua", "require \"ping\"\nreturn {}\n"}});
  runtime::RunOptions options;
  options.module_dirs = {dir.string()};
  for (const char* name : {"selfish", "ping"}) {
    const std::string message = test::script_error(std::string(header) + "cast_on(4)\nrequire \"" + name + "\"\n", "t.lua", options);
    EXPECT_NE(message.find("requires itself, directly or through others"), std::string::npos) << message;
    EXPECT_NE(message.find(".lua:1: module \""), std::string::npos) << message;  // the module's own line
    EXPECT_NE(message.find("(called from t.lua:3)"), std::string::npos) << message;
  }
  fs::remove_all(dir);
}

TEST(ModulesRequire, AModuleCannotReachFilesOrTheSystem) {
  const fs::path dir = folder_with(
      "modules-sandbox",
      {{"peek.lua", "return { io = io, os = os, debug = debug, package = package, dofile = dofile, loadfile = loadfile }\n"},
       {"sneaky.lua", "local f = io.open(\"/etc/passwd\")\nreturn {}\n"},
       {"clock.lua", "return { now = function() return os.time() end }\n"}});
  runtime::RunOptions options;
  options.module_dirs = {dir.string()};
  const std::string start = std::string(header) + "cast_on(4)\nrow \"k\"\n";
  EXPECT_EQ(test::script_error(start + "for _, name in ipairs { \"io\", \"os\", \"debug\", \"package\", \"dofile\", \"loadfile\" } do\n"
                             "  assert(require(\"peek\")[name] == nil, name)\nend\n",
                     "t.lua", options),
            "");
  const std::string io = test::script_error(start + "require \"sneaky\"\n", "t.lua", options);
  EXPECT_NE(io.find("sneaky.lua:1: attempt to index a nil value (global 'io')"), std::string::npos) << io;
  const std::string os = test::script_error(start + "require(\"clock\").now()\n", "t.lua", options);
  EXPECT_NE(os.find("clock.lua:1: attempt to index a nil value (global 'os')"), std::string::npos) << os;
  fs::remove_all(dir);
}

TEST(ModulesRequire, AVerbFailingInAModuleNamesThePatternLineToo) {
  const fs::path dir = folder_with("modules-verb", {{"bad.lua", "return { go = function()\n  row \"k3\"\nend }\n"}});
  runtime::RunOptions options;
  options.module_dirs = {dir.string()};
  const std::string message =
      test::script_error(std::string(header) + "local bad = require \"bad\"\ncast_on(4)\nbad.go()\n", "t.lua", options);
  EXPECT_EQ(message.rfind((dir / "bad.lua").string() + ":2: ", 0), 0u) << message;
  EXPECT_NE(message.find("(called from t.lua:4)"), std::string::npos) << message;
  fs::remove_all(dir);
}

TEST(ModulesRequire, AModuleThatFailedToLoadFailsAgainWithItsOwnError) {
  const fs::path dir = folder_with("modules-broken", {{"broken.lua", "error(\"broken on purpose\")\n"}});
  runtime::RunOptions options;
  options.module_dirs = {dir.string()};
  const std::string message = test::script_error(
      std::string(header) + "local ok = pcall(require, \"broken\")\nassert(not ok)\nrequire \"broken\"\n", "t.lua", options);
  EXPECT_NE(message.find("broken.lua:1: broken on purpose"), std::string::npos) << message;
  fs::remove_all(dir);
}

TEST(ModulesRequire, RowsWorkedByALibraryFunctionAreLocatedAtThePatternsLine) {
  const fs::path dir = folder_with("modules-where", {{"knit.lua", "return { go = function()\n  row \"k\"\nend }\n"}});
  runtime::RunOptions options;
  options.module_dirs = {dir.string()};
  const auto result = runtime::run_pattern(std::string(header) + "local m = require \"knit\"\ncast_on(4)\nm.go()\n", "t.lua", options);
  ASSERT_EQ(result.pattern.courses.size(), 1u);
  EXPECT_EQ(result.pattern.courses[0].where.file, "t.lua");
  EXPECT_EQ(result.pattern.courses[0].where.line, 4);
  fs::remove_all(dir);
}

TEST(ModulesRequire, TheFilesReadAreTheWatchersList) {
  // knitc view watches these: the pattern and every module it required, also when a
  // module failed (mending the module must rebuild).
  const fs::path dir = folder_with("modules-files", {{"knit.lua", "return { go = function()\n  row \"k\"\nend }\n"},
                                                      {"broken.lua", "error(\"broken on purpose\")\n"}});
  runtime::RunOptions options;
  options.module_dirs = {dir.string()};
  const auto result = runtime::run_pattern(std::string(header) + "local m = require \"knit\"\ncast_on(4)\nm.go()\n", "t.lua", options);
  ASSERT_EQ(result.files.size(), 2u);
  EXPECT_EQ(result.files[0], "t.lua");
  EXPECT_EQ(fs::path(result.files[1]).filename(), "knit.lua");
  try {
    runtime::run_pattern(std::string(header) + "require \"knit\"\nrequire \"broken\"\n", "t.lua", options);
    FAIL() << "a broken module must fail the pattern";
  } catch (const runtime::PatternError& e) {
    ASSERT_EQ(e.files.size(), 3u);
    EXPECT_EQ(fs::path(e.files[2]).filename(), "broken.lua");
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace knitc

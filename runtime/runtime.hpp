// The runtime: runs a pattern script in a sandboxed Lua 5.4 state and returns the
// validated Pattern it describes. The only part of knitc that knows Lua.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "pattern.hpp"

namespace knitc::runtime {

// A script's budget (docs/security.md). Work and memory stop a script at the same place
// on every machine; the deadline is a wall-clock backstop for what they misjudge.
struct Limits {
  std::uint64_t instructions = 200'000'000;  // units of work: Lua VM instructions, and the
                                             // same in library calls; about a second
  std::size_t memory_bytes = 256u << 20;     // bytes the script may hold at once, in Lua
                                             // and in what the verbs keep for it
  double seconds = 3.0;                      // wall-clock time the script may run
  std::size_t string_bytes = 4u << 20;       // the longest string a script may make
};

struct RunOptions {
  Limits limits;
  // Where `require "name"` looks, in order, before the pattern's own lib/ folder and
  // knitc's library (patterns/lib). Nothing else of the file system is reachable.
  std::vector<std::string> module_dirs;
  std::optional<std::int64_t> seed;  // math.random's seed; else pattern{ seed = } or 0
  int max_tucks = 4;                 // tucks stacked on one needle before it is an error
  double max_float_mm = 25.0;        // floats longer than this are warned about
};

// A problem in a pattern script. what() is "file:line: what went wrong; what to do",
// printable (no control bytes, no overlong words) and bounded in length.
class PatternError : public std::runtime_error {
 public:
  explicit PatternError(const std::string& message, std::vector<std::string> warnings_before = {},
                        std::vector<std::string> files_read = {})
      : std::runtime_error(message), warnings(std::move(warnings_before)), files(std::move(files_read)) {}
  std::vector<std::string> warnings;  // the warnings given before the error, to print first
  std::vector<std::string> files;     // the pattern and the modules it required before the error
};

// A pattern file that cannot be read: missing, not a regular file, unreadable.
class FileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct RunResult {
  Pattern pattern;
  std::vector<std::string> warnings;  // "file:line: ..." each
  std::vector<std::string> files;     // the pattern's file and every module it required: what a watcher watches
};

// Runs `source` as the script `file` (the name messages use) and builds its Pattern.
// Throws PatternError for any problem in the script, its limits or its meaning.
RunResult run_pattern(std::string_view source, const std::string& file, const RunOptions& options = {});

// Reads the script at `path` and runs it. Throws FileError if the file cannot be read
// (only regular files are: never a FIFO or a device), PatternError for problems in it,
// including a file over the size a pattern may have (max_source_bytes).
RunResult run_pattern_file(const std::string& path, const RunOptions& options = {});

// A printed pattern read as a file of its own: the declaration a script would make, from
// the command line or these defaults (docs/printed.md).
struct PrintedOptions {
  std::optional<int> cast_on;        // else the text's "cast on N", its stated multiple, or row 1's
  double stitches_per_10cm = 22.0;   // the gauge
  double rows_per_10cm = 30.0;
  std::string weight = "dk";         // the yarn's weight (the weights of docs/language.md)
  std::string color = "#d9c8a9";
  std::optional<Knitting> knitting;  // else round when its rows are rounds ("Rnd 1:"), else flat
  // "garter", "chain" or "knit" (docs/stitches.md); else chain when the text says to slip
  // the first stitch of every row, else garter.
  std::optional<std::string> selvedge;
};

// Whether knitc reads `path` as a printed pattern rather than a script: any file but .lua.
bool is_printed_pattern(const std::string& path);

// Reads the printed pattern at `path` and works it as a knitspeak block (the knitspeak
// verb's reading) on a cast-on of `printed.cast_on`, else the count the text states
// ("Cast on 26 sts"), else its stated multiple ("multiple of 6 sts plus 3": the fewest
// repeats, at least two, that make 24 stitches or more), else the widths its row 1 fits
// (the first, from two repeats and 24 stitches up, on which every row comes out).
// Messages are "path:line: ..." at the text's own lines. Throws as run_pattern_file does.
RunResult run_printed_file(const std::string& path, const PrintedOptions& printed, const RunOptions& options = {});

// The largest pattern or module file knitc reads.
inline constexpr std::size_t max_source_bytes = 4u << 20;

// `text` fit to print in a message: control bytes, stray UTF-8 and bidirectional
// overrides written as escapes, any word over 200 bytes cut in its middle, and the
// whole at most `max_bytes` (cut in the middle, saying how much was left out).
std::string printable(std::string_view text, std::size_t max_bytes = 2000);

// The reference of the pattern language, as Markdown: every verb, stitch and chart
// symbol, generated from the tables that declare them (docs/language.md).
std::string language_reference();

}  // namespace knitc::runtime

// A printed pattern as a file of its own (`knitc build pattern.txt`): the text is worked
// as a knitspeak block under a declaration made from the options, through the same verbs
// a script calls, so every rule and message is the script's.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <regex>

#include "language/knitspeak.hpp"
#include "language/written.hpp"
#include "script.hpp"
#include "source_files.hpp"

namespace knitc::runtime {

namespace {

constexpr int smallest_swatch = 24;  // stitches: a cast-on found from a multiple is at least this
constexpr int largest_search = 400;  // stitches: the widest cast-on tried for an unstated multiple
constexpr int most_trials = 8;       // whole runs tried for an unstated multiple

std::string lowered(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

int whole(const std::string& digits) {
  if (digits.empty() || digits.size() > 6) return 0;
  return std::stoi(digits);
}

// The text's lines, each short enough to search (a statement is a line, not a page).
std::vector<std::string> short_lines(const std::string& low) {
  std::vector<std::string> out;
  for (std::size_t at = 0; at < low.size();) {
    const std::size_t end = std::min(low.find('\n', at), low.size());
    if (end - at <= 2000) out.push_back(low.substr(at, end - at));
    at = end + 1;
  }
  return out;
}

// "Cast on 26 sts", "CO 26".
std::optional<int> stated_cast_on(const std::string& low) {
  static const std::regex cast(R"((?:^|[^a-z])(?:cast on|co|worked over|cast-on count of)\s*(?:loosely\s+|a total of\s+)?:?\s*(\d{1,6})(?!\d))");
  for (const std::string& line : short_lines(low)) {
    std::smatch m;
    if (!std::regex_search(line, m, cast)) continue;
    const int n = whole(m[1]);
    if (n > 0) return n;
  }
  return std::nullopt;
}

// "a multiple of 6 sts plus 3", "multiple of 12 + 2", "(multiple of 4)", "Multiple: 8+1".
std::optional<std::pair<int, int>> stated_multiple(const std::string& low) {
  static const std::regex multiple(
      R"(mult(?:iple)?s?\s*(?:of|:)?\s*(\d{1,5})\s*(?:sts?|stitches)?(?:\s*,?\s*(?:\+|plus)\s*(\d{1,5}))?)");
  for (const std::string& line : short_lines(low)) {
    std::smatch m;
    if (!std::regex_search(line, m, multiple)) continue;
    const int n = whole(m[1]);
    if (n > 0) return std::pair{n, m[2].matched ? whole(m[2]) : 0};
  }
  return std::nullopt;
}

// Worked in the round when its rows are rounds ("Rnd 1:", "Round 3.").
bool in_rounds(const std::string& low) {
  static const std::regex round_label(R"(^\s*(?:rnds?|rounds?)\s*\d)");
  for (const std::string& line : short_lines(low))
    if (std::regex_search(line, round_label)) return true;
  return false;
}

// "Slip the first stitch of every row", "sl 1st st of each row": a chain selvedge.
bool says_chain_selvedge(const std::string& low) {
  static const std::regex slip(R"((?:slip|sl)\s+(?:the\s+)?(?:first|1st)\s+(?:st|stitch)\w*\s+(?:of\s+)?(?:every|each|all)\s+rows?)");
  for (const std::string& line : short_lines(low))
    if (std::regex_search(line, slip)) return true;
  return false;
}

// The script that works `text` as a printed pattern, all on its first line, so the text's
// line n is the file's line n. The text goes inside a long bracket no line of it can close.
std::string driver(const std::string& name, const PrintedOptions& o, Knitting knitting, const std::string& selvedge,
                   int cast_on, const std::string& text) {
  std::string level;
  while (text.find("]" + level + "]") != std::string::npos) level += '=';
  const std::string knitted = knitting == Knitting::flat ? "flat" : "round";
  return "pattern { name = \"" + name + "\", gauge = { stitches = " + show(o.stitches_per_10cm) +
         ", rows = " + show(o.rows_per_10cm) + " }, yarns = { A = { weight = \"" + o.weight + "\", color = \"" + o.color +
         "\" } }, knitting = \"" + knitted + "\", selvedge = \"" + selvedge + "\" } cast_on(" + std::to_string(cast_on) + ") knitspeak [" + level + "[" + text +
         "]" + level + "]";
}

// The cast-ons from 1 to largest_search that row 1 works and that leave the count it
// states, if it states one ("(15 sts)"); nothing when the text has no row 1 to read.
std::vector<int> fitting_row_one(const std::string& text) {
  const auto read = language::read_knitspeak(text, std::vector<std::string>{"A"});
  const auto* block = std::get_if<language::Knitspeak>(&read);
  if (!block || block->rows.empty()) return {};
  const language::KnitspeakRow& first = block->rows.front();
  const auto parsed = language::parse_row(first.text, std::vector<std::string>{"A"}, false);
  const auto* row = std::get_if<language::RowText>(&parsed);
  if (!row) return {};
  std::vector<int> out;
  for (int n = 1; n <= largest_search; ++n) {
    if (row->as_they_appear) {
      out.push_back(n);
      continue;
    }
    const auto worked = language::work_row(*row, first.text, n, 1);
    const auto* stitches = std::get_if<std::vector<language::Worked>>(&worked);
    if (!stitches) continue;
    int produced = 0;
    for (const language::Worked& w : *stitches) produced += stitch(w.stitch).produces;
    if (!first.stitches_after || *first.stitches_after == produced) out.push_back(n);
  }
  return out;
}

}  // namespace

bool is_printed_pattern(const std::string& path) { return std::filesystem::path(path).extension() != ".lua"; }

RunResult run_printed_file(const std::string& path, const PrintedOptions& printed, const RunOptions& options) {
  std::string text;
  try {
    text = read_source(path);
  } catch (const SourceTooLarge& e) {
    throw PatternError(printable(e.what()));
  }
  if (const std::string why = not_text(path, text); !why.empty()) throw PatternError(printable(why));
  // Lines that start with '#' are headings and notes (Markdown's, or a header the
  // designer keeps): blanked, so their words state nothing and the lines keep their numbers.
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t end = std::min(text.find('\n', at), text.size());
    if (text[at] == '#') std::fill(text.begin() + static_cast<std::ptrdiff_t>(at), text.begin() + static_cast<std::ptrdiff_t>(end), ' ');
    at = end + 1;
  }
  std::string name = std::filesystem::path(path).stem().string();
  name.erase(std::remove_if(name.begin(), name.end(), [](unsigned char c) { return !std::isalnum(c) && c != '_' && c != '-'; }),
             name.end());
  if (name.empty()) name = "printed";
  const std::string low = lowered(text);
  const Knitting knitting = printed.knitting.value_or(in_rounds(low) ? Knitting::round : Knitting::flat);
  const std::string selvedge = printed.selvedge.value_or(says_chain_selvedge(low) ? "chain" : "garter");
  auto run = [&](int cast_on) { return run_pattern(driver(name, printed, knitting, selvedge, cast_on, text), path, options); };

  if (printed.cast_on) return run(*printed.cast_on);
  if (const auto n = stated_cast_on(low)) return run(*n);
  // The widths row 1 fits (of the stated multiple, where one is stated and any fits),
  // from two of its repeats and the swatch's width up, tried in turn until every row
  // comes out.
  std::vector<int> fits = fitting_row_one(text);
  if (const auto m = stated_multiple(low)) {
    const auto [every, plus] = *m;
    std::vector<int> of_multiple;
    for (int n : fits)
      if (n % every == plus % every && n >= plus) of_multiple.push_back(n);
    if (!of_multiple.empty()) fits = std::move(of_multiple);
    else if (fits.empty()) {
      int repeats = 2;
      while (every * repeats + plus < smallest_swatch) ++repeats;
      return run(every * repeats + plus);  // its message says what does not fit
    }
  }
  if (fits.empty()) {
    // Let the run say what is wrong with the text at the smallest swatch.
    run(smallest_swatch);
    throw PatternError(path + ":1: row 1 fits no cast-on up to " + std::to_string(largest_search) +
                       " stitches; state the multiple (\"multiple of 4 sts plus 2\") or give --cast-on N");
  }
  const int period = fits.size() > 1 ? fits[1] - fits[0] : 0;
  const int least = std::max(smallest_swatch, fits[0] + period);
  std::optional<PatternError> first_error;
  int trials = 0;
  for (int n : fits) {
    if (n < least && n != fits.back()) continue;
    try {
      return run(n);
    } catch (const PatternError& e) {
      if (!first_error) first_error = e;
    }
    if (++trials == most_trials) break;
  }
  throw *first_error;
}

}  // namespace knitc::runtime

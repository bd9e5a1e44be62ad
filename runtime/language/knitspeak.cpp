#include "language/knitspeak.hpp"
#include "language/knitspeak_lines.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <map>
#include <regex>

#include "language/spelling.hpp"
#include "language/written.hpp"

namespace knitc::language {

namespace {

constexpr std::size_t max_block_rows = 100'000;             // rows a block expands to
constexpr std::size_t max_block_text_bytes = 16u << 20;     // bytes of those rows' texts

using namespace knitspeak_lines;

// Reading a block line by line: numbered rows are gathered and worked in number order,
// repeats and unnumbered rows where they stand. Each step returns false on an error
// (kept in `error`).
class Reader {
 public:
  explicit Reader(std::span<const std::string> yarn_ids) : yarn_ids_(yarn_ids) {}

  // "Row 1 (RS): ...", "Rows 5-8: Repeat rows 1-4."
  bool label(int line, const Label& l) {
    std::string problem;
    const auto again = repeated_rows(l.body, problem);
    if (!problem.empty()) return fail(line, problem);
    std::optional<int> count;
    const std::string text = again ? std::string() : without_count(l.body, count);
    if (!again && text.empty()) return fail(line, "row " + std::to_string(l.rows.front()) + " has no stitches after its label");
    // "3rd to 8th rows: Rep 1st and 2nd rows 3 times more": the rows repeated in turn.
    if (again && again->size() > l.rows.size())
      return fail(line, std::to_string(l.rows.size()) + " rows repeat " + std::to_string(again->size()) +
                            "; give as many rows as they repeat (Rows 5-8: Repeat rows 1-4)");
    // "Rib: Row 1 ... Pattern: Row 1 ...": a row 1 after a part of two rows or more starts
    // the next part, numbered afresh (after a single row it is more likely a typo).
    if (l.rows.front() == 1 && (given_.count(1) || emitted_.count(1)) && !again && given_.size() + emitted_.size() >= 2) {
      if (!flush()) return false;
      if (!given_.empty()) return gap();
      emitted_.clear();
      other_.reset();
      next_number_ = 0;
    }
    for (std::size_t i = 0; i < l.rows.size(); ++i) {
      const int n = l.rows[i];
      if (given_.count(n) || emitted_.count(n)) return fail(line, "row " + std::to_string(n) + " is given twice");
      given_[n] = Given{line, text, l.side, count, again ? std::optional<int>((*again)[i % again->size()]) : std::nullopt};
    }
    if (l.every_other) {
      if (other_) return fail(line, "a second text for every other row; the one at line " + std::to_string(other_->given.line + 1) + " is given");
      other_ = Other{l.rows.front() % 2, given_[l.rows.front()]};
    }
    return true;
  }

  // "On WS rows, work sts as they appear": the text of every wrong-side row not given.
  bool wrong_side_rows(int line, const std::string& text) {
    if (other_) return fail(line, "a second text for every other row; the one at line " + std::to_string(other_->given.line + 1) + " is given");
    other_ = Other{-1, Given{line, text, Side::wrong, std::nullopt, std::nullopt}};
    return true;
  }

  void define(GlossaryEntry e) {
    if (out_.glossary.size() < max_glossary) out_.glossary.push_back(std::move(e));
  }

  // "Repeat rows 3-6." where it stands: those rows once more.
  bool repeat(int line, const std::vector<int>& rows) {
    if (!flush()) return false;
    for (int n : rows) {
      const auto it = emitted_.find(n);
      if (it == emitted_.end()) return fail(line, "repeats row " + std::to_string(n) + ", which has not been given before this line");
      if (!room(line, out_.rows[it->second].text.size())) return false;
      KnitspeakRow r = out_.rows[it->second];
      r.line = line;
      r.repeat = true;
      out_.rows.push_back(std::move(r));
    }
    return true;
  }

  // A line that is not a row, whatever it reads as: skipped with a warning.
  bool note(int line, std::string_view text_line) {
    out_.skipped.push_back({line, "not a row, skipped: " + quote_row(text_line)});
    return true;
  }

  // An unnumbered line: a row if it parses as one (no hint needed: only asking), else
  // skipped with a warning.
  bool unnumbered(int line, std::string_view text_line) {
    std::optional<int> count;
    const std::string text = without_count(std::string(text_line), count);
    if (text.empty() || parse_row(text, yarn_ids_, false).index() != 0) {
      out_.skipped.push_back({line, "not a row, skipped: " + quote_row(text_line)});
      return true;
    }
    if (!flush() || !room(line, text.size())) return false;
    KnitspeakRow r;
    r.line = line;
    r.text = text;
    r.stitches_after = count;
    out_.rows.push_back(std::move(r));
    return true;
  }

  // The first row given after a row never given.
  bool gap() {
    const auto& [n, g] = *given_.begin();
    return fail(g.line, "row " + std::to_string(n) + " is given but row " + std::to_string(next_number_) +
                            " never is; number the rows without a gap");
  }

  bool fail(int line, std::string message) {
    error_ = KnitspeakNote{line, std::move(message)};
    return false;
  }

  std::variant<Knitspeak, KnitspeakNote> finish() {
    if (error_ || !flush()) return *error_;
    // A text for every other row, after a last row of the other side: the pair completed.
    if (other_ && given_.empty() && next_number_ > 1 && parity(next_number_) == other_parity() && !emit(next_number_, other_->given))
      return *error_;
    for (KnitspeakRow& r : out_.rows) r.text = with_crosses_in_words(with_glossary(r.text, out_.glossary));
    if (!given_.empty()) {
      gap();
      return *error_;
    }
    return std::move(out_);
  }

 private:
  struct Given {
    int line;
    std::string text;
    std::optional<Side> side;
    std::optional<int> count;
    std::optional<int> same_as;  // "Rows 5-8: Repeat rows 1-4": row 5 is row 1
  };

  // The rows a block may expand to, and the bytes of their texts: a few lines of
  // "Repeat rows 1-99999." must not fill memory before a single row is worked.
  bool room(int line, std::size_t bytes) {
    text_bytes_ += bytes;
    if (out_.rows.size() >= max_block_rows)
      return fail(line, "the text comes to more than " + std::to_string(max_block_rows) + " rows");
    if (text_bytes_ > max_block_text_bytes)
      return fail(line, "the text's rows come to more than " + std::to_string(max_block_text_bytes >> 20) + " MiB of instructions");
    return true;
  }

  bool emit(int number, const Given& g) {
    if (!room(g.line, g.text.size())) return false;
    if (out_.rows.empty() && g.side) first_side_ = *g.side;
    KnitspeakRow r;
    r.line = g.line;
    r.number = number;
    r.side = g.side;
    r.stitches_after = g.count;
    if (g.same_as) {
      const auto it = emitted_.find(*g.same_as);
      if (it == emitted_.end())
        return fail(g.line, "row " + std::to_string(number) + " repeats row " + std::to_string(*g.same_as) +
                                ", which comes later or not at all; repeat rows already worked");
      const KnitspeakRow& source = out_.rows[it->second];
      r.text = source.text;
      if (!r.side && source.side) r.side = source.side;
      if (!r.stitches_after) r.stitches_after = source.stitches_after;
    } else {
      r.text = g.text;
    }
    emitted_[number] = out_.rows.size();
    out_.rows.push_back(std::move(r));
    return true;
  }

  // Works the numbered rows given so far, in order, from the next one on; a row not given
  // is the text for every other row, where there is one for its side.
  bool flush() {
    if (next_number_ == 0 && !given_.empty()) next_number_ = given_.begin()->first;
    while (!given_.empty()) {
      const auto it = given_.find(next_number_);
      if (it != given_.end()) {
        if (!emit(next_number_, it->second)) return false;
        given_.erase(it);
      } else if (other_ && parity(next_number_) == other_parity()) {
        if (!emit(next_number_, other_->given)) return false;
      } else {
        break;
      }
      ++next_number_;
    }
    return true;
  }

  static int parity(int n) { return n % 2; }
  // The rows the text for every other row stands for: those of its own row's parity, or
  // the wrong-side rows (even, unless the first row was printed as a wrong-side row).
  int other_parity() const {
    if (other_->parity >= 0) return other_->parity;
    return first_side_ == Side::wrong ? 1 : 0;
  }

  std::span<const std::string> yarn_ids_;
  Knitspeak out_;
  std::map<int, Given> given_;          // by number: rows are worked in number order
  std::map<int, std::size_t> emitted_;  // number -> index in out_.rows
  struct Other {
    int parity;  // of the rows it stands for; -1: the wrong-side rows
    Given given;
  };
  std::optional<Other> other_;          // "Row 2 (and every WS row): ..."
  Side first_side_ = Side::right;
  int next_number_ = 0;                 // the next numbered row to work; 0 until the first
  std::size_t text_bytes_ = 0;
  std::optional<KnitspeakNote> error_;
};

}  // namespace

std::variant<Knitspeak, KnitspeakNote> read_knitspeak(std::string_view block, std::span<const std::string> yarn_ids) {
  Reader reader(yarn_ids);
  for (const auto& [line_number, plain] : plain_lines(block)) {
    bool ok = true;
    for (const std::string_view piece : paragraph_rows(trim(plain))) {
      const std::string_view line = without_bullet(piece);
      if (line.empty() || is_fence(line)) continue;
      std::string problem;  // a row list that cannot be honoured
      if (const auto l = label(line, problem)) {
        ok = reader.label(line_number, *l);
      } else if (!problem.empty()) {
        ok = reader.fail(line_number, problem);
      } else if (const auto again = repeated_rows(line, problem)) {
        ok = reader.repeat(line_number, *again);
      } else if (!problem.empty()) {
        ok = reader.fail(line_number, problem);
      } else if (const auto text = wrong_side_text(line)) {
        std::optional<int> count;
        ok = reader.wrong_side_rows(line_number, without_count(*text, count));
      } else if (auto entry = read_glossary_line(line, line_number)) {
        if (!entry->known) reader.define(std::move(*entry));
        ok = reader.note(line_number, line);  // a glossary line is no row
      } else {
        ok = reader.unnumbered(line_number, line);
      }
      if (!ok) break;
    }
    if (!ok) break;
  }
  return reader.finish();
}

}  // namespace knitc::language

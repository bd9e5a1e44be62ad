// The work, as knitters say: the fabric knitted so far and the stitches on the needle.
// The verbs drive it; it keeps the knitting's state and rules (the live count, how each
// live stitch shows on the face, which side a row is worked from, the limits) without Lua,
// so it can be fuzzed alone. Every change is all or nothing: a call that fails changes
// nothing, and mark() / restore() undo a whole verb.
#pragma once

#include <optional>
#include <variant>
#include <string>
#include <string_view>
#include <vector>

#include "language/written.hpp"
#include "pattern.hpp"

namespace knitc::language {

// How an edge stitch ("edge st", "selvedge st", "sel st") is worked: knitted at both ends
// of every row (garter, the default: a ridge every other row); the first slipped knitwise
// and the last knitted (chain: one long loop every two rows); or knitted on right-side
// rows and purled on wrong-side ones (knit: the edge shows as a knit stitch on the face).
enum class Selvedge { garter, chain, knit };

class Work {
 public:
  struct Limits {
    long long stitches = limits::stitches_on_needle;  // on the needle, after any course
    long long loops = limits::script_loops;           // in the whole fabric, the cast-on's too
  };

  Work() = default;
  // The declared pattern (name, gauge, yarns, knitting), with no courses yet.
  Work(Pattern declared, Limits limits);

  const Pattern& pattern() const { return pattern_; }
  Pattern take() { return std::move(pattern_); }
  int live() const { return live_; }
  int yarn() const { return yarn_; }  // the yarn being knitted, an index into pattern().yarns
  int next_row() const { return static_cast<int>(pattern_.courses.size()) + 1; }
  // The side row `row` (1 for the first) is worked from: every row in the round; in flat
  // knitting the odd rows, or the even ones when row 1 was worked from the wrong side.
  Side side_of(int row) const;
  int cast_on_line() const { return cast_on_line_; }
  int bind_off_line() const { return bind_off_line_; }

  // Each returns what is wrong, or nothing when done; a call that fails changes nothing.
  std::optional<std::string> cast_on(int stitches, int yarn, int line);
  // `plated`: a second yarn knitted into every loop the yarn makes, on the loops'
  // technical face (plating), or -1.
  void change_yarn(int yarn, int plated = -1) { yarn_ = yarn, plated_ = plated; }
  int plated() const { return plated_; }
  void set_selvedge(Selvedge s) { selvedge_ = s; }
  Selvedge selvedge() const { return selvedge_; }
  // Row 1 is worked from the wrong side (knitspeak's "Row 1 (WS):"); before any row.
  std::optional<std::string> start_on_wrong_side();
  // Why no row can be worked now ("no live stitches ..."), or nothing.
  std::optional<std::string> no_live_stitches() const;
  const std::vector<int>& markers() const { return markers_; }
  // Works written instructions (parsed from `source`) across the live stitches in the
  // current yarn as the next row, from `where`.
  std::optional<std::string> work_text(const RowText& text, std::string_view source, const SourceLocation& where);
  // Adds a course given in face view: it must work exactly the live stitches; checks what
  // it leaves on the needle.
  std::optional<std::string> add(std::vector<Op> ops, const SourceLocation& where);
  std::optional<std::string> bind_off(int line);

  // What a course of these stitches takes from the heap once added, for the caller's
  // memory cap: the course, its stitches, its file name, and the list's next growth.
  std::size_t cost(std::size_t stitches, const SourceLocation& where) const;

  // A point to come back to: the work as it was before a verb. Marks nest: restoring one
  // undoes everything since, and the marks taken since are spent.
  struct Mark {
    std::size_t courses = 0;
    int live = 0, yarn = 0, plated = -1, cast_on = 0, cast_on_yarn = 0, cast_on_line = 0, bind_off_line = 0;
    long long loops = 0;
    bool bound_off = false, wrong_side_first = false;
    std::vector<bool> purl_faced;
    std::vector<int> markers;
  };
  Mark mark() const;
  void restore(const Mark& m);

 private:
  Pattern pattern_;
  Limits limits_;
  int live_ = 0;
  int yarn_ = 0;
  int plated_ = -1;
  long long loops_ = 0;
  int cast_on_line_ = 0, bind_off_line_ = 0;
  bool wrong_side_first_ = false;
  Selvedge selvedge_ = Selvedge::garter;
  std::vector<bool> purl_faced_;  // per live stitch, face order: shows as a purl on the face
  // Stitch markers on the needle, as face-view gaps: k is between live stitches k - 1 and
  // k. Every course carries them along; rows place, slip and remove them.
  std::vector<int> markers_;

  // A row with markers, part by part, in working order: its stitches, the markers it
  // places (gaps in the row's working order after it) and those it removes (face-view
  // gaps before it).
  struct MarkedRow {
    std::vector<Worked> stitches;
    std::vector<std::size_t> placed;  // after how many of the stitches
    std::vector<int> removed;
  };
  std::variant<MarkedRow, std::string> work_parts(const RowText& text, std::string_view source, int row) const;
};

}  // namespace knitc::language

#include "language/work.hpp"

#include <algorithm>

namespace knitc::language {

namespace {

// How each live stitch shows on the face after a course: what "knit the knit sts and
// purl the purl sts" reads. A slipped or tucked stitch keeps the look of the one below.
std::vector<bool> faces_after(const Course& c, const std::vector<bool>& below) {
  std::vector<bool> out;
  std::size_t at = 0;
  for (const Op& op : c.ops) {
    const StitchDef& st = stitch(op.stitch);
    const bool purl = purled(st);
    for (int k = 0; k < st.produces; ++k) {
      const bool kept = st.family == StitchFamily::slip || st.family == StitchFamily::tuck;
      out.push_back(kept && at + static_cast<std::size_t>(k) < below.size() ? below[at + static_cast<std::size_t>(k)] : purl);
    }
    at += static_cast<std::size_t>(st.consumes);
  }
  return out;
}

}  // namespace

Work::Work(Pattern declared, Limits limits) : pattern_(std::move(declared)), limits_(limits) {
  pattern_.courses.clear();
  pattern_.cast_on = 0;
  pattern_.bound_off = false;
}

Side Work::side_of(int row) const {
  return pattern_.knitting == Knitting::flat && (row + (wrong_side_first_ ? 1 : 0)) % 2 == 0 ? Side::wrong : Side::right;
}

std::optional<std::string> Work::cast_on(int stitches, int yarn, int line) {
  if (cast_on_line_ != 0) return "cast_on was already called at line " + std::to_string(cast_on_line_);
  if (stitches < 1 || stitches > limits_.stitches)
    return "cast_on's stitch count is " + std::to_string(stitches) + "; it must be from 1 to " + std::to_string(limits_.stitches);
  live_ = stitches;
  yarn_ = yarn;
  loops_ = stitches;  // the cast-on's loops count, as loops_of counts them
  pattern_.cast_on = stitches;
  pattern_.cast_on_yarn = yarn;
  purl_faced_.assign(static_cast<std::size_t>(stitches), false);
  cast_on_line_ = line;
  return std::nullopt;
}

std::optional<std::string> Work::start_on_wrong_side() {
  if (!pattern_.courses.empty()) return std::string("only the first row can be worked from the wrong side first");
  if (pattern_.knitting == Knitting::flat) wrong_side_first_ = true;
  return std::nullopt;
}

std::optional<std::string> Work::no_live_stitches() const {
  if (live_ > 0) return std::nullopt;
  if (bind_off_line_ != 0) return "no live stitches: all were bound off at line " + std::to_string(bind_off_line_);
  if (cast_on_line_ == 0) return std::string("no live stitches; call cast_on(n) first");
  return std::string("no live stitches are left; the rows before decreased them all");
}

std::optional<std::string> Work::work_text(const RowText& text, std::string_view source, const SourceLocation& where) {
  if (auto e = no_live_stitches()) return e;
  // "(WS) k2, p2": a first row printed so turns the work first (undone if the row fails);
  // later, it is checked.
  if (text.side && pattern_.knitting == Knitting::flat) {
    const bool turn = pattern_.courses.empty() && *text.side == Side::wrong && !wrong_side_first_;
    if (turn) wrong_side_first_ = true;
    if (*text.side != side_of(next_row()))
      return "row " + std::to_string(next_row()) + " " + quote_row(source) + " is printed as a " +
             (*text.side == Side::right ? "right" : "wrong") + "-side row but is a " +
             (*text.side == Side::right ? "wrong" : "right") + "-side row of the fabric; check the rows before it";
    RowText rest = text;
    rest.side.reset();
    auto e = work_text(rest, source, where);
    if (e && turn) wrong_side_first_ = false;
    return e;
  }
  const int row = next_row();
  if (text.as_they_appear) {  // face view directly: each stitch keeps the look it has
    std::vector<Op> ops;
    for (int i = 0; i < live_; ++i) {
      const bool purl = static_cast<std::size_t>(i) < purl_faced_.size() && purl_faced_[static_cast<std::size_t>(i)];
      ops.push_back({stitch_id(purl != text.opposite ? "p" : "k"), yarn_});
    }
    return add(std::move(ops), where);
  }
  auto worked = work_row(text, source, live_, row);
  if (auto* e = std::get_if<TextError>(&worked)) return e->message;
  std::vector<Worked>& stitches = std::get<std::vector<Worked>>(worked);
  for (std::size_t i = 0; i < stitches.size(); ++i) {
    Worked& w = stitches[i];
    if (!w.edge) continue;
    const bool first = i == 0, last = i + 1 == stitches.size();
    if (!first && !last)
      return "row " + std::to_string(row) + " " + quote_row(source) +
             ": an edge stitch belongs at the start or the end of a row, not in its middle";
    const char* name = "k";
    if (selvedge_ == Selvedge::chain && first) name = "sl wyib";
    if (selvedge_ == Selvedge::knit && side_of(row) == Side::wrong) name = "p";
    w = {stitch_id(name), w.yarn, false};
  }
  auto ops = face_view(stitches, side_of(row), yarn_);
  if (auto* e = std::get_if<TextError>(&ops)) return "row " + std::to_string(row) + " " + quote_row(source) + " is a wrong-side row: " + e->message;
  return add(std::move(std::get<std::vector<Op>>(ops)), where);
}

std::optional<std::string> Work::add(std::vector<Op> ops, const SourceLocation& where) {
  if (auto e = no_live_stitches()) return e;
  Course c;
  c.ops = std::move(ops);
  c.side = side_of(next_row());
  c.where = where;
  if (c.ops.empty()) return "row " + std::to_string(next_row()) + " has no stitches";
  if (const int worked = consumed(c); worked != live_)
    return "row " + std::to_string(next_row()) + " works " + std::to_string(worked) + " stitches but " + std::to_string(live_) +
           " are live";
  const int live = produced(c);
  if (live > limits_.stitches)
    return "row " + std::to_string(next_row()) + " leaves " + std::to_string(live) + " stitches; at most " +
           std::to_string(limits_.stitches) + " fit on a needle";
  if (loops_ + live > limits_.loops)
    return "the fabric would have more than " + std::to_string(limits_.loops) + " loops; knit a smaller piece";
  loops_ += live;
  live_ = live;
  purl_faced_ = faces_after(c, purl_faced_);
  pattern_.courses.push_back(std::move(c));
  return std::nullopt;
}

std::optional<std::string> Work::bind_off(int line) {
  if (auto e = no_live_stitches()) return e;
  if (pattern_.courses.empty()) return std::string("bind_off right after cast_on leaves no fabric; knit some rows first");
  pattern_.bound_off = true;
  live_ = 0;
  bind_off_line_ = line;
  return std::nullopt;
}

std::size_t Work::cost(std::size_t stitches, const SourceLocation& where) const {
  // The course's own blocks (and malloc's keeping of them), and the list's next growth.
  std::size_t bytes = sizeof(Course) + stitches * sizeof(Op) + where.file.capacity() + 32;
  const auto& courses = pattern_.courses;
  if (courses.size() == courses.capacity()) bytes += std::max<std::size_t>(1, courses.capacity()) * sizeof(Course);
  return bytes;
}

Work::Mark Work::mark() const {
  return {pattern_.courses.size(), live_, yarn_, pattern_.cast_on, pattern_.cast_on_yarn, cast_on_line_, bind_off_line_,
          loops_, pattern_.bound_off, wrong_side_first_, purl_faced_};
}

void Work::restore(const Mark& m) {
  pattern_.courses.resize(std::min(pattern_.courses.size(), m.courses));
  live_ = m.live;
  yarn_ = m.yarn;
  pattern_.cast_on = m.cast_on;
  pattern_.cast_on_yarn = m.cast_on_yarn;
  cast_on_line_ = m.cast_on_line;
  bind_off_line_ = m.bind_off_line;
  loops_ = m.loops;
  pattern_.bound_off = m.bound_off;
  wrong_side_first_ = m.wrong_side_first;
  purl_faced_ = m.purl_faced;
}

}  // namespace knitc::language

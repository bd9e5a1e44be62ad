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

// Where each marker lies after a course: between the same stitches, the stitches made
// before it counted; one inside a stitch that works across it (k2tog over a marker)
// moves to after that stitch.
std::vector<int> markers_after(const Course& c, const std::vector<int>& markers) {
  std::vector<int> out;
  for (int gap : markers) {
    int taken = 0, made = 0;
    for (const Op& op : c.ops) {
      if (taken >= gap) break;
      taken += stitch(op.stitch).consumes;
      made += stitch(op.stitch).produces;
    }
    out.push_back(made);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
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
  MarkedRow marked;
  if (!text.parts.empty()) {
    auto parts = work_parts(text, source, row);
    if (auto* e = std::get_if<std::string>(&parts)) return *e;
    marked = std::move(std::get<MarkedRow>(parts));
  } else {
    auto worked = work_row(text, source, live_, row);
    if (auto* e = std::get_if<TextError>(&worked)) return e->message;
    marked.stitches = std::move(std::get<std::vector<Worked>>(worked));
  }
  std::vector<Worked>& stitches = marked.stitches;
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
  const std::vector<int> before = markers_;
  for (int gap : marked.removed) markers_.erase(std::remove(markers_.begin(), markers_.end(), gap), markers_.end());
  if (auto e = add(std::move(std::get<std::vector<Op>>(ops)), where)) {
    markers_ = before;
    return e;
  }
  // The markers placed: after so many of the row's stitches in working order, so many
  // stitches made; a right-side row works from the right edge.
  for (std::size_t after : marked.placed) {
    int made = 0;
    for (std::size_t i = 0; i < after; ++i) made += stitch(stitches[i].stitch).produces;
    markers_.push_back(side_of(row) == Side::right ? live_ - made : made);
  }
  std::sort(markers_.begin(), markers_.end());
  markers_.erase(std::unique(markers_.begin(), markers_.end()), markers_.end());
  return std::nullopt;
}

std::variant<Work::MarkedRow, std::string> Work::work_parts(const RowText& text, std::string_view source, int row) const {
  const bool leftwards = side_of(row) == Side::right;  // worked from the right edge
  // The markers in the row's working order: how many live stitches lie before each.
  std::vector<int> ahead;
  for (int gap : markers_) ahead.push_back(leftwards ? live_ - gap : gap);
  std::sort(ahead.begin(), ahead.end());
  auto to_face = [&](int worked) { return leftwards ? live_ - worked : worked; };
  const std::string name = "row " + std::to_string(row) + " " + quote_row(source);
  MarkedRow out;
  int at = 0;  // live stitches worked so far
  for (const MarkedPart& part : text.parts) {
    const RowText& t = part.text;
    // The marker this part works to: the next after where it starts ("k to m" just after
    // a marker means the one after it); a slip or a removal takes one right there too.
    const bool here = part.end == MarkerEnd::slip || part.end == MarkerEnd::remove;
    const auto next = std::find_if(ahead.begin(), ahead.end(), [&](int m) { return here ? m >= at : m > at; });
    const bool marked = next != ahead.end();
    const bool repeats = t.star.has_value();
    int room = 0;
    switch (part.end) {
      case MarkerEnd::row_end: room = live_ - at; break;
      case MarkerEnd::place: room = repeats ? (marked ? *next : live_) - at : 0; break;
      default:
        if (!marked)
          return name + (part.end == MarkerEnd::slip || part.end == MarkerEnd::remove ? " slips or removes a marker"
                                                                                      : " works to a marker") +
                 ", but no marker lies ahead " + (at == 0 ? "" : "after " + std::to_string(at) + " stitches ") +
                 "on the needle; place one with pm on an earlier row";
        room = *next - at - (part.end == MarkerEnd::before_marker ? part.before : 0);
        if (room < 0)
          return name + " works to " + std::to_string(part.before) + " stitches before a marker only " +
                 std::to_string(*next - at) + " stitches on";
        break;
    }
    // "*k3; rep from * to last 3 sts, pm, k to end": what its own closing stitches leave
    // of those is the rest's, past the marker it places.
    if (repeats && t.to_last && part.end == MarkerEnd::place) {
      RowText closing;
      closing.before = t.after;
      auto c = work_once(closing, source, row);
      if (auto* e = std::get_if<TextError>(&c)) return e->message;
      room -= std::max(0, *t.to_last - consumed(std::get<std::vector<Worked>>(c)));
    }
    std::vector<Worked> worked;
    if (repeats) {
      RowText filled = t;
      if (part.end == MarkerEnd::place) filled.to_last.reset();  // the room says it now
      auto w = work_row(filled, source, room, row);
      if (auto* e = std::get_if<TextError>(&w)) return e->message;
      worked = std::move(std::get<std::vector<Worked>>(w));
    } else if (!t.before.empty()) {
      // Fixed stitches: before a marker placed or slipped, worked once, and they must
      // reach it; to the row's end, repeated across as any row without a repeat is.
      auto w = part.end == MarkerEnd::row_end ? work_row(t, source, room, row) : work_once(t, source, row);
      if (auto* e = std::get_if<TextError>(&w)) return e->message;
      worked = std::move(std::get<std::vector<Worked>>(w));
    }
    if (part.end != MarkerEnd::place && part.end != MarkerEnd::row_end && consumed(worked) != room)
      return name + " works " + std::to_string(consumed(worked)) + " stitches before a marker " + std::to_string(room) +
             " stitches on; make them agree";
    out.stitches.insert(out.stitches.end(), worked.begin(), worked.end());
    at += consumed(worked);
    if (part.end == MarkerEnd::place) out.placed.push_back(out.stitches.size());
    if (part.end == MarkerEnd::remove) out.removed.push_back(to_face(at));
  }
  if (at != live_)
    return name + " works " + std::to_string(at) + " stitches but " + std::to_string(live_) + " are live";
  return out;
}

std::optional<std::string> Work::add(std::vector<Op> ops, const SourceLocation& where) {
  if (auto e = no_live_stitches()) return e;
  Course c;
  c.ops = std::move(ops);
  // Plating: the working yarn's stitches take the plating yarn with them.
  if (plated_ >= 0)
    for (Op& op : c.ops)
      if (op.yarn == yarn_ && op.plated < 0) op.plated = plated_;
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
  markers_ = markers_after(c, markers_);
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
  return {pattern_.courses.size(), live_, yarn_, plated_, pattern_.cast_on, pattern_.cast_on_yarn, cast_on_line_, bind_off_line_,
          loops_, pattern_.bound_off, wrong_side_first_, purl_faced_, markers_};
}

void Work::restore(const Mark& m) {
  pattern_.courses.resize(std::min(pattern_.courses.size(), m.courses));
  live_ = m.live;
  yarn_ = m.yarn;
  plated_ = m.plated;
  pattern_.cast_on = m.cast_on;
  pattern_.cast_on_yarn = m.cast_on_yarn;
  cast_on_line_ = m.cast_on_line;
  bind_off_line_ = m.bind_off_line;
  loops_ = m.loops;
  pattern_.bound_off = m.bound_off;
  wrong_side_first_ = m.wrong_side_first;
  purl_faced_ = m.purl_faced;
  markers_ = m.markers;
}

}  // namespace knitc::language

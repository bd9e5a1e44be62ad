// Working a parsed row across the live stitches: repeats filled, counts checked, and the
// worked stitches turned into face-view ops for the side the row is worked from.
#include <algorithm>

#include "language/written.hpp"

namespace knitc::language {

namespace {

void flatten(const Sequence& seq, std::vector<Worked>& out, std::size_t limit) {
  for (const Element& e : seq) {
    for (int i = 0; i < e.count && out.size() <= limit; ++i) {
      if (e.is_group) flatten(e.body, out, limit);
      else out.push_back(e.stitch);
    }
  }
}

std::string stitches(int n) { return std::to_string(n) + (n == 1 ? " stitch" : " stitches"); }
std::string sts(int n) { return std::to_string(n) + (n == 1 ? " st" : " sts"); }

std::string over_or_short(int left) {
  return left > 0 ? std::to_string(left) + " left over" : std::to_string(-left) + " missing";
}

}  // namespace

int consumed(std::span<const Worked> worked) {
  int n = 0;
  for (const Worked& w : worked) n += stitch(w.stitch).consumes;
  return n;
}

namespace {

// When a row runs out of stitches partway through a stitch that works several (a
// decrease or a cable at the edge), the message names that stitch.
std::optional<std::string> edge_shortfall(std::span<const Worked> worked, int live) {
  int used = 0;
  for (const Worked& w : worked) {
    const StitchDef& s = stitch(w.stitch);
    if (used + s.consumes > live) {
      const int left = live - used;
      if (s.consumes < 2 || left <= 0) return std::nullopt;
      if (s.family == StitchFamily::cable && used == 0)
        return std::string(s.name) + " needs " + stitches(s.consumes) + " but only " + std::to_string(live) +
               " are live; a cable cannot be wider than the fabric";
      return std::string(s.name) + " at the edge has no neighbour to work with: it needs " + stitches(s.consumes) +
             " but " + (left == 1 ? "1 is" : std::to_string(left) + " are") + " left; move it in from the edge";
    }
    used += s.consumes;
  }
  return std::nullopt;
}

}  // namespace

namespace {

// Where a repeat's last pass stops when the row ends "ending with" stitches the repeat
// itself works ("*yo, sk2p, yo, k3; rep from *, ending with yo, k2"): the length of the
// shortest start of `star` that ends with `closing`, or nothing when no run of the
// repeat's stitches is `closing`.
std::optional<std::size_t> last_repeat_cut(std::span<const Worked> star, std::span<const Worked> closing) {
  if (closing.empty() || closing.size() > star.size()) return std::nullopt;
  for (std::size_t end = closing.size(); end < star.size(); ++end)
    if (std::equal(closing.begin(), closing.end(), star.begin() + static_cast<std::ptrdiff_t>(end - closing.size())))
      return end;
  return std::nullopt;
}

}  // namespace

std::variant<std::vector<Worked>, TextError> work_once(const RowText& text, std::string_view source, int row) {
  const std::size_t limit = static_cast<std::size_t>(max_count) * 3;  // as work_row's
  std::vector<Worked> out;
  flatten(text.before, out, limit);
  if (out.size() > limit) return TextError{"row " + std::to_string(row) + " " + quote_row(source) + " is longer than any row can be"};
  return out;
}

std::variant<std::vector<Worked>, TextError> work_row(const RowText& text, std::string_view source, int live, int row) {
  // A row can never need more stitches than the limit of live ones; stop flattening there.
  const std::size_t limit = static_cast<std::size_t>(max_count) * 3;
  std::vector<Worked> before, star, after;
  flatten(text.before, before, limit);
  if (text.star) flatten(*text.star, star, limit);
  flatten(text.after, after, limit);
  const std::string name = "row " + std::to_string(row) + " " + quote_row(source);
  if (text.as_they_appear) return TextError{name + " works each stitch as it shows: that takes the stitches below, not the text"};
  if (before.size() > limit || star.size() > limit || after.size() > limit)
    return TextError{name + " is longer than any row can be"};

  if (!text.star) {
    const int unit = consumed(before);
    if (unit == 0) {
      if (live == 0) return before;
      return TextError{name + " works none of the " + std::to_string(live) + " live stitches; give stitches such as \"k\""};
    }
    if (unit > live) {
      if (auto edge = edge_shortfall(before, live)) return TextError{name + ": " + *edge};
      return TextError{name + " uses " + stitches(unit) + " but " + std::to_string(live) + " are live (" +
                       over_or_short(live - unit) + "); remove " + stitches(unit - live) + " or change the repeat"};
    }
    if (live % unit != 0 && 2 * unit > live)  // it fits once at most: a fixed row, short
      return TextError{name + " uses " + stitches(unit) + " but " + std::to_string(live) + " are live (" +
                       over_or_short(live - unit) + "); add " + stitches(live - unit) + " or change the repeat"};
    if (live % unit != 0)
      return TextError{name + " repeats every " + stitches(unit) + " and does not fit " + std::to_string(live) +
                       " live stitches (" + over_or_short(live % unit) + "); make the count a multiple of " +
                       std::to_string(unit) + " or end the row with fixed stitches (*...; rep from * to last " +
                       sts(live % unit) + ", ...)"};
    if (before.size() * static_cast<std::size_t>(live / unit) > limit) return TextError{name + " makes more stitches than any row can hold"};
    std::vector<Worked> out;
    out.reserve(before.size() * (live / unit));
    for (int i = 0; i < live / unit; ++i) out.insert(out.end(), before.begin(), before.end());
    return out;
  }

  const int a = consumed(before), b = consumed(star), s = consumed(after);
  // "rep from * to end, ending k2" is the repeat filling what the closing stitches leave.
  if (text.to_last && *text.to_last != s && *text.to_last != 0)
    return TextError{name + " repeats to the last " + stitches(*text.to_last) + " but " + stitches(s) +
                     " follow the repeat; make the two agree"};
  if (b == 0) return TextError{name + ": the *repeat works no stitches"};
  const int room = live - a - s;
  if (room < b) {
    std::vector<Worked> once(before);
    once.insert(once.end(), star.begin(), star.end());
    once.insert(once.end(), after.begin(), after.end());
    if (auto edge = edge_shortfall(once, live)) return TextError{name + ": " + *edge};
    return TextError{name + " needs at least " + stitches(a + b + s) + " for one repeat but " + std::to_string(live) +
                     " are live (" + over_or_short(room - b) + "); add stitches or shorten the repeat"};
  }
  if (room % b != 0 && a == 0 && s == 0)
    return TextError{name + " repeats every " + stitches(b) + " and does not fit " + std::to_string(live) +
                     " live stitches (" + over_or_short(room % b) + "); make the count a multiple of " + std::to_string(b)};
  if (room % b != 0) {
    // "rep from * across row, ending with yo, k2", as vintage patterns mean it: the last
    // repeat stops where it has worked the closing stitches, when that fits exactly.
    if (auto cut = last_repeat_cut(star, after); cut && (live - a - consumed(std::span(star).first(*cut))) % b == 0 &&
                                                 live - a - consumed(std::span(star).first(*cut)) >= 0) {
      const int whole = (live - a - consumed(std::span(star).first(*cut))) / b;
      if (before.size() + star.size() * static_cast<std::size_t>(whole + 1) > limit)
        return TextError{name + " makes more stitches than any row can hold"};
      std::vector<Worked> out(before);
      for (int i = 0; i < whole; ++i) out.insert(out.end(), star.begin(), star.end());
      out.insert(out.end(), star.begin(), star.begin() + static_cast<std::ptrdiff_t>(*cut));
      return out;
    }
    return TextError{name + ": the *repeat of " + stitches(b) + " does not fit the " + std::to_string(room) +
                     " stitches between the fixed ones (" + over_or_short(room % b) +
                     "); change the repeat or the fixed stitches"};
  }
  if (before.size() + after.size() + star.size() * static_cast<std::size_t>(room / b) > limit)
    return TextError{name + " makes more stitches than any row can hold"};
  std::vector<Worked> out(before);
  for (int i = 0; i < room / b; ++i) out.insert(out.end(), star.begin(), star.end());
  out.insert(out.end(), after.begin(), after.end());
  return out;
}

std::variant<std::vector<Op>, TextError> face_view(std::span<const Worked> worked, Side side, int yarn) {
  std::vector<Op> ops;
  ops.reserve(worked.size());
  for (const Worked& w : worked) {
    Op op{w.stitch, w.yarn < 0 ? yarn : w.yarn};
    if (side == Side::wrong) {
      const auto face = wrong_side_face(w.stitch);
      if (!face && stitch(w.stitch).family == StitchFamily::cable)
        return TextError{std::string(stitch(w.stitch).name) +
                         " worked from the wrong side shows purled outer stitches crossing around a knit middle on the "
                         "face, which knitc cannot draw yet; work it on a right-side row"};
      if (!face)
        return TextError{std::string(stitch(w.stitch).name) +
                         " has no wrong-side form; work it on a right-side row"};
      op.stitch = *face;
    }
    ops.push_back(op);
  }
  // Right-side rows are worked from the right edge: the first stitch worked is the last
  // in face order.
  if (side == Side::right) std::reverse(ops.begin(), ops.end());
  return ops;
}

}  // namespace knitc::language

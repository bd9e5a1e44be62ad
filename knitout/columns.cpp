// Knitout in: the needle columns across the two beds (columns.hpp).
#include "columns.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <unordered_map>

namespace knitc::knitout {

namespace {

// A course's positions as needle columns (`spacing` needle pitches), flat work's
// positions sorted along the beds, `worked` where the course made a loop: each column's
// width, half the way from the column before to the one after (at most one; an end's,
// its neighbour's), and how its loops take it.
enum class Arrangement {
  // Side by side, each taking a share of the column:
  // - its two beds' loops both worked (a full-needle rib) or both left: half each, so
  //   the course is as wide as its needles, not twice;
  // - one worked, the other left (a pass on one bed): the worked loop all but a tenth,
  //   so that the loop the course makes is as wide as the column;
  // - fewer loops than the course's columns most often hold (one bed's needle at an
  //   end, with no partner): each as wide as the others' loops, so the rib's positions
  //   stay on one lattice for its repeat (relax::lattice_step).
  side_by_side,
  // Two layers: each loop at the column's whole width, the back bed's behind the front's
  // (its position 0 wide, over the one before).
  layered,
};
struct Columns {
  std::vector<double> widths;
  std::vector<signed char> layers;
};
Columns needle_columns(const std::vector<Position>& pos, const std::vector<char>& worked, const std::vector<char>& paired,
                       int spacing, Arrangement how) {
  const double left_weight = 0.1;  // a left stitch's share against a worked one's 1
  Columns out;
  out.widths.assign(pos.size(), 1.0);
  std::vector<long> columns;          // distinct, in order
  std::vector<std::size_t> first{0};  // each column's first position, and the end
  for (std::size_t j = 0; j < pos.size(); ++j) {
    const long c = column_of(pos[j]);
    if (columns.empty() || columns.back() != c) {
      if (!columns.empty()) first.push_back(j);
      columns.push_back(c);
    }
  }
  first.push_back(pos.size());
  const std::size_t n = columns.size();
  std::vector<double> share(n, 1.0);
  for (std::size_t k = 1; k + 1 < n; ++k)
    share[k] = std::min(1.0, 0.5 * static_cast<double>(columns[k + 1] - columns[k - 1]) / spacing);
  if (n >= 3) share.front() = share[1], share.back() = share[n - 2];
  if (n == 2) share.front() = share.back() = std::min(1.0, static_cast<double>(columns[1] - columns[0]) / spacing);
  if (how == Arrangement::layered) {
    out.layers.resize(pos.size());
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t from = first[k], to = first[k + 1];
      const bool side = to - from == 2 && paired[from] && paired[from + 1];
      for (std::size_t j = from; j < to; ++j) {
        out.widths[j] = side ? 0.5 * share[k] : j == from ? share[k] : 0.0;
        out.layers[j] = front(pos[j].needle.bed) ? 1 : -1;
      }
    }
    return out;
  }
  // The loops a column of the course most often holds.
  std::map<std::size_t, std::size_t> holding;
  for (std::size_t k = 0; k < n; ++k) ++holding[first[k + 1] - first[k]];
  std::size_t usual = 1, most = 0;
  for (const auto& [loops, columns_holding] : holding)
    if (columns_holding > most) most = columns_holding, usual = loops;
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t from = first[k], to = first[k + 1];
    const auto busy = std::count(worked.begin() + static_cast<std::ptrdiff_t>(from), worked.begin() + static_cast<std::ptrdiff_t>(to), 1);
    const bool mixed = busy > 0 && static_cast<std::size_t>(busy) < to - from;
    double total = to - from < usual ? static_cast<double>(usual - (to - from)) : 0.0;
    for (std::size_t j = from; j < to; ++j) total += mixed && !worked[j] ? left_weight : 1.0;
    for (std::size_t j = from; j < to; ++j) out.widths[j] = share[k] * (mixed && !worked[j] ? left_weight : 1.0) / total;
  }
  if (std::all_of(out.widths.begin(), out.widths.end(), [](double w) { return w == 1.0; })) out.widths.clear();
  return out;
}

}  // namespace

long column_of(const Position& q) { return std::lround(q.x - 0.25); }

long spacing_of(const std::vector<RawCourse>& courses, bool round) {
  std::map<long, long long> gaps;
  for (const RawCourse& c : courses) {
    std::vector<long> at;  // needles (a tube) or needle columns (flat) holding loops
    for (const Position& p : c.positions)
      if (!round || p.needle.bed == Bed::f) at.push_back(round ? p.needle.index : column_of(p));
    std::sort(at.begin(), at.end());
    at.erase(std::unique(at.begin(), at.end()), at.end());
    for (std::size_t k = 1; k < at.size(); ++k)
      if (at[k] - at[k - 1] <= 3) ++gaps[at[k] - at[k - 1]];
  }
  long spacing = 1;
  long long most = 0;
  for (const auto& [gap, count] : gaps)
    if (count > most) most = count, spacing = gap;
  return spacing;
}

ColumnWidths column_widths(const std::vector<RawCourse>& courses, const std::vector<std::vector<char>>& worked,
                           const std::vector<Loop>& loops, int spacing) {
  ColumnWidths out;
  if (courses.empty()) return out;
  // Per position of each course: its loop made next to its column's other one along one
  // yarn (a rib's stitches).
  auto paired_in = [&](const RawCourse& c) {
    std::vector<char> next(c.positions.size(), 0);
    std::unordered_map<int, std::size_t> at;  // loop -> its place in c.made
    for (std::size_t i = 0; i < c.made.size(); ++i) at[c.made[i]] = i;
    auto made_at = [&](std::size_t j) -> long {
      for (int l : c.positions[j].pile)
        if (auto it = at.find(l); it != at.end()) return static_cast<long>(it->second);
      return -1;
    };
    for (std::size_t j = 0; j + 1 < c.positions.size(); ++j) {
      if (column_of(c.positions[j]) != column_of(c.positions[j + 1])) continue;
      const long a = made_at(j), b = made_at(j + 1);
      if (a < 0 || b < 0 || std::abs(a - b) != 1) continue;
      const auto& ca = loops[static_cast<std::size_t>(c.made[static_cast<std::size_t>(a)])].carriers;
      const auto& cb = loops[static_cast<std::size_t>(c.made[static_cast<std::size_t>(b)])].carriers;
      if (ca == cb) next[j] = next[j + 1] = 1;
    }
    return next;
  };
  std::vector<std::vector<char>> paired;
  for (const RawCourse& c : courses) paired.push_back(paired_in(c));
  // The yarn a position's loop was made with this course, or -1.
  auto yarn_at = [&](const RawCourse& c, const std::vector<char>& made_here, std::size_t j) {
    if (!made_here[j]) return -1;
    for (auto l = c.positions[j].pile.rbegin(); l != c.positions[j].pile.rend(); ++l) {
      const Loop& loop = loops[static_cast<std::size_t>(*l)];
      if (!loop.carriers.empty()) return loop.carriers.front();
    }
    return -1;
  };
  long shared = 0, both = 0, one = 0, rib = 0;  // columns holding two loops; both worked, one; both with one yarn
  std::size_t positions = 0;
  for (std::size_t ci = 1; ci < courses.size(); ++ci) {
    positions += courses[ci].positions.size();
    for (std::size_t j = 0; j + 1 < courses[ci].positions.size(); ++j)
      if (column_of(courses[ci].positions[j]) == column_of(courses[ci].positions[j + 1])) {
        ++shared;
        both += worked[ci][j] && worked[ci][j + 1];
        one += worked[ci][j] != worked[ci][j + 1];
        rib += worked[ci][j] && worked[ci][j + 1] && yarn_at(courses[ci], worked[ci], j) == yarn_at(courses[ci], worked[ci], j + 1);
      }
  }
  if (shared == 0) return out;
  // Side by side: a course knits both of nearly every column with one yarn (a full-needle
  // rib, a Milano rib), or one of them (an interlock). Else two layers, where they
  // are the fabric's, most of its loops in them: not a few double-bed courses in a sheet
  // (a cable's, a short row's), which keep whole positions.
  const bool side = (10 * both >= 9 * shared && 10 * rib >= 9 * both) || 10 * one >= 9 * shared;
  if (!side && 4 * static_cast<std::size_t>(shared) < positions) return out;
  const Arrangement how = side ? Arrangement::side_by_side : Arrangement::layered;
  // An interlock throughout (three in four of its loops in shared columns): its courses
  // rise as its layers' loops ask. Not a few courses of it, as the ribbed hat's waste:
  // risen so, the hat passed 9,106 of its 169,402 crossings through (114 not).
  out.in_turn = 10 * one >= 9 * shared && 8 * static_cast<std::size_t>(shared) >= 3 * positions;
  Columns cast_on = needle_columns(courses[0].positions, std::vector<char>(courses[0].positions.size(), 1), paired[0], spacing, how);
  out.cast_on = std::move(cast_on.widths);
  out.cast_on_layers = std::move(cast_on.layers);
  for (std::size_t ci = 1; ci < courses.size(); ++ci) {
    Columns c = needle_columns(courses[ci].positions, worked[ci], paired[ci], spacing, how);
    out.courses.push_back(std::move(c.widths));
    out.layers.push_back(std::move(c.layers));
  }
  return out;
}

std::vector<double> layer_rises(const std::vector<Loop>& loops, const std::vector<int>& course_of,
                                const std::vector<RawCourse>& courses) {
  std::vector<double> y(courses.size(), 0.0);  // each course's height, in course spacings
  for (std::size_t ci = 1; ci < courses.size(); ++ci) {
    double asks[2] = {-1.0, -1.0};  // per bed, front then back: the height its loops ask
    for (int l : courses[ci].made) {
      const Loop& loop = loops[static_cast<std::size_t>(l)];
      if (loop.made_by == Opcode::tuck || loop.parents.empty()) continue;
      // The wale's loop: the lowest in the pile that was knitted, not tucked.
      int wale = loop.parents.front();
      for (int q : loop.parents)
        if (loops[static_cast<std::size_t>(q)].made_by != Opcode::tuck) {
          wale = q;
          break;
        }
      const auto below = static_cast<std::size_t>(course_of[static_cast<std::size_t>(wale)]);
      double& ask = asks[front(loop.needle.bed) ? 0 : 1];
      if (below < ci) ask = std::max(ask, y[below] + 1.0);
    }
    const double ask = asks[0] < 0.0 ? asks[1] : asks[1] < 0.0 ? asks[0] : std::min(asks[0], asks[1]);
    y[ci] = std::max(y[ci - 1] + (ask < 0.0 ? 0.25 : 0.5), ask);
  }
  std::vector<double> rises;
  for (std::size_t ci = 1; ci < courses.size(); ++ci) rises.push_back(y[ci] - y[ci - 1]);
  return rises;
}

void share_columns(Course& course, const std::vector<std::size_t>& shared) {
  if (shared.empty() || !course.widths.empty()) return;
  const StitchId bo = stitch_id("bo");
  auto next = shared.begin();
  for (std::size_t i = 0; i < course.ops.size(); ++i) {
    const int slots = course.ops[i].stitch == bo ? 1 : stitch(course.ops[i].stitch).produces;
    const bool half = next != shared.end() && *next == i;
    if (half) {
      course.widths.back() = 0.5;
      ++next;
    }
    course.widths.insert(course.widths.end(), static_cast<std::size_t>(slots), half ? 0.5 : 1.0);
  }
}

}  // namespace knitc::knitout

// Knitout in: the needle columns across the two beds (columns.hpp).
#include "columns.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace knitc::knitout {

namespace {

// Each live stitch's needle position's width, in loop widths (`spacing` needle pitches),
// flat work's positions sorted along the beds, `worked` where the course made a loop:
// its column's width (half the way from the column before to the one after, at most
// one; an end's, its neighbour's) shared by the stitches in it.
// - A column whose two beds' loops are both worked (a full-needle rib) or both left:
//   half each, so the course is as wide as its needles, not twice.
// - One worked, the other left (a pass on one bed): the worked loop takes all but a
//   tenth, so that the loop the course makes is as wide as the column.
// - Fewer loops than the course's columns most often hold (one bed's needle at an end,
//   with no partner): each as wide as the others' loops, so the rib's positions stay on
//   one lattice for its repeat (relax::lattice_step).
// A rib on alternate needles and a jersey keep one. Empty where every width is one.
std::vector<double> needle_widths(const std::vector<Position>& pos, const std::vector<char>& worked, int spacing) {
  const double left_weight = 0.1;  // a left stitch's share against a worked one's 1
  std::vector<double> widths(pos.size(), 1.0);
  std::vector<long> columns;          // distinct, in order
  std::vector<std::size_t> first{0};  // each column's first position, and the end
  for (std::size_t j = 0; j < pos.size(); ++j) {
    const long c = column_of(pos[j]);
    if (!columns.empty() && columns.back() != c) first.push_back(j);
    if (columns.empty() || columns.back() != c) columns.push_back(c);
  }
  first.push_back(pos.size());
  const std::size_t n = columns.size();
  std::vector<double> share(n, 1.0);
  for (std::size_t k = 1; k + 1 < n; ++k)
    share[k] = std::min(1.0, 0.5 * static_cast<double>(columns[k + 1] - columns[k - 1]) / spacing);
  if (n >= 3) share.front() = share[1], share.back() = share[n - 2];
  if (n == 2) share.front() = share.back() = std::min(1.0, static_cast<double>(columns[1] - columns[0]) / spacing);
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
    for (std::size_t j = from; j < to; ++j) widths[j] = share[k] * (mixed && !worked[j] ? left_weight : 1.0) / total;
  }
  if (std::all_of(widths.begin(), widths.end(), [](double w) { return w == 1.0; })) return {};
  return widths;
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

ColumnWidths column_widths(const std::vector<RawCourse>& courses, const std::vector<std::vector<char>>& worked, int spacing) {
  ColumnWidths out;
  long shared = 0, both = 0, one = 0;
  for (std::size_t ci = 1; ci < courses.size(); ++ci)
    for (std::size_t j = 0; j + 1 < courses[ci].positions.size(); ++j)
      if (column_of(courses[ci].positions[j]) == column_of(courses[ci].positions[j + 1])) {
        ++shared;
        both += worked[ci][j] && worked[ci][j + 1];
        one += worked[ci][j] != worked[ci][j + 1];
      }
  if (courses.empty() || shared == 0 || (10 * both < 9 * shared && 10 * one < 9 * shared)) return out;
  out.cast_on = needle_widths(courses[0].positions, std::vector<char>(courses[0].positions.size(), 1), spacing);
  for (std::size_t ci = 1; ci < courses.size(); ++ci) out.courses.push_back(needle_widths(courses[ci].positions, worked[ci], spacing));
  return out;
}

}  // namespace knitc::knitout

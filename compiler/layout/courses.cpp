// The courses of the layout: each course's needle positions (their widths, where each
// course starts, which way it is worked, how high it lies) and where a loop of it is
// across and up, for the layout's passes (layout.cpp) and the stages after it.
#include "layout/courses.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>

namespace knitc::layout {

// x of a needle position's centre in its course.
double centre_x(const Layout& out, int course, int slot) {
  const double o = out.origin_x[course], W = out.loop_width;
  // Before any cluster, as whole loop widths always were: the same coordinates to the bit.
  if (out.slot_x[course][slot + 1] == o + (slot + 1) * W) return o + (slot + 0.5) * W;
  const Span s = span_of(out, course, slot);
  return 0.5 * (s.left + s.right);
}
// A loop's width: W, its share of a cluster's, or its needle position's where a machine's
// needles set the course's widths (exactly W for every other loop, so that fabrics
// without either keep their coordinates to the bit).
double width_of(const Layout& out, const Loop& l) {
  const bool by_needles = out.needle_widths[static_cast<std::size_t>(l.course)] != 0;
  if (!by_needles && (stitch(l.stitch).cluster_width <= 0.0 || l.shape == Template::tuck)) return out.loop_width;
  const Span s = span_of(out, l.course, l.wale);
  return s.right - s.left;
}

namespace {

// A course's needle positions relative to its origin: each one's left edge and the last
// one's right (one more than the positions), and their centres. Up to the first cluster
// whole loop widths are multiplied, not summed, so that a fabric without clusters keeps
// the very same coordinates.
struct Columns {
  std::vector<double> edges, centres;
};
Columns columns_of(const std::vector<double>& widths, double W) {
  Columns out;
  out.edges.push_back(0.0);
  bool uniform = true;
  for (std::size_t k = 0; k < widths.size(); ++k) {
    uniform = uniform && widths[k] == W;
    // A layer's position 0 wide lies over the one before it (Layout::layers).
    if (widths[k] == 0.0 && k > 0) out.centres.push_back(out.centres.back());
    else out.centres.push_back(uniform ? (static_cast<double>(k) + 0.5) * W : out.edges.back() + 0.5 * widths[k]);
    out.edges.push_back(uniform ? static_cast<double>(k + 1) * W : out.edges.back() + widths[k]);
  }
  return out;
}

// The width of each needle position after each course, mm: W, a machine's needles' share
// (Course::widths; the bind-off's, the last course's), or a cluster's share. Marks the
// courses whose widths the needles set.
std::vector<std::vector<double>> slot_widths(Layout& out, const Pattern& pattern, const knit_graph::Graph& graph) {
  std::vector<std::vector<double>> width(static_cast<std::size_t>(out.courses));
  out.needle_widths.assign(static_cast<std::size_t>(out.courses), 0);
  out.layers.assign(static_cast<std::size_t>(out.courses), {});
  for (int c = 0; c < out.courses; ++c) {
    const std::size_t n = static_cast<std::size_t>(out.needle[c]);
    width[c].assign(n, out.loop_width);
    const std::size_t row = std::min(static_cast<std::size_t>(c), pattern.courses.size());  // past the last: the bind-off
    const std::vector<double>& set = row == 0 ? pattern.cast_on_widths : pattern.courses[row - 1].widths;
    if (set.size() != n) continue;
    for (std::size_t k = 0; k < n; ++k) width[c][k] = set[k] * out.loop_width;
    out.needle_widths[c] = 1;
    const std::vector<signed char>& layers = row == 0 ? pattern.cast_on_layers : pattern.courses[row - 1].layers;
    if (layers.size() == n) out.layers[c] = layers;
  }
  for (const knit_graph::Loop& k : graph.loops) {
    const StitchDef& s = stitch(k.stitch);
    if (s.cluster_width > 0.0 && !k.held) width[k.course][k.slot] = s.cluster_width * out.loop_width / s.produces;
  }
  return width;
}

// Short rows: each column's height where a course leaves a stitch unreached (a short
// row's turn, or another carrier's part of the row), Layout::column_y; empty where none
// does, or where the courses lie at their layers' heights.
std::vector<std::vector<double>> column_heights(const Layout& out, const knit_graph::Graph& graph, bool bind_off) {
  const auto reached = [](const knit_graph::Column& k) { return k.reached; };
  auto turns = [&](std::size_t c) {
    const auto& columns = graph.stands_on[c];
    return !layered(out, static_cast<int>(c)) && !std::all_of(columns.begin(), columns.end(), reached) &&
           std::any_of(columns.begin(), columns.end(), reached);
  };
  // The bind-off's course (added below) reaches every column, so it never turns: look
  // for a turn in the graph's own courses before copying them.
  bool short_rows = false;
  for (std::size_t c = 1; c < graph.stands_on.size() && !short_rows; ++c) short_rows = turns(c);
  const std::size_t courses = graph.stands_on.size() + (bind_off ? 1 : 0);
  if (!short_rows || !out.heights.empty() || static_cast<int>(courses) != out.courses) return {};
  std::vector<std::vector<knit_graph::Column>> stands_on = graph.stands_on;
  if (bind_off) {
    auto& last = stands_on.emplace_back();
    for (int column : graph.live_columns) last.push_back({column, 1, true});
  }
  std::vector<std::vector<double>> y(stands_on.size());
  y[0].assign(static_cast<std::size_t>(out.needle[0]), 0.0);
  // Per column: whether a loop has been pulled through a stitch in it yet (its wale
  // begun); the cast-on's, a yarn over's and a tuck's alone do not begin one.
  std::vector<char> begun(y[0].size(), 0);
  for (std::size_t c = 1; c < stands_on.size(); ++c) {
    const auto& columns = stands_on[c];
    // A course that reaches every column rises whole, as without short rows (a slipped
    // stitch stretched with its neighbours, a tuck held over the old loop's head); so do
    // two layers' courses; a pass that pulls no loop through but reaches most of the
    // columns (a cast-on's rows of tucks); and a pass that slips or tucks more than a
    // third of the columns it reaches (one bed's pass of a tube or a double-bed fabric
    // read flat, every other column left to the other bed's pass, which completes the
    // row). Where another course reaches only some columns, a column rises where a loop
    // is pulled through it, and where it is slipped or tucked between two that rise: not
    // where one carrier of an intarsia slips or tucks past the edge of its part to join
    // the next, whose own pass knits it.
    auto pulled = [&](std::size_t s) { return s < columns.size() && columns[s].reached && columns[s].pulled; };
    // A slipped or tucked column between two the course pulls loops through.
    auto between = [&](std::size_t s) { return columns[s].reached && !columns[s].pulled && s > 0 && pulled(s - 1) && pulled(s + 1); };
    std::ptrdiff_t pulls = 0, reaches = 0;
    for (std::size_t s = 0; s < columns.size(); ++s) pulls += pulled(s), reaches += columns[s].reached;
    const auto width = static_cast<std::ptrdiff_t>(columns.size());
    const bool whole = layered(out, static_cast<int>(c)) || reaches == width || (pulls == 0 && 2 * reaches > width) ||
                       (pulls > 0 && 3 * (reaches - pulls) > reaches);
    std::vector<double> base(columns.size(), std::numeric_limits<double>::quiet_NaN());
    for (std::size_t s = 0; s < columns.size(); ++s) {
      const knit_graph::Column& k = columns[s];
      if (k.below < 0) continue;
      const auto below = y[c - 1].begin() + k.below;
      base[s] = *std::max_element(below, below + k.across);
    }
    // A column left one course behind the columns beside it (a selvedge the rows turn
    // before every other row) is stretched up to them where the course reaches it again,
    // as a slipped stitch is. Columns further behind (a short row's turn, a block of
    // entrelac), or several side by side (a part the rows reach every other row), keep
    // their own height: the fabric is that much shorter there.
    std::vector<double> level = base;
    for (std::size_t s = 0; s < columns.size(); ++s) {
      if (!columns[s].reached || std::isnan(base[s])) continue;
      double beside = std::numeric_limits<double>::infinity();
      bool any = false;
      for (const std::size_t n : {s - 1, s + 1})
        if (n < columns.size() && columns[n].reached && !std::isnan(base[n])) beside = std::min(beside, base[n]), any = true;
      if (any && beside > base[s] && beside - base[s] <= 1.001 * out.course_spacing) level[s] = beside;
    }
    // A column whose wale has not begun (a loop an i-cord left on each needle it passed,
    // for the fabric to be knitted from later) is carried up with the rows knitted beside
    // it, a course below them, so that its wale begins with theirs.
    double top = -std::numeric_limits<double>::infinity();
    for (std::size_t s = 0; s < columns.size(); ++s)
      if (pulled(s) && !std::isnan(level[s])) top = std::max(top, level[s] + out.course_spacing);
    y[c].assign(columns.size(), std::numeric_limits<double>::quiet_NaN());
    std::vector<char> now_begun(columns.size(), 0);
    for (std::size_t s = 0; s < columns.size(); ++s) {
      const knit_graph::Column& k = columns[s];
      if (k.below >= 0)
        now_begun[s] = (pulled(s) || std::any_of(begun.begin() + k.below, begun.begin() + k.below + k.across, [](char b) { return b; }));
      if (std::isnan(level[s])) continue;
      const bool rises = whole || pulled(s) || between(s);
      y[c][s] = rises ? level[s] + out.course_spacing : level[s];
      if (!rises && !now_begun[s]) y[c][s] = std::max(y[c][s], top - out.course_spacing);
    }
    begun = std::move(now_begun);
    // A yarn over stands beside the stitch before it in the course, or after it.
    for (std::size_t s = 0; s < columns.size(); ++s)
      if (std::isnan(y[c][s]) && s > 0) y[c][s] = y[c][s - 1];
    for (std::size_t s = columns.size(); s-- > 0;)
      if (std::isnan(y[c][s])) y[c][s] = s + 1 < columns.size() ? y[c][s + 1] : static_cast<double>(c) * out.course_spacing;
  }
  // Every loop at its course's height after all (a selvedge stretched level, a stitch
  // left unreached once): laid by courses, as a fabric without short rows is, to the bit.
  for (std::size_t c = 1; c < y.size(); ++c)
    for (std::size_t s = 0; s < y[c].size(); ++s)
      if (stands_on[c][s].reached && std::abs(y[c][s] - static_cast<double>(c) * out.course_spacing) > 1e-6 * out.course_spacing)
        return y;
  return {};
}

}  // namespace

// The courses: their needles, where each starts, which way each is worked.
Layout frame_courses(const Pattern& pattern, const knit_graph::Graph& graph, bool bind_off) {
  Layout out;
  const Gauge& g = pattern.gauge;
  const double W = g.loop_width, T = g.thickness;
  double thickest = 0.0;
  for (const Yarn& y : pattern.yarns) thickest = std::max(thickest, y.diameter);
  out.knitting = pattern.knitting;
  out.loop_width = W;
  out.course_spacing = g.course_spacing();
  out.float_behind = -(0.3 * T + 0.6 * thickest);
  out.float_in_front = T + 0.6 * thickest;
  out.needle = graph.columns;
  if (bind_off) out.needle.push_back(static_cast<int>(graph.live.size()));
  out.courses = static_cast<int>(out.needle.size());
  out.wales = out.needle.empty() ? 0 : *std::max_element(out.needle.begin(), out.needle.end());
  const auto widths = slot_widths(out, pattern, graph);
  if (std::any_of(pattern.courses.begin(), pattern.courses.end(), [](const Course& c) { return c.rise != 1.0; })) {
    out.heights.assign(static_cast<std::size_t>(out.courses), 0.0);
    for (int c = 1; c < out.courses; ++c) {
      const std::size_t row = static_cast<std::size_t>(c);  // past the last: the bind-off, a whole course up
      out.heights[c] = out.heights[c - 1] + (row <= pattern.courses.size() ? pattern.courses[row - 1].rise : 1.0) * out.course_spacing;
    }
  }
  if (std::any_of(out.layers.begin(), out.layers.end(), [](const auto& l) { return !l.empty(); })) out.layer_depth = T;
  out.column_y = column_heights(out, graph, bind_off);
  // Per course, the plain loops (knit or purl through one loop of the course below) and
  // their parents' columns: what lines a course up over the one below.
  // A course with none (the second bed's pass of a two-layer fabric, its loops pulled
  // through the rib row two courses down) lines up over the parents it has, wherever
  // they lie.
  std::vector<std::vector<std::array<int, 3>>> plain(static_cast<std::size_t>(out.courses));  // (column, parent's course, its column)
  std::vector<std::vector<std::array<int, 3>>> older(static_cast<std::size_t>(out.courses));
  for (const knit_graph::Loop& k : graph.loops) {
    if (k.course == 0 || k.held || k.plating || stitch(k.stitch).family == StitchFamily::cable) continue;
    // Through one stitch: one loop, or a plated stitch's two (the first yarn's and its plating).
    const auto through = std::count_if(k.parents.begin(), k.parents.end(),
                                       [&](int q) { return !graph.loops[static_cast<std::size_t>(q)].plating; });
    if (through != 1 || graph.loops[static_cast<std::size_t>(k.parents.front())].plating) continue;
    const knit_graph::Loop& parent = graph.loops[static_cast<std::size_t>(k.parents.front())];
    (parent.course == k.course - 1 ? plain : older)[k.course].push_back({k.slot, parent.course, parent.slot});
  }
  if (bind_off)
    for (std::size_t s = 0; s < graph.live.size(); ++s)
      if (graph.live[s].size() == 1) {
        const knit_graph::Loop& parent = graph.loops[graph.live[s].front()];
        plain.back().push_back({static_cast<int>(s), parent.course, parent.slot});
      }
  for (int c = 0; c < out.courses; ++c) {
    const double width = std::accumulate(widths[c].begin(), widths[c].end(), 0.0);
    const Columns columns = columns_of(widths[c], W);
    // A tube starts each round at angle zero. Flat work: each course where its plain
    // loops lie over their parents (the median of their offsets), so that stitches bound
    // off or decreased at one edge leave the rest in place; with none, centred over the
    // course below.
    double origin = 0.0;
    if (pattern.knitting == Knitting::flat && c > 0) {
      const double below = out.origin_x[c - 1], below_width = out.slot_x[c - 1].back() - below;
      origin = below + 0.5 * (below_width - width);
      const auto& over = plain[c].empty() ? older[c] : plain[c];
      if (!over.empty()) {
        std::vector<double> offsets;
        for (const auto& [column, course, parent] : over)
          offsets.push_back(centre_x(out, course, parent) - columns.centres[static_cast<std::size_t>(column)]);
        std::sort(offsets.begin(), offsets.end());
        const std::size_t n = offsets.size();
        origin = n % 2 ? offsets[n / 2] : 0.5 * (offsets[n / 2 - 1] + offsets[n / 2]);
      }
    }
    out.origin_x.push_back(origin);
    std::vector<double>& edges = out.slot_x.emplace_back();
    for (double e : columns.edges) edges.push_back(origin + e);
    int direction = -1;  // in the round every course runs right to left
    if (pattern.knitting == Knitting::flat) {
      if (c == 0) direction = !pattern.courses.empty() && pattern.courses.front().side == Side::wrong ? -1 : 1;
      else if (c <= static_cast<int>(pattern.courses.size())) direction = pattern.courses[c - 1].side == Side::right ? -1 : 1;
      else direction = -out.direction.back();  // the bind-off turns like any row
    }
    out.direction.push_back(direction);
  }
  out.floats = graph.floats;
  out.wraps = graph.wraps;
  out.bobbles = graph.bobbles;
  return out;
}

int way(const Layout& layout, std::size_t index) {
  const Loop& l = layout.loops[index];
  const int course_way = layout.direction[static_cast<std::size_t>(l.course)];
  return l.against ? -course_way : course_way;
}

double course_y(const Layout& layout, int course) {
  return layout.heights.empty() ? course * layout.course_spacing : layout.heights[static_cast<std::size_t>(course)];
}

double foot_y(const Layout& layout, int course, int slot) {
  if (layout.column_y.empty()) return course_y(layout, course);
  return layout.column_y[static_cast<std::size_t>(course)][static_cast<std::size_t>(slot)];
}

double laid_height(const Layout& layout) {
  double top = static_cast<double>(layout.courses) * layout.course_spacing;
  if (layout.column_y.empty()) return top;
  top = 0.0;
  for (const auto& course : layout.column_y)
    for (double y : course) top = std::max(top, y + layout.course_spacing);
  return top;
}

bool layered(const Layout& layout, int course) {
  const auto c = static_cast<std::size_t>(course);
  return c < layout.layers.size() && !layout.layers[c].empty();
}

Span span_of(const Layout& layout, int course, int slot) {
  const auto& edges = layout.slot_x[static_cast<std::size_t>(course)];
  const auto s = static_cast<std::size_t>(slot);
  if (s > 0 && edges[s + 1] == edges[s] && layered(layout, course)) return {edges[s - 1], edges[s]};
  return {edges[s], edges[s + 1]};
}

double course_width(const Layout& layout, int course) {
  const auto& edges = layout.slot_x[static_cast<std::size_t>(course)];
  return edges.back() - edges.front();
}

glm::dvec3 to_fabric(const Layout& layout, const glm::dvec3& p, int course) {
  if (layout.knitting == Knitting::flat) return p;
  const double circumference = course_width(layout, course);
  if (circumference <= 0.0) return p;
  return roll(p, circumference, layout.course_spacing);
}

glm::dvec3 roll(const glm::dvec3& p, double circumference, double climb) {
  const double turn = p.x / circumference;  // 0 at needle position 0, 1 a round later
  const double angle = 2.0 * std::numbers::pi * turn - std::numbers::pi;
  const double r = circumference / (2.0 * std::numbers::pi) + p.z;
  // Worked right to left, a round climbs one course from x = circumference to x = 0.
  return {r * std::sin(angle), p.y + climb * (1.0 - turn), r * std::cos(angle)};
}

glm::dvec3 unroll(const glm::dvec3& q, double circumference, double climb, double near_x) {
  const double angle = std::atan2(q.x, q.z);
  double turn = (angle + std::numbers::pi) / (2.0 * std::numbers::pi);
  turn += std::round(near_x / circumference - turn);
  return {turn * circumference, q.y - climb * (1.0 - turn), std::hypot(q.x, q.z) - circumference / (2.0 * std::numbers::pi)};
}

}  // namespace knitc::layout

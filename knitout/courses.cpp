// The machine's loops grouped into courses, and each course said as a pattern's stitches.
//
// A course is what the carriers knit between two transfers, until a needle would be
// worked twice: one pass of a sheet, both passes of a round of a tube, every carrier's
// pass of an intarsia row. When it ends, every needle holding loops is a live stitch, in
// face order (flat: left to right along the beds; a tube: the front bed left to right,
// then the back bed right to left, its outside). Each live stitch is then one of:
//   a loop knitted through the loops of some live stitches of the course before  k, p, decreases
//   those stitches in another order, all single                               a cable (crossing order:
//                                                                               the group that settled first is on top)
//   a tuck on top of a stitch                                                  tuck
//   a new loop on an empty needle                                              yo (the cast-on, increases)
//   a stitch left as it was                                                    slip (yarn passed it) or held
//   the old loops a split moved off beside its new loop                        kfb
// and a live stitch of the course before that is on no needle was dropped: drop.
#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <cstdio>
#include <cstdlib>

#include "knit_graph/knit_graph.hpp"
#include "knitout.hpp"

namespace knitc::knitout {

namespace {

struct Position {
  Needle needle;
  double x = 0.0;          // across the beds, in needle pitches
  std::vector<int> pile;   // loops, bottom to top
};

struct Crossing {  // a carrier at a needle
  int carrier;
  double x;
  int direction;
  bool front;
};

// Where a carrier went in one direction without turning: the span it passed, and the
// beds it stitched or missed on. A course keeps these, not every stitch, so a program of
// a million misses costs a million steps.
struct Run {
  int carrier;
  int direction;
  double low, high;
  bool front = false, back = false;
  bool on(bool side) const { return side ? front : back; }
  bool passes(double x) const { return low < x - 1e-6 && high > x + 1e-6; }
};

// Adds where a carrier went to a course's runs: the carrier's last run grows, or a new
// one starts where it turned.
void add(std::vector<Run>& runs, const Crossing& c) {
  for (auto r = runs.rbegin(); r != runs.rend(); ++r) {
    if (r->carrier != c.carrier) continue;
    if (r->direction == c.direction) {
      r->low = std::min(r->low, c.x);
      r->high = std::max(r->high, c.x);
      (c.front ? r->front : r->back) = true;
      return;
    }
    break;
  }
  Run r{c.carrier, c.direction, c.x, c.x};
  (c.front ? r.front : r.back) = true;
  runs.push_back(r);
}

struct RawCourse {
  int first_operation = 0;
  double racking = 0.0;
  std::vector<int> made;             // loops made, in order
  std::vector<Run> went;             // where its carriers went
  std::vector<Position> positions;   // at its end, unordered
};

double across(Needle n, double racking) { return front(n.bed) ? n.index : n.index + racking + 1e-3; }

const StitchId none = static_cast<StitchId>(-1);
const StitchId drop = stitch_id("drop"), bo = stitch_id("bo");

StitchId cable_stitch(int width, int held, bool held_on_top) {
  for (std::size_t i = 0; i < stitch_table().size(); ++i) {
    const StitchDef& d = stitch_table()[i];
    if (d.family == StitchFamily::cable && d.consumes == width && d.cable.held == held && d.cable.front == held_on_top &&
        d.cable.middle == 0 && !d.cable.purl_background && !d.cable.purled && !d.twisted)
      return static_cast<StitchId>(i);
  }
  return none;
}

}  // namespace

Imported import_program(const Program& program, const Profile& profile) {
  Imported out;
  out.profile = profile;
  out.warnings = program.warnings;
  Machine machine(program, profile);

  // Run the machine, cutting courses.
  std::vector<RawCourse> courses;
  std::vector<int> course_of;  // per loop
  bool open = false;
  auto has_open_loop = [&](Needle n) {
    for (int l : machine.pile(n))
      if (course_of[static_cast<std::size_t>(l)] == static_cast<int>(courses.size()) - 1 && open) return true;
    return false;
  };
  auto close = [&] {
    if (!open) return;
    RawCourse& c = courses.back();
    for (Needle n : machine.occupied()) c.positions.push_back({n, across(n, c.racking), machine.pile(n)});
    open = false;
  };
  std::size_t plated = 0, splits = 0;
  int plated_line = 0, last_drop_line = 0;
  std::vector<Run> waiting;  // misses before the next course opens
  for (std::size_t i = 0; i < program.operations.size(); ++i) {
    const Operation& op = program.operations[i];
    const bool stitch = (op.op == Opcode::knit || op.op == Opcode::tuck || op.op == Opcode::split) && !op.carriers.empty();
    const bool moves = op.op == Opcode::xfer || op.op == Opcode::drop ||
                       ((op.op == Opcode::knit || op.op == Opcode::split) && op.carriers.empty());
    if (open && (stitch || moves) &&
        (has_open_loop(op.needle) || ((op.op == Opcode::split || op.op == Opcode::xfer) && has_open_loop(op.target))))
      close();
    // A carrier turning back along the bed it came (a flat row's turn), or passing over a
    // stitch it has already passed in this course, onto a needle holding loops, starts
    // the next course; a tube's turn onto the other bed, or a cast-on's onto empty
    // needles, does not.
    auto turns = [&](const std::vector<Run>& went) {
      for (int carrier : op.carriers)
        for (auto e = went.rbegin(); e != went.rend(); ++e)
          if (e->carrier == carrier) {
            if (e->direction != op.direction && e->on(front(op.needle.bed))) return true;
            break;
          }
      return false;
    };
    if (open && stitch && !machine.pile(op.needle).empty()) {
      const auto& went = courses.back().went;
      const double x = across(op.needle, courses.back().racking);
      const bool side = front(op.needle.bed);
      bool passed = turns(went);
      for (const Run& r : went)
        passed = passed || (std::find(op.carriers.begin(), op.carriers.end(), r.carrier) != op.carriers.end() && r.on(side) && r.passes(x));
      if (passed) close();
    }
    const std::size_t before = machine.loops().size();
    if (moves && !open) last_drop_line = op.line;
    machine.run(i);
    course_of.resize(machine.loops().size(), -1);
    if (machine.loops().size() > before) {
      if (!open) {
        courses.push_back({});
        courses.back().first_operation = static_cast<int>(i);
        courses.back().racking = machine.racking();
        open = true;
      }
      RawCourse& c = courses.back();
      course_of[before] = static_cast<int>(courses.size()) - 1;
      c.made.push_back(static_cast<int>(before));
      if (op.carriers.size() > 1 && plated++ == 0) plated_line = op.line;
      if (op.op == Opcode::split) ++splits;
      (front(op.needle.bed) ? out.front_loops : out.back_loops) += 1;
    }
    // Where the carriers went. A miss that turns back waits for the next stitch: it
    // belongs to that stitch's course, whichever that is.
    if (op.op == Opcode::miss) {
      const bool waits = !open || turns(courses.back().went);
      for (int carrier : op.carriers) {
        const Crossing c{carrier, across(op.needle, open ? courses.back().racking : machine.racking()), op.direction, front(op.needle.bed)};
        if (waits) add(waiting, c);
        else add(courses.back().went, c);
      }
    } else if (stitch && open) {
      auto& went = courses.back().went;
      for (const Run& r : waiting) {
        add(went, {r.carrier, r.low, r.direction, r.front});
        add(went, {r.carrier, r.high, r.direction, r.front});
        if (r.back) add(went, {r.carrier, r.high, r.direction, false});
      }
      waiting.clear();
      for (int carrier : op.carriers) add(went, {carrier, across(op.needle, courses.back().racking), op.direction, front(op.needle.bed)});
    }
  }
  close();
  if (courses.empty())
    throw KnitoutError(program.file + ":1: the program makes no loops; a knitout program knits, tucks or splits with a carrier", 1);
  if (plated > 0)
    out.warnings.push_back(program.file + ":" + std::to_string(plated_line) + ": warning: " + std::to_string(plated) +
                           " loops are plated (made with several carriers); each is drawn in its first carrier's yarn");

  // A bind-off's steps, each a course of a loop or two knitted through the last step's
  // loop moved onto an older stitch, are one course: every loop of the chain but the last
  // is bound off (bo), as a pattern's bind-off row says it.
  {
    std::vector<RawCourse> runs;
    std::vector<int> run_of(courses.size(), 0);
    bool small_run = false, chain_run = false;
    for (std::size_t c = 0; c < courses.size(); ++c) {
      RawCourse& raw = courses[c];
      bool step = false;
      if (!runs.empty() && small_run && raw.made.size() <= 2) {
        const int last = static_cast<int>(runs.size()) - 1;
        for (int l : raw.made) {
          bool chained = false, older = false;
          for (int q : machine.loops()[static_cast<std::size_t>(l)].parents) {
            const int at = course_of[static_cast<std::size_t>(q)];
            chained = chained || at == last;
            older = older || (at >= 0 && at < last);
          }
          // Through the chain's last loop and an older stitch; or, once a chain, its
          // loop knitted again on its needle (a bind-off that knits each step twice or more).
          step = step || (chained && (older || chain_run));
        }
      }
      if (step) {
        RawCourse& run = runs.back();
        run.made.insert(run.made.end(), raw.made.begin(), raw.made.end());
        run.went.insert(run.went.end(), raw.went.begin(), raw.went.end());
        run.positions = std::move(raw.positions);
        chain_run = true;
      } else {
        runs.push_back(std::move(raw));
        small_run = runs.back().made.size() <= 2;
        chain_run = false;
      }
      const int index = static_cast<int>(runs.size()) - 1;
      for (int l : runs.back().made) course_of[static_cast<std::size_t>(l)] = index;
      run_of[c] = index;
    }
    courses = std::move(runs);
  }

  // Flat or round: a tube's rounds knit the front bed one way and the back bed the other.
  int rounds = 0, sheets = 0;
  for (const RawCourse& c : courses) {
    std::set<std::pair<int, int>> ways;  // (carrier, direction) per bed side
    bool f = false, b = false, tube = false;
    std::map<int, std::pair<int, int>> by_carrier;  // carrier -> (front direction, back direction)
    for (int l : c.made) {
      const Loop& loop = machine.loops()[static_cast<std::size_t>(l)];
      auto& d = by_carrier[loop.carriers.front()];
      (front(loop.needle.bed) ? f : b) = true;
      (front(loop.needle.bed) ? d.first : d.second) = loop.direction;
    }
    for (const auto& [carrier, d] : by_carrier) tube = tube || (d.first != 0 && d.second != 0 && d.first != d.second);
    // Weighed by loops: a bind-off's steps (split on one bed, knit on the other) are not rounds.
    if (f && b) (tube ? rounds : sheets) += static_cast<int>(c.made.size());
    if (getenv("KNITOUT_DEBUG") && f && b) fprintf(stderr, "course at line %d: %s\n", program.operations[c.first_operation].line, tube ? "tube" : "sheet");
  }
  const bool round = rounds > sheets;

  Pattern& pattern = out.pattern;
  pattern.knitting = round ? Knitting::round : Knitting::flat;
  pattern.name = program.file;
  // The yarns: one per carrier that made a loop, sorted by name.
  std::vector<std::string> names;
  for (const Loop& l : machine.loops())
    for (int c : l.carriers) names.push_back(program.carriers[static_cast<std::size_t>(c)]);
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  std::vector<int> yarn_of(program.carriers.size(), 0);
  for (std::size_t c = 0; c < program.carriers.size(); ++c)
    yarn_of[c] = static_cast<int>(std::lower_bound(names.begin(), names.end(), program.carriers[c]) - names.begin());
  // The fabric's size from the machine's gauge: a loop as wide as the needles it spans
  // (full gauge one pitch, half gauge two), the yarn a quarter of that as in the seed paper.
  std::map<int, long long> gaps;
  for (const RawCourse& c : courses) {
    std::vector<int> on_front;
    for (const Position& p : c.positions)
      if (p.needle.bed == Bed::f) on_front.push_back(p.needle.index);
    std::sort(on_front.begin(), on_front.end());
    for (std::size_t k = 1; k < on_front.size(); ++k)
      if (on_front[k] - on_front[k - 1] <= 3) ++gaps[on_front[k] - on_front[k - 1]];
  }
  int spacing = 1;
  long long most = 0;
  for (const auto& [gap, count] : gaps)
    if (count > most) most = count, spacing = gap;
  const double pitch = 25.4 / profile.gauge;
  pattern.gauge.loop_width = pitch * spacing;
  pattern.gauge.loop_height = 1.05 * pattern.gauge.loop_width;
  pattern.gauge.thickness = 0.5 * pattern.gauge.loop_width;
  static const char* palette[] = {"#d9c8a9", "#8a1c2b", "#2f5d8a", "#e0b33a", "#3c7a4a", "#6b4a8a", "#c8643c", "#404040"};
  for (std::size_t y = 0; y < names.size(); ++y) {
    Yarn yarn;
    yarn.id = names[y];
    yarn.diameter = 0.25 * pattern.gauge.loop_width;
    yarn.core_diameter = yarn.diameter / yarn::free_per_core;
    yarn.color = palette[y % std::size(palette)];
    pattern.yarns.push_back(yarn);
  }
  for (const Operation& op : program.operations) {  // x-vis-color #rrggbb C
    if (op.op != Opcode::extension || !op.words.starts_with("x-vis-color")) continue;
    std::vector<std::string> w;
    for (std::size_t at = 0; at < op.words.size();) {
      const std::size_t e = std::min(op.words.find(' ', at), op.words.size());
      if (e > at) w.push_back(op.words.substr(at, e - at));
      at = e + 1;
    }
    if (w.size() != 3 || w[1].size() != 7 || w[1][0] != '#') continue;
    for (Yarn& y : pattern.yarns)
      if (y.id == w[2]) y.color = w[1];
  }

  // Each course in stitches.
  const std::vector<Loop>& loops = machine.loops();
  std::vector<int> stitch_of(loops.size(), -1);
  std::size_t live = 0;
  const StitchId k = stitch_id("k"), p = stitch_id("p"), yo = stitch_id("yo"), tuck = stitch_id("tuck"),
                 held = stitch_id("held"), kfb = stitch_id("kfb"), pfb = stitch_id("pfb");
  std::vector<int> on_needles;  // the loops stitch_of names
  std::vector<char> placed(loops.size(), 0), split_parent(loops.size(), 0);
  int approximated = 0;
  for (std::size_t ci = 0; ci < courses.size(); ++ci) {
    RawCourse& raw = courses[ci];
    const Operation& first = program.operations[static_cast<std::size_t>(raw.first_operation)];
    auto fail = [&](const std::string& message, const std::string& hint) {
      throw KnitoutError(located(program, first, message, hint), first.line);
    };
    std::vector<Position>& pos = raw.positions;
    std::sort(pos.begin(), pos.end(), [&](const Position& a, const Position& b) {
      if (round && front(a.needle.bed) != front(b.needle.bed)) return front(a.needle.bed);
      if (round && !front(a.needle.bed)) return a.x > b.x;
      return a.x < b.x;
    });
    const int mine = static_cast<int>(ci);
    auto is_new = [&](int l) { return course_of[static_cast<std::size_t>(l)] == mine; };
    if (ci == 0) {  // the cast-on: loops on empty needles
      for (const Position& q : pos)
        for (int l : q.pile)
          if (!is_new(l)) fail("the first course knits into loops that were never made", "cast on first");
      pattern.cast_on = static_cast<int>(pos.size());
      pattern.cast_on_yarn = yarn_of[static_cast<std::size_t>(loops[static_cast<std::size_t>(raw.made.front())].carriers.front())];
      for (std::size_t j = 0; j < pos.size(); ++j)
        for (int l : pos[j].pile) {
          stitch_of[static_cast<std::size_t>(l)] = static_cast<int>(j);
          on_needles.push_back(l);
        }
      live = pos.size();
      continue;
    }
    Course course;
    course.where = {program.file, first.line};
    const Loop& opener = loops[static_cast<std::size_t>(raw.made.front())];
    course.side = round || opener.direction < 0 ? Side::right : Side::wrong;
    const int course_yarn = yarn_of[static_cast<std::size_t>(opener.carriers.front())];

    enum class Kind { made, tucked, unworked, partner };
    struct Info {
      Kind kind = Kind::unworked;
      std::vector<int> stitches;  // of the course before, sorted
      int loop = -1;              // the new loop (made, tucked)
      int top = -1;               // the stitch of the loop on top (made)
    };
    std::vector<Info> info(pos.size());
    std::string odd;  // why the course can only be drawn approximately
    std::vector<char> used(live, 0);
    for (int l : raw.made)
      if (loops[static_cast<std::size_t>(l)].made_by == Opcode::split)
        for (int q : loops[static_cast<std::size_t>(l)].parents) split_parent[static_cast<std::size_t>(q)] = 1;
    auto stitches_of = [&](const std::vector<int>& ls) {
      std::vector<int> s;
      for (int l : ls) {
        const int st = stitch_of[static_cast<std::size_t>(l)];
        if (st < 0) fail("a loop reappears that was not on a needle at the last course", "this is a bug in knitc's machine; please report it");
        s.push_back(st);
      }
      std::sort(s.begin(), s.end());
      s.erase(std::unique(s.begin(), s.end()), s.end());
      return s;
    };
    for (std::size_t j = 0; j < pos.size(); ++j) {
      Info& f = info[j];
      const auto& pile = pos[j].pile;
      std::vector<int> old;
      int fresh = 0;
      for (int l : pile) {
        if (is_new(l)) ++fresh;
        else old.push_back(l);
      }
      if (fresh == 0) {
        const bool all_split = std::all_of(old.begin(), old.end(), [&](int l) { return split_parent[static_cast<std::size_t>(l)] != 0; });
        f.kind = all_split ? Kind::partner : Kind::unworked;
        f.stitches = stitches_of(old);
      } else if (pile.size() == 1 && loops[static_cast<std::size_t>(pile[0])].made_by != Opcode::tuck) {
        f.kind = Kind::made;
        f.loop = pile[0];
        // Through the older loops; a bind-off's chain also goes through its own last loop.
        std::vector<int> older;
        for (int q : loops[static_cast<std::size_t>(pile[0])].parents)
          if (!is_new(q)) older.push_back(q);
        f.stitches = stitches_of(older);
        if (!older.empty()) f.top = stitch_of[static_cast<std::size_t>(older.back())];
      } else if (fresh == 1 && is_new(pile.back()) && loops[static_cast<std::size_t>(pile.back())].made_by == Opcode::tuck) {
        f.kind = Kind::tucked;
        f.loop = pile.back();
        f.stitches = stitches_of(old);
      } else {  // new loops under old ones, or several new: drawn as one loop through the old
        odd = "needle " + name(pos[j].needle) + " holds new loops under or among old ones";
        f.kind = Kind::made;
        for (int l : pile)
          if (is_new(l) && f.loop < 0) f.loop = l;
        f.stitches = stitches_of(old);
      }
      if (f.kind != Kind::partner)
        for (int s : f.stitches) used[static_cast<std::size_t>(s)] = 1;
    }
    // The stitches a loop of the course went through that is on no needle now: bound off
    // (a later loop of the course was knitted through it).
    std::vector<char> bound(live, 0);
    for (const Position& q : pos)
      for (int l : q.pile) placed[static_cast<std::size_t>(l)] = 1;
    for (int l : raw.made) {
      if (placed[static_cast<std::size_t>(l)]) continue;
      for (int q : loops[static_cast<std::size_t>(l)].parents)
        if (!is_new(q) && stitch_of[static_cast<std::size_t>(q)] >= 0) bound[static_cast<std::size_t>(stitch_of[static_cast<std::size_t>(q)])] = 1;
    }
    for (const Position& q : pos)
      for (int l : q.pile) placed[static_cast<std::size_t>(l)] = 0;
    // Whether a yarn of the course passed x without a stitch there.
    auto crossed = [&](double x, int& carrier) {
      for (const Run& r : raw.went)
        if (r.passes(x)) {
          carrier = r.carrier;
          return true;
        }
      return false;
    };
    auto yarn_for = [&](int loop) { return yarn_of[static_cast<std::size_t>(loops[static_cast<std::size_t>(loop)].carriers.front())]; };
    std::size_t next = 0;
    auto emit = [&](StitchId s, int yarn) { course.ops.push_back({s, yarn}); };
    struct Unsupported {
      std::string why;
    };
    auto unsupported = [](const std::string& message, const std::string& hint) {
      throw Unsupported{hint.empty() ? message : message + "; " + hint};
    };
    try {
    if (!odd.empty()) unsupported(odd, "");
    for (std::size_t j = 0; j < pos.size();) {
      const Info& f = info[j];
      while (next < live && !used[next]) emit(bound[next] ? bo : drop, course_yarn), ++next;
      const bool purl_side = !round && !front(pos[j].needle.bed);
      if (f.kind == Kind::partner) {
        // A split's old loops beside its new loop: an increase, both loops through the stitch.
        if (j + 1 < pos.size() && info[j + 1].kind == Kind::made && info[j + 1].stitches == f.stitches &&
            f.stitches.size() == 1 && static_cast<std::size_t>(f.stitches.front()) == next) {
          emit(purl_side ? pfb : kfb, yarn_for(info[j + 1].loop));
          next = static_cast<std::size_t>(f.stitches.back()) + 1;
          j += 2;
        } else {
          emit(yo, course_yarn);  // beside it the other way: drawn as the split's loop's neighbour
          ++j;
        }
        continue;
      }
      const bool contiguous = !f.stitches.empty() && static_cast<std::size_t>(f.stitches.front()) == next &&
                              f.stitches.back() - f.stitches.front() + 1 == static_cast<int>(f.stitches.size());
      if (f.stitches.empty()) {
        emit(yo, f.loop >= 0 ? yarn_for(f.loop) : course_yarn);
        ++j;
        continue;
      }
      if (contiguous) {
        const int n = static_cast<int>(f.stitches.size());
        const bool split_next = j + 1 < pos.size() && info[j + 1].kind == Kind::partner && info[j + 1].stitches == f.stitches;
        StitchId s = none;
        if (f.kind == Kind::made && split_next && n == 1) {
          emit(purl_side ? pfb : kfb, yarn_for(f.loop));
          ++j;
        } else if (f.kind == Kind::made) {
          const bool left_top = f.top == f.stitches.front(), right_top = f.top == f.stitches.back();
          if (n == 1) s = purl_side ? p : k;
          else if (n == 2) s = stitch_id(purl_side ? (left_top ? "p2tog" : "ssp") : (left_top ? "k2tog" : "ssk"));
          else if (n == 3) s = purl_side ? stitch_id("p3tog") : stitch_id(left_top ? "k3tog" : right_top ? "sssk" : "cdd");
          else if (n == 5) s = stitch_id(purl_side ? "p5tog" : "k5tog");
          else unsupported(std::to_string(n) + " loops are knitted together on " + name(pos[j].needle) + "; knitc draws decreases of 2, 3 or 5",
                    "decrease in steps of at most three loops");
          emit(s, yarn_for(f.loop));
        } else if (f.kind == Kind::tucked) {
          if (n != 1) unsupported("a tuck on " + name(pos[j].needle) + " over " + std::to_string(n) + " stacked loops; knitc draws a tuck on one stitch",
                           "knit the stacked loops together before tucking on them");
          emit(tuck, yarn_for(f.loop));
        } else {
          if (n != 1) unsupported("loops of " + std::to_string(n) + " stitches stacked on " + name(pos[j].needle) + " and left unknitted",
                           "knit them together in the next course");
          int carrier = -1;
          if (crossed(pos[j].x, carrier))
            emit(stitch_id(purl_side ? "sl wyif" : "sl wyib"), yarn_of[static_cast<std::size_t>(carrier)]);
          else
            emit(held, course_yarn);
        }
        next = static_cast<std::size_t>(f.stitches.back()) + 1;
        ++j;
        continue;
      }
      // Single stitches in another order: a cable, the two groups changing places.
      std::size_t width = 0;
      {
        int low = 1 << 30, high = -1;
        for (std::size_t t = j; t < pos.size() && t - j < 8; ++t) {
          if (info[t].stitches.size() != 1 || info[t].kind != Kind::made) break;
          low = std::min(low, info[t].stitches[0]);
          high = std::max(high, info[t].stitches[0]);
          if (static_cast<std::size_t>(low) == next && high - low == static_cast<int>(t - j) && t > j) {
            width = t - j + 1;
            break;
          }
        }
      }
      StitchId s = none;
      if (width > 0) {
        // The order after: the right group (`held`, first here) then the left one.
        const int w = static_cast<int>(width);
        const int held_n = static_cast<int>(next) + w - info[j].stitches[0];
        bool ok = held_n > 0 && held_n < w;
        for (int t = 0; ok && t < w; ++t) {
          const int want = t < held_n ? static_cast<int>(next) + w - held_n + t : static_cast<int>(next) + t - held_n;
          ok = info[j + static_cast<std::size_t>(t)].stitches[0] == want;
        }
        if (ok) {
          // The group whose loops reached their needles first lies on top.
          int right_settled = -1, left_settled = -1;
          for (int t = 0; t < w; ++t) {
            const Loop& l = loops[static_cast<std::size_t>(info[j + static_cast<std::size_t>(t)].loop)];
            int settled = -1;
            for (int q : l.parents) settled = std::max(settled, machine.moved_at()[static_cast<std::size_t>(q)]);
            (t < held_n ? right_settled : left_settled) = std::max(t < held_n ? right_settled : left_settled, settled);
          }
          s = cable_stitch(w, held_n, right_settled < left_settled);
        }
      }
      if (s == none) {
        std::string seen;
        for (std::size_t t = j; t < pos.size() && t < j + 8; ++t) {
          seen += " " + name(pos[t].needle) + ":";
          for (int q : info[t].stitches) seen += std::to_string(q - static_cast<int>(next)) + ",";
          seen += std::to_string(static_cast<int>(info[t].kind));
        }
        unsupported("the loops knitted on " + name(pos[j].needle) + " and beside it were moved past each other in a way knitc cannot yet draw (" + seen + ")",
             "knitc draws crosses of two groups of up to four stitches each, swapped by racked transfers");
      }
      emit(s, yarn_for(info[j].loop));
      next += width;
      j += width;
    }
    while (next < live) {
      if (used[next]) unsupported("the stitches of the course before are knitted out of their order", "");
      emit(bound[next] ? bo : drop, course_yarn);
      ++next;
    }
    } catch (const Unsupported& e) {
      // Drawn approximately: each live stitch through as many stitches of the course before
      // as its loops came from, in order; the rest bound off.
      course.ops.clear();
      std::size_t taken = 0;
      for (std::size_t j = 0; j < pos.size(); ++j) {
        const Info& f = info[j];
        const std::size_t n = f.kind == Kind::partner ? 0 : std::min<std::size_t>({f.stitches.size(), 3, live - taken});
        const bool purl_side = !round && !front(pos[j].needle.bed);
        const int yarn = f.loop >= 0 ? yarn_for(f.loop) : course_yarn;
        StitchId s = yo;
        if (n == 1) s = f.kind == Kind::made ? (purl_side ? p : k) : f.kind == Kind::tucked ? tuck : held;
        if (n == 2) s = stitch_id(purl_side ? "p2tog" : "k2tog");
        if (n == 3) s = stitch_id(purl_side ? "p3tog" : "k3tog");
        emit(s, yarn);
        taken += n;
      }
      for (; taken < live; ++taken) emit(bo, course_yarn);
      if (approximated++ < 5)
        out.warnings.push_back(program.file + ":" + std::to_string(first.line) + ": warning: drawn approximately: " + e.why);
    }
    for (int l : raw.made)
      if (loops[static_cast<std::size_t>(l)].made_by == Opcode::split)
        for (int q : loops[static_cast<std::size_t>(l)].parents) split_parent[static_cast<std::size_t>(q)] = 0;
    if (getenv("KNITOUT_DEBUG") && (static_cast<std::size_t>(consumed(course)) != live || static_cast<std::size_t>(produced(course)) != pos.size())) {
      fprintf(stderr, "line %d: consumed %d of %zu, produced %d of %zu:", first.line, consumed(course), live, produced(course), pos.size());
      for (const Op& o : course.ops) fprintf(stderr, " %s", std::string(stitch(o.stitch).name).c_str());
      fprintf(stderr, "\n");
      for (std::size_t j = 0; j < pos.size(); ++j) {
        fprintf(stderr, "  %s kind %d:", name(pos[j].needle).c_str(), static_cast<int>(info[j].kind));
        for (int q : info[j].stitches) fprintf(stderr, " %d", q);
        fprintf(stderr, "\n");
      }
    }
    for (int l : on_needles) stitch_of[static_cast<std::size_t>(l)] = -1;
    on_needles.clear();
    for (std::size_t j = 0; j < pos.size(); ++j)
      for (int l : pos[j].pile) {
        stitch_of[static_cast<std::size_t>(l)] = static_cast<int>(j);
        on_needles.push_back(l);
      }
    live = pos.size();
    pattern.courses.push_back(std::move(course));
  }
  // A last course that binds off every stitch but the one the chain ends on is the
  // pattern's bind-off: the knitter pulls the yarn through that last loop.
  if (!pattern.courses.empty()) {
    const Course& last = pattern.courses.back();
    int bound = 0, kept = 0;
    for (const Op& op : last.ops) (op.stitch == bo ? bound : kept) += 1;
    const bool chain_end = kept == 1 && bound >= 1 &&
                           std::any_of(last.ops.begin(), last.ops.end(), [&](const Op& op) {
                             return op.stitch == stitch_id("k") || op.stitch == stitch_id("p");
                           });
    if (chain_end && pattern.courses.size() > 1) {
      pattern.courses.pop_back();
      pattern.bound_off = true;
    }
  }
  // A drop the knit graph cannot unravel (through a decrease or a held tuck below it):
  // drawn bound off at that row, and said.
  for (int tries = 0;; ++tries) {
    try {
      knit_graph::build(pattern);
      break;
    } catch (const knit_graph::RowError& e) {
      const std::size_t row = static_cast<std::size_t>(e.course - 1);
      if (row >= pattern.courses.size()) throw;
      Course& c = pattern.courses[row];
      // Each try builds the graph again: past a few rows of them, every later drop is
      // drawn bound off at once, so a program of many such drops stays linear.
      const std::size_t last = tries < 8 ? row + 1 : pattern.courses.size();
      int changed = 0;
      for (std::size_t r = row; r < last; ++r)
        for (Op& op : pattern.courses[r].ops)
          if (op.stitch == drop) op.stitch = bo, ++changed;
      if (changed == 0 || tries > 8)
        throw KnitoutError(program.file + ":" + std::to_string(c.where.line) + ": " + e.what(), c.where.line);
      out.warnings.push_back(program.file + ":" + std::to_string(c.where.line) + ": warning: " + std::to_string(changed) +
                             " loops dropped " + (last == row + 1 ? "here" : "here and after") + " cannot run down their wales (" + e.what() +
                             "); drawn bound off");
    }
  }
  if (approximated > 5)
    out.warnings.push_back(program.file + ": warning: " + std::to_string(approximated - 5) + " more courses drawn approximately");
  // Loops taken off after the last course (a final drop) are drawn as they were: open.
  std::size_t dropped_at_end = 0;
  for (const Position& q : courses.back().positions)
    if (machine.pile(q.needle) != q.pile) ++dropped_at_end;
  if (dropped_at_end > 0)
    out.warnings.push_back(program.file + ":" + std::to_string(last_drop_line) + ": warning: the program ends by dropping " +
                           std::to_string(dropped_at_end) + " live loops of its last course, unsecured; they are drawn open, "
                           "as on the needles (on the machine they would run unless bound off or held by waste yarn)");
  (void)splits;
  return out;
}

Imported import_text(std::string_view text, const std::string& file) {
  const Program program = parse(text, file);
  return import_program(program, profile_for(program));
}

}  // namespace knitc::knitout

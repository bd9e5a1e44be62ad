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

#include "columns.hpp"
#include "cut.hpp"
#include "knit_graph/knit_graph.hpp"
#include "knitout.hpp"

namespace knitc::knitout {

namespace {

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
  Machine machine(program, profile);
  Cut cut = cut_courses(program, machine);
  out.warnings = program.warnings;
  out.warnings.insert(out.warnings.end(), cut.warnings.begin(), cut.warnings.end());
  out.front_loops = cut.front_loops;
  out.back_loops = cut.back_loops;
  std::vector<RawCourse>& courses = cut.courses;
  const std::vector<int>& course_of = cut.course_of;
  const bool round = cut.round;
  const int last_drop_line = cut.last_drop_line;

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
  const long spacing = spacing_of(courses, round);
  const double pitch = 25.4 / profile.gauge;
  pattern.gauge.loop_width = pitch * static_cast<double>(spacing);
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
  std::vector<double> live_x;   // flat: each live stitch's place across the beds (Position::x)
  // Per course, the yarn overs (op indexes) made in the column of the stitch worked just
  // before them.
  std::vector<std::vector<std::size_t>> shared_column(courses.size());
  std::vector<char> placed(loops.size(), 0), split_parent(loops.size(), 0);
  int approximated = 0;
  // Per course after the cast-on, where it made a loop (for the needles' widths, below).
  std::vector<std::vector<char>> worked(courses.size());
  for (std::size_t ci = 0; ci < courses.size(); ++ci) {
    RawCourse& raw = courses[ci];
    const Operation& first = program.operations[static_cast<std::size_t>(raw.first_operation)];
    auto fail = [&](const std::string& message, const std::string& hint) {
      throw KnitoutError(located(program, first, message, hint), first.line);
    };
    std::vector<Position>& pos = raw.positions;
    // A tube's live stitches by layer (its wale's: the bottom loop's, not a tuck's on it),
    // whichever bed holds them now.
    auto front_layer = [&](const Position& q) { return cut.front_layer[static_cast<std::size_t>(q.pile.front())] != 0; };
    std::sort(pos.begin(), pos.end(), [&](const Position& a, const Position& b) {
      if (round && front_layer(a) != front_layer(b)) return front_layer(a);
      if (round && !front_layer(a)) return a.x > b.x;
      return a.x < b.x;
    });
    // A stitch seen as a purl: flat, one on the back bed; round, one whose new loop was
    // made (or, with none, whose needle is) on its layer's other bed.
    auto purl_at = [&](const Position& q, int loop) {
      if (!round) return !front(q.needle.bed);
      const Bed bed = loop >= 0 ? loops[static_cast<std::size_t>(loop)].needle.bed : q.needle.bed;
      return front(bed) != front_layer(q);
    };
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
      for (const Position& q : pos) live_x.push_back(q.x);
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
    // A loop made by two carriers is plated: the second's yarn knitted into it with the
    // first's (a third and more are drawn as the first: cut.cpp warns).
    auto emit_made = [&](StitchId s, int loop) {
      const std::vector<int>& carriers = loops[static_cast<std::size_t>(loop)].carriers;
      const int second = carriers.size() > 1 ? yarn_of[static_cast<std::size_t>(carriers[1])] : -1;
      course.ops.push_back({s, yarn_for(loop), second == yarn_for(loop) ? -1 : second});
    };
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
      // The stitches left unworked before this one: bound off or dropped. Before a new loop
      // through none of them (a yarn over, a split's loop), in flat work only those to its
      // left, so that it stands where the machine made it (a split bind-off leaves a loop
      // over each stitch it binds off, not a row of them past the last).
      const bool through_none = f.kind != Kind::partner && f.stitches.empty();
      while (next < live && !used[next] && (round || !through_none || live_x[next] <= pos[j].x))
        emit(bound[next] ? bo : drop, course_yarn), ++next;
      const bool purl_side = purl_at(pos[j], f.loop);
      if (f.kind == Kind::partner) {
        // A split's old loops beside its new loop: an increase, both loops through the stitch.
        if (j + 1 < pos.size() && info[j + 1].kind == Kind::made && info[j + 1].stitches == f.stitches &&
            f.stitches.size() == 1 && static_cast<std::size_t>(f.stitches.front()) == next) {
          emit_made(purl_side ? pfb : kfb, info[j + 1].loop);
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
        // Made in the needle column of the stitch just worked (a split bind-off's loop,
        // over the stitch bound off, or the chain's last loop): the two share the column.
        if (!round && next > 0 && !course.ops.empty()) {
          const StitchDef& before = stitch(course.ops.back().stitch);
          const bool bound_there = course.ops.back().stitch == bo && std::abs(live_x[next - 1] - pos[j].x) < 0.5;
          const bool knitted_there = before.consumes == 1 && before.produces == 1 && j > 0 && std::abs(pos[j - 1].x - pos[j].x) < 0.5;
          if (bound_there || knitted_there) shared_column[ci].push_back(course.ops.size());
        }
        if (f.loop >= 0) emit_made(yo, f.loop);
        else emit(yo, course_yarn);
        ++j;
        continue;
      }
      if (contiguous) {
        const int n = static_cast<int>(f.stitches.size());
        const bool split_next = j + 1 < pos.size() && info[j + 1].kind == Kind::partner && info[j + 1].stitches == f.stitches;
        StitchId s = none;
        if (f.kind == Kind::made && split_next && n == 1) {
          emit_made(purl_side ? pfb : kfb, f.loop);
          ++j;
        } else if (f.kind == Kind::made) {
          const bool left_top = f.top == f.stitches.front(), right_top = f.top == f.stitches.back();
          if (n == 1) s = purl_side ? p : k;
          else if (n == 2) s = stitch_id(purl_side ? (left_top ? "p2tog" : "ssp") : (left_top ? "k2tog" : "ssk"));
          else if (n == 3) s = purl_side ? stitch_id("p3tog") : stitch_id(left_top ? "k3tog" : right_top ? "sssk" : "cdd");
          else if (n == 5) s = stitch_id(purl_side ? "p5tog" : "k5tog");
          else unsupported(std::to_string(n) + " loops are knitted together on " + name(pos[j].needle) + "; knitc draws decreases of 2, 3 or 5",
                    "decrease in steps of at most three loops");
          emit_made(s, f.loop);
        } else if (f.kind == Kind::tucked) {
          if (n != 1) unsupported("a tuck on " + name(pos[j].needle) + " over " + std::to_string(n) + " stacked loops; knitc draws a tuck on one stitch",
                           "knit the stacked loops together before tucking on them");
          emit_made(tuck, f.loop);
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
      emit_made(s, info[j].loop);
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
      shared_column[ci].clear();
      std::size_t taken = 0;
      for (std::size_t j = 0; j < pos.size(); ++j) {
        const Info& f = info[j];
        const std::size_t n = f.kind == Kind::partner ? 0 : std::min<std::size_t>({f.stitches.size(), 3, live - taken});
        const bool purl_side = purl_at(pos[j], f.loop);
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
    for (int l : on_needles) stitch_of[static_cast<std::size_t>(l)] = -1;
    on_needles.clear();
    for (std::size_t j = 0; j < pos.size(); ++j)
      for (int l : pos[j].pile) {
        stitch_of[static_cast<std::size_t>(l)] = static_cast<int>(j);
        on_needles.push_back(l);
      }
    live = pos.size();
    live_x.clear();
    for (const Position& q : pos) live_x.push_back(q.x);
    worked[ci].resize(pos.size());
    for (std::size_t j = 0; j < pos.size(); ++j) worked[ci][j] = info[j].kind == Kind::made || info[j].kind == Kind::tucked;
    pattern.courses.push_back(std::move(course));
  }
  // Where both beds' loops share needle columns, each position's width (columns.hpp).
  if (!round) {
    ColumnWidths widths = column_widths(courses, worked, loops, static_cast<int>(spacing));
    const bool layered = widths.layered() || widths.in_turn;
    pattern.cast_on_widths = std::move(widths.cast_on);
    pattern.cast_on_layers = std::move(widths.cast_on_layers);
    for (std::size_t ci = 1; ci < courses.size() && ci - 1 < widths.courses.size(); ++ci) {
      pattern.courses[ci - 1].widths = std::move(widths.courses[ci - 1]);
      pattern.courses[ci - 1].layers = std::move(widths.layers[ci - 1]);
    }
    // Two layers: each course as high as its layer's loops need.
    if (layered) {
      const std::vector<double> rises = layer_rises(loops, course_of, courses);
      for (std::size_t ci = 1; ci < courses.size(); ++ci) pattern.courses[ci - 1].rise = rises[ci - 1];
    }
  }
  // A loop made in the column of the stitch just worked shares it (columns.hpp).
  for (std::size_t ci = 1; ci < courses.size(); ++ci) share_columns(pattern.courses[ci - 1], shared_column[ci]);
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
  return out;
}

Imported import_text(std::string_view text, const std::string& file) {
  const Program program = parse(text, file);
  return import_program(program, profile_for(program));
}

}  // namespace knitc::knitout

// Knitout in: the machine run and its loops cut into courses (cut.hpp).
#include "cut.hpp"

#include <algorithm>
#include <map>
#include <optional>

namespace knitc::knitout {

namespace {

// Where a course is a pass along one bed and a pass back along the other with one yarn
// (made by knits and tucks only, the second through none of the first's loops): the
// index in `made` where the second pass starts, else 0.
std::size_t second_pass(const RawCourse& c, const std::vector<Loop>& loops) {
  if (c.made.size() < 2) return 0;
  const Loop& head = loops[static_cast<std::size_t>(c.made.front())];
  const bool side = front(head.needle.bed);
  std::size_t turn = 0;
  for (std::size_t i = 0; i < c.made.size(); ++i) {
    const Loop& loop = loops[static_cast<std::size_t>(c.made[i])];
    if (loop.carriers != head.carriers || (loop.made_by != Opcode::knit && loop.made_by != Opcode::tuck)) return 0;
    const bool first = turn == 0 && front(loop.needle.bed) == side && loop.direction == head.direction;
    if (turn == 0 && !first) turn = i;
    if (turn != 0 && (front(loop.needle.bed) == side || loop.direction != -head.direction)) return 0;
  }
  if (turn == 0 || head.direction == 0) return 0;
  for (std::size_t i = turn; i < c.made.size(); ++i)
    for (int q : loops[static_cast<std::size_t>(c.made[i])].parents)
      if (std::find(c.made.begin(), c.made.begin() + static_cast<std::ptrdiff_t>(turn), q) != c.made.begin() + static_cast<std::ptrdiff_t>(turn))
        return 0;
  return turn;
}

// Flat work whose course is a pass along one bed and back along the other (a Milano
// rib's jersey passes between its rib rows, a few rounds of tube in a flat program) is
// two courses, one per bed, as a flat row's turn is: read as one, as a tube's round is,
// its yarn would run the width and back within a course of a flat sheet. The first
// course's needles as they stood at its end: the second's loops replaced by the loops
// they were knitted through.
void split_passes(Cut& cut, const Machine& machine) {
  const std::vector<Loop>& loops = machine.loops();
  std::vector<RawCourse> out;
  out.reserve(cut.courses.size());
  std::vector<char> second(loops.size(), 0);
  for (RawCourse& c : cut.courses) {
    const std::size_t turn = second_pass(c, loops);
    if (turn == 0) {
      out.push_back(std::move(c));
      continue;
    }
    RawCourse a, b;
    a.first_operation = c.first_operation;
    b.first_operation = loops[static_cast<std::size_t>(c.made[turn])].operation;
    a.racking = b.racking = c.racking;
    a.made.assign(c.made.begin(), c.made.begin() + static_cast<std::ptrdiff_t>(turn));
    b.made.assign(c.made.begin() + static_cast<std::ptrdiff_t>(turn), c.made.end());
    // The runs are in the order the carrier went: the first pass's up to its turn.
    const int way = loops[static_cast<std::size_t>(c.made.front())].direction;
    bool turned = false;
    for (const Run& r : c.went) {
      turned = turned || r.direction == -way;
      (turned ? b.went : a.went).push_back(r);
    }
    for (int l : b.made) second[static_cast<std::size_t>(l)] = 1;
    for (const Position& p : c.positions) {
      Position q{p.needle, p.x, {}};
      for (int l : p.pile) {
        if (!second[static_cast<std::size_t>(l)]) q.pile.push_back(l);
        else if (loops[static_cast<std::size_t>(l)].made_by == Opcode::knit)
          q.pile.insert(q.pile.end(), loops[static_cast<std::size_t>(l)].parents.begin(), loops[static_cast<std::size_t>(l)].parents.end());
      }
      if (!q.pile.empty()) a.positions.push_back(std::move(q));
    }
    for (int l : b.made) second[static_cast<std::size_t>(l)] = 0;
    b.positions = std::move(c.positions);
    out.push_back(std::move(a));
    out.push_back(std::move(b));
  }
  cut.courses = std::move(out);
  for (std::size_t i = 0; i < cut.courses.size(); ++i)
    for (int l : cut.courses[i].made) cut.course_of[static_cast<std::size_t>(l)] = static_cast<int>(i);
}

}  // namespace

Cut cut_courses(const Program& program, Machine& machine) {
  Cut cut;
  std::vector<RawCourse>& courses = cut.courses;
  std::vector<int>& course_of = cut.course_of;
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
  std::size_t plated = 0;
  int plated_line = 0;
  int& last_drop_line = cut.last_drop_line;
  std::vector<Run> waiting;  // misses before the next course opens
  std::map<int, int> last_way;  // per carrier: the direction it last stitched in
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
      // A carrier turning back into a new pass on needles this course has not stitched (a
      // spacer's layer after the tucks between them, a jacquard's next colour, a rib's
      // pass starting on the other bed): the pass starts the next course if it goes on to
      // stitch where this course already has, or its first loops would be drawn a course
      // low.
      const auto last = last_way.find(op.carriers.front());
      if (!passed && last != last_way.end() && last->second != op.direction && op.direction != 0)
        for (std::size_t k = i + 1; k < program.operations.size() && !passed; ++k) {
          const Operation& next = program.operations[k];
          const bool stitches = next.op == Opcode::knit || next.op == Opcode::tuck || next.op == Opcode::split;
          if ((!stitches && next.op != Opcode::miss) || next.carriers != op.carriers || next.direction != op.direction) break;
          passed = stitches && has_open_loop(next.needle);
        }
      if (passed) close();
    }
    if (stitch && op.direction != 0) last_way[op.carriers.front()] = op.direction;
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
      if (op.carriers.size() > 2 && plated++ == 0) plated_line = op.line;
      (front(op.needle.bed) ? cut.front_loops : cut.back_loops) += 1;
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
  cut.warnings.insert(cut.warnings.end(), machine.warnings().begin(), machine.warnings().end());
  if (courses.empty())
    throw KnitoutError(program.file + ":1: the program makes no loops; a knitout program knits, tucks or splits with a carrier", 1);
  if (plated > 0)
    cut.warnings.push_back(program.file + ":" + std::to_string(plated_line) + ": warning: " + std::to_string(plated) +
                           " loops are made with three or more carriers; each is drawn plated with its first two carriers' yarns, the first on the back");

  // A bind-off's steps, each a course of a loop or two knitted through the last step's
  // loop moved onto an older stitch, are one course: every loop of the chain but the last
  // is bound off (bo), as a pattern's bind-off row says it.
  {
    std::vector<RawCourse> runs;
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
    }
    courses = std::move(runs);
  }

  // Each loop's layer, were the fabric a tube: its wale's, the layer of the loop it was
  // pulled through (the top one); a loop through none (cast on, a tuck, a yarn-over) is of
  // the bed it was made on. Not the bed of a loop pulled through another: a layer's purls
  // are knitted on the other bed, and a half-gauge tube parks a layer's loops on either.
  const std::vector<Loop>& loops = machine.loops();
  std::vector<char>& layer = cut.front_layer;
  layer.resize(loops.size());
  for (std::size_t l = 0; l < loops.size(); ++l) {
    const Loop& loop = loops[l];
    layer[l] = loop.parents.empty() ? front(loop.needle.bed) : layer[static_cast<std::size_t>(loop.parents.back())];
  }
  // A course that is one pass: one carrier, one direction, and every loop on one side, as
  // `side_of` (a loop's index) tells it: its layer, or its bed.
  struct Pass {
    int carrier, direction;
    bool side;
  };
  auto pass_of = [&](const RawCourse& c, auto&& side_of) -> std::optional<Pass> {
    if (c.made.empty()) return std::nullopt;
    const Loop& head = loops[static_cast<std::size_t>(c.made.front())];
    const Pass pass{head.carriers.front(), head.direction, side_of(c.made.front())};
    if (pass.direction == 0) return std::nullopt;
    for (int l : c.made) {
      const Loop& loop = loops[static_cast<std::size_t>(l)];
      if (loop.carriers.front() != pass.carrier || loop.direction != pass.direction || side_of(l) != pass.side) return std::nullopt;
    }
    return pass;
  };
  auto layer_of = [&](int l) { return layer[static_cast<std::size_t>(l)] != 0; };
  auto bed_of = [&](int l) { return front(loops[static_cast<std::size_t>(l)].needle.bed); };
  // A tube's two passes cut apart by transfers between them (a half-gauge tube parks one
  // layer's loops, or moves its purls, between its passes): one carrier each, one direction
  // each, the two opposite and of the two layers, the second knitting through none of the
  // first's loops. They are one round.
  {
    std::vector<RawCourse> merged;
    for (std::size_t c = 0; c < courses.size(); ++c) {
      const auto a = pass_of(courses[c], layer_of);
      const auto b = a && c + 1 < courses.size() ? pass_of(courses[c + 1], layer_of) : std::nullopt;
      bool pair = b && a->carrier == b->carrier && a->direction == -b->direction && a->side != b->side;
      for (std::size_t i = 0; pair && i < courses[c + 1].made.size(); ++i)
        for (int q : loops[static_cast<std::size_t>(courses[c + 1].made[i])].parents)
          pair = pair && course_of[static_cast<std::size_t>(q)] != static_cast<int>(c);
      if (!pair) {
        merged.push_back(std::move(courses[c]));
      } else {
        RawCourse both = std::move(courses[c]);
        RawCourse& second = courses[c + 1];
        both.made.insert(both.made.end(), second.made.begin(), second.made.end());
        both.went.insert(both.went.end(), second.went.begin(), second.went.end());
        both.positions = std::move(second.positions);
        merged.push_back(std::move(both));
        ++c;
      }
      for (int l : merged.back().made) course_of[static_cast<std::size_t>(l)] = static_cast<int>(merged.size()) - 1;
    }
    courses = std::move(merged);
  }

  // Flat or round: a tube's rounds knit the front layer one way and the back layer the
  // other, on both beds, each round turning the way the last one did. A Milano rib's
  // passes between its rib rows go round so too, but turn the other way each time (three
  // passes a row): only a round that turns as its carrier's last did (or its first)
  // counts.
  int rounds = 0, sheets = 0;
  std::map<int, int> turning;  // per carrier: the way its last round knitted the front layer
  // A pass along one bed whose carrier's next pass comes back along the same bed is a flat
  // row (an i-cord cast-on's fabric, knitted on the front bed only after its cord's rounds);
  // a tube's passes, where not one round, go to the other bed.
  std::vector<std::size_t> next_pass(courses.size(), courses.size());  // the next course its first loop's carrier made
  {
    std::map<int, std::size_t> later;
    for (std::size_t at = courses.size(); at-- > 0;) {
      if (courses[at].made.empty()) continue;
      const int carrier = loops[static_cast<std::size_t>(courses[at].made.front())].carriers.front();
      if (const auto it = later.find(carrier); it != later.end()) next_pass[at] = it->second;
      later[carrier] = at;
    }
  }
  auto turns_on_its_bed = [&](std::size_t at) {
    const auto pass = pass_of(courses[at], bed_of);
    const auto next = pass && next_pass[at] < courses.size() ? pass_of(courses[next_pass[at]], bed_of) : std::nullopt;
    return next && next->direction == -pass->direction && next->side == pass->side;
  };
  for (std::size_t at = 0; at < courses.size(); ++at) {
    const RawCourse& c = courses[at];
    bool f = false, b = false;
    int tube = -1, way = 0;  // the carrier that went round, and its way along the front layer
    std::map<int, std::pair<int, int>> by_carrier;  // carrier -> (front layer's direction, back layer's)
    for (int l : c.made) {
      const Loop& loop = loops[static_cast<std::size_t>(l)];
      auto& d = by_carrier[loop.carriers.front()];
      (front(loop.needle.bed) ? f : b) = true;
      (layer[static_cast<std::size_t>(l)] != 0 ? d.first : d.second) = loop.direction;
    }
    for (const auto& [carrier, d] : by_carrier)
      if (tube < 0 && d.first != 0 && d.second != 0 && d.first != d.second) tube = carrier, way = d.first;
    // Weighed by loops: a bind-off's steps (split on one bed, knit on the other) are not rounds.
    if (!f || !b) {
      if (turns_on_its_bed(at)) sheets += static_cast<int>(c.made.size());
      continue;
    }
    if (tube < 0) {
      sheets += static_cast<int>(c.made.size());
      continue;
    }
    const auto last = turning.find(tube);
    if (last == turning.end() || last->second == way) rounds += static_cast<int>(c.made.size());
    turning[tube] = way;
  }
  cut.round = rounds > sheets;
  if (!cut.round) split_passes(cut, machine);

  return cut;
}

}  // namespace knitc::knitout

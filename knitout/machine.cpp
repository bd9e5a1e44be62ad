#include "machine.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace knitc::knitout {

namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  return s;
}

std::string number_text(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", v);
  return buffer;
}

const std::vector<int> no_loops;

}  // namespace

Profile profile_named(const std::string& name) {
  // A Shima SWG091N2: 15 gauge, 36 inches of bed, racking up to 8 pitches, 10 carriers.
  if (name == "swg") return {"swg", 540, 15.0, 8.0, 10, true};
  // A Kniterate: 7 gauge, 252 needles a bed, racking up to 4 pitches, 6 carriers, no sliders.
  if (name == "kniterate") return {"kniterate", 252, 7.0, 4.0, 6, false};
  throw std::invalid_argument("unknown machine profile '" + name + "'; knitc knows swg (a Shima SWG-like V-bed) and kniterate");
}

Profile profile_for(const Program& program) {
  const std::string* machine = program.header("Machine");
  Profile p = profile_named(machine && lower(*machine).find("kniterate") != std::string::npos ? "kniterate" : "swg");
  if (machine) {
    if (*machine == "SWG061N2") p.needles = 360;
  }
  if (const std::string* g = program.header("Gauge")) {
    const double v = std::atof(g->c_str());
    if (v >= 1.0 && v <= 30.0) p.gauge = v;
  }
  if (const std::string* w = program.header("Width")) {
    const int v = std::atoi(w->c_str());
    if (v >= 1 && v <= 100000) p.needles = v;
  }
  return p;
}

Machine::Machine(const Program& program, Profile profile)
    : program_(program), profile_(std::move(profile)), in_(program.carriers.size(), 0), hooked_(program.carriers.size(), 0) {}

const std::vector<int>& Machine::pile(Needle needle) const {
  const auto it = piles_.find(key(needle));
  return it == piles_.end() ? no_loops : it->second;
}

std::vector<Needle> Machine::occupied() const {
  std::vector<Needle> out;
  for (const auto& [k, p] : piles_)
    if (!p.empty()) out.push_back({static_cast<Bed>(k & 3), static_cast<int>(k >> 2)});
  return out;
}

void Machine::fail(const Operation& op, const std::string& message, const std::string& hint) const {
  throw KnitoutError(located(program_, op, message, hint), op.line);
}

void Machine::check_needle(const Operation& op, Needle n) {
  const int low = std::min(lowest_, n.index), high = std::max(highest_ < lowest_ ? n.index : highest_, n.index);
  if (profile_.needles > 0 && high - low + 1 > profile_.needles)
    fail(op, name(n) + " is beyond the machine's bed: the program would span needles " + std::to_string(low) + " to " +
                 std::to_string(high) + ", " + std::to_string(high - low + 1) + " needles, and the " + profile_.name + " bed has " +
                 std::to_string(profile_.needles),
         "knit narrower, or name a wider machine in the ;;Width: header");
  lowest_ = low;
  highest_ = high;
}

void Machine::check_carriers(const Operation& op) {
  for (int c : op.carriers)
    if (!in_[static_cast<std::size_t>(c)])
      fail(op, std::string(name(op.op)) + " with carrier " + program_.carriers[static_cast<std::size_t>(c)] + ", which is not in",
           "bring it in first with 'inhook " + program_.carriers[static_cast<std::size_t>(c)] + "' (or 'in')");
}

void Machine::check_aligned(const Operation& op, Needle from, Needle to) const {
  if (front(from.bed) == front(to.bed))
    fail(op, std::string(name(op.op)) + " from " + name(from) + " to " + name(to) + ": both needles are on the same side",
         "loops move between the front (f, fs) and the back (b, bs) beds");
  const Needle f = front(from.bed) ? from : to, b = front(from.bed) ? to : from;
  if (std::abs(static_cast<double>(f.index - b.index) - racking_) > 1e-9) {
    const double needed = f.index - b.index;
    fail(op, std::string(name(op.op)) + " from " + name(from) + " to " + name(to) + ": the needles are not aligned at racking " + number_text(racking_),
         "at racking R front needle n faces back needle n - R: rack " + number_text(needed) + " first");
  }
}

void Machine::check_pile(const Operation& op, Needle n) {
  const std::size_t held = pile_of(n).size();
  if (held > static_cast<std::size_t>(profile_.most_loops))
    fail(op, "needle " + name(n) + " holds " + std::to_string(held) + " loops, past the " + std::to_string(profile_.most_loops) +
                 " a needle can knit off",
         "knit the loops off sooner, or spread the tucks or the decrease over more needles");
}

void Machine::move(std::size_t index, Needle from, Needle to) {
  auto& source = pile_of(from);
  if (source.empty()) return;
  auto& target = pile_of(to);
  for (int l : source) {
    target.push_back(l);  // onto the loops already there: the moved loops lie on top
    moved_at_[static_cast<std::size_t>(l)] = static_cast<int>(index);
  }
  pile_of(from).clear();
  check_pile(program_.operations[index], to);
}

void Machine::run(std::size_t index) {
  const Operation& op = program_.operations[index];
  switch (op.op) {
    case Opcode::in: case Opcode::inhook:
      // A machine has one yarn inserting hook: it holds one carrier set until released.
      if (op.op == Opcode::inhook)
        for (std::size_t c = 0; c < hooked_.size(); ++c)
          if (hooked_[c]) {
            warnings_.push_back(located(program_, op, "warning: inhook while carrier " + program_.carriers[c] +
                                                          " is still on the yarn inserting hook (from line " + std::to_string(hooked_line_) + ")",
                                        "a machine has one hook: release it first with 'releasehook " + program_.carriers[c] + "'"));
            break;
          }
      if (op.op == Opcode::inhook) hooked_line_ = op.line;
      for (int c : op.carriers) {
        if (in_[static_cast<std::size_t>(c)])
          fail(op, "carrier " + program_.carriers[static_cast<std::size_t>(c)] + " is in already", "take it out first, or leave out this line");
        in_[static_cast<std::size_t>(c)] = 1;
        hooked_[static_cast<std::size_t>(c)] = op.op == Opcode::inhook;
      }
      return;
    case Opcode::releasehook:
      for (int c : op.carriers) hooked_[static_cast<std::size_t>(c)] = 0;
      return;
    case Opcode::out: case Opcode::outhook:
      for (int c : op.carriers) {
        if (!in_[static_cast<std::size_t>(c)])
          fail(op, "carrier " + program_.carriers[static_cast<std::size_t>(c)] + " is not in", "only a carrier brought in can go out");
        in_[static_cast<std::size_t>(c)] = 0;
        hooked_[static_cast<std::size_t>(c)] = 0;  // out with it, hook and all
      }
      return;
    case Opcode::rack:
      if (std::abs(op.racking) > profile_.max_racking + 1e-9)
        fail(op, "racking " + number_text(op.racking) + " is beyond the " + profile_.name + "'s reach of " + number_text(profile_.max_racking) + " needles",
             "make the move in smaller steps");
      racking_ = op.racking;
      return;
    case Opcode::stitch: case Opcode::pause: case Opcode::extension: return;
    case Opcode::miss:
      check_needle(op, op.needle);
      check_carriers(op);
      return;
    case Opcode::amiss:
      check_needle(op, op.needle);
      return;
    case Opcode::drop:
      check_needle(op, op.needle);
      pile_of(op.needle).clear();
      return;
    case Opcode::xfer:
      check_needle(op, op.needle);
      check_needle(op, op.target);
      check_aligned(op, op.needle, op.target);
      move(index, op.needle, op.target);
      return;
    case Opcode::knit: case Opcode::tuck: case Opcode::split: {
      check_needle(op, op.needle);
      if (op.op == Opcode::split) {
        check_needle(op, op.target);
        check_aligned(op, op.needle, op.target);
      }
      if (slider(op.needle.bed))
        fail(op, std::string(name(op.op)) + " on slider " + name(op.needle), "sliders hold loops in transfers; knit on f or b");
      check_carriers(op);
      if (op.carriers.empty()) {  // no yarn: knit drops, tuck tugs, split transfers
        if (op.op == Opcode::knit) pile_of(op.needle).clear();
        if (op.op == Opcode::split) move(index, op.needle, op.target);
        return;
      }
      Loop l;
      l.made_by = op.op;
      l.needle = op.needle;
      l.direction = op.direction;
      l.carriers = op.carriers;
      l.operation = static_cast<int>(index);
      const int id = static_cast<int>(loops_.size());
      auto& here = pile_of(op.needle);
      if (op.op == Opcode::tuck) {
        here.push_back(id);
        check_pile(op, op.needle);
      } else {
        l.parents = here;
        if (op.op == Opcode::split) {
          auto& there = pile_of(op.target);
          for (int p : here) {
            there.push_back(p);
            moved_at_[static_cast<std::size_t>(p)] = static_cast<int>(index);
          }
          check_pile(op, op.target);
        }
        auto& again = pile_of(op.needle);  // the target's insertion may have moved the map's storage
        again.assign(1, id);
      }
      loops_.push_back(std::move(l));
      moved_at_.push_back(-1);
      return;
    }
  }
}

}  // namespace knitc::knitout

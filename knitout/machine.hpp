// The V-bed machine a knitout program drives: two beds and their sliders, each needle's
// ordered pile of loops, the racking, the carriers. It runs the operations one at a time,
// refuses what the machine cannot do (with the line), and keeps every loop it made and
// the loops each was pulled through: the machine's own knit graph.
#pragma once

#include <string>
#include <unordered_map>
#include <vector>

#include "program.hpp"

namespace knitc::knitout {

// What the numbers of a program mean on one kind of machine.
struct Profile {
  std::string name;        // "swg" (a Shima SWG-like), "kniterate"
  int needles = 0;         // per bed: the widest span a program may use
  double gauge = 15.0;     // needles per inch
  double max_racking = 8;  // needle pitches either way
  int carriers = 10;
  bool sliders = true;     // slider needles (fs, bs) to hold loops in transfers
  // Loops one needle may hold (tucks and stacked transfers): past a few a machine cannot
  // knit them off, and every one would lie at one point (27 real programs and the CMU
  // examples hold at most 3).
  int most_loops = 8;
};
Profile profile_named(const std::string& name);  // throws std::invalid_argument for an unknown one
// The profile a program's header names (";;Machine:", ";;Gauge:", ";;Width:"), else the SWG-like one.
Profile profile_for(const Program& program);

// One loop the machine made.
struct Loop {
  Opcode made_by = Opcode::knit;  // knit, tuck or split
  Needle needle;                  // where it was made
  int direction = 0;
  std::vector<int> carriers;      // its yarns (several: plated)
  std::vector<int> parents;       // the pile it was pulled through, bottom to top (none for a tuck)
  int operation = 0;              // index into Program::operations
};

class Machine {
 public:
  Machine(const Program& program, Profile profile);

  // Runs operations[index]. Throws KnitoutError for what the machine cannot do. Warnings
  // (a loop dropped that was holding others up, ...) go to warnings().
  void run(std::size_t index);

  const std::vector<int>& pile(Needle needle) const;
  // Every needle holding loops.
  std::vector<Needle> occupied() const;
  double racking() const { return racking_; }
  const std::vector<Loop>& loops() const { return loops_; }
  // When each loop last moved (the operation's index), or -1: a cable's crossing order.
  const std::vector<int>& moved_at() const { return moved_at_; }
  const Profile& profile() const { return profile_; }
  // "file:line: warning: ..." for what a machine would not do but knitc can still draw.
  const std::vector<std::string>& warnings() const { return warnings_; }

 private:
  static long long key(Needle n) { return (static_cast<long long>(n.index) << 2) | static_cast<long long>(n.bed); }
  std::vector<int>& pile_of(Needle n) { return piles_[key(n)]; }
  [[noreturn]] void fail(const Operation& op, const std::string& message, const std::string& hint) const;
  void check_needle(const Operation& op, Needle n);
  void check_carriers(const Operation& op);
  void check_aligned(const Operation& op, Needle from, Needle to) const;
  void check_pile(const Operation& op, Needle n);
  void move(std::size_t index, Needle from, Needle to);

  const Program& program_;
  Profile profile_;
  std::unordered_map<long long, std::vector<int>> piles_;
  std::vector<Loop> loops_;
  std::vector<int> moved_at_;
  double racking_ = 0.0;
  std::vector<char> in_;            // per carrier: brought in
  std::vector<char> hooked_;        // per carrier: held by the inserting hook
  int hooked_line_ = 0;             // the line of the inhook that holds them
  std::vector<std::string> warnings_;
  int lowest_ = 0, highest_ = -1;   // the needles used so far, for the bed's width
};

}  // namespace knitc::knitout

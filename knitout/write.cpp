// A pattern written as a knitout program (knitout.hpp): each live stitch on a needle,
// each course's transfers planned so that stacked loops land in the order the stitch
// wants (the loop on top last), then the course knitted pass by pass, a pass per yarn.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "knitout.hpp"

namespace knitc::knitout {

namespace {

struct Place {
  bool back = false;
  int needle = 0;
  bool operator==(const Place&) const = default;
  bool operator<(const Place& o) const { return back != o.back ? !back : needle < o.needle; }
};

std::string needle_name(Place p) { return (p.back ? "b" : "f") + std::to_string(p.needle); }

std::string number(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", v);
  return b;
}

// A stitch's loops moving to a needle; a later priority lands after (on top of) an earlier.
struct Move {
  int stitch;
  Place from, to;
  int priority = 0;
  std::string_view what;  // the stitch that asks for it, for messages
};

struct Writer {
  const Pattern& pattern;
  const Profile& profile;
  std::string out;
  double rack = 0.0;
  std::vector<char> in;          // per yarn: brought in
  std::vector<char> hooked;      // per yarn: its hook not yet released
  std::vector<Place> live;       // each live stitch's needle, face order
  SourceLocation where;          // the course being written
  int highest = 0;

  void put(const std::string& s) {
    out += s;
    out += '\n';
  }
  std::string carrier(int yarn) const { return std::to_string(yarn + 1); }
  [[noreturn]] void fail(const std::string& message, const std::string& hint) const {
    throw KnitoutError(where.file + ":" + std::to_string(where.line) + ": " + message + "; " + hint, where.line);
  }
  void use(Place p) {
    highest = std::max(highest, p.needle);
    if (profile.needles > 0 && p.needle > profile.needles)
      fail("the fabric needs " + std::to_string(p.needle) + " needles and the " + profile.name + " bed has " + std::to_string(profile.needles),
           "knit fewer stitches, or choose a wider machine");
  }
  void set_rack(double r, const std::string& why) {
    if (std::abs(r) > profile.max_racking + 1e-9)
      fail("'" + why + "' needs a racking of " + number(r) + " and the " + profile.name + " reaches " + number(profile.max_racking),
           "cross or shift fewer stitches at once");
    if (r != rack) put("rack " + number(r));
    rack = r;
  }
  void bring_in(int yarn) {
    if (in[static_cast<std::size_t>(yarn)]) return;
    if (yarn + 1 > profile.carriers)
      fail("yarn " + pattern.yarns[static_cast<std::size_t>(yarn)].id + " needs carrier " + carrier(yarn) + " and the " + profile.name +
               " has " + std::to_string(profile.carriers),
           "use fewer yarns");
    put("inhook " + carrier(yarn));
    in[static_cast<std::size_t>(yarn)] = 1;
    hooked[static_cast<std::size_t>(yarn)] = 1;
  }
  void release(int yarn) {
    if (!hooked[static_cast<std::size_t>(yarn)]) return;
    put("releasehook " + carrier(yarn));
    hooked[static_cast<std::size_t>(yarn)] = 0;
  }

  // The transfers that bring every stitch to its place: those staying on their bed are
  // parked on the other bed at racking 0 first; then, racking by racking, each lands once
  // nothing still to leave is on its needle and every lower priority bound there is in.
  void transfer(std::vector<Move> moves) {
    std::map<Place, std::vector<int>> on;  // stitches on each needle
    for (std::size_t s = 0; s < live.size(); ++s) on[live[s]].push_back(static_cast<int>(s));
    std::vector<Move> pending;
    for (Move m : moves) {
      if (m.from == m.to && m.priority == 0) continue;
      if (m.from.back == m.to.back) {  // park on the other bed first
        const Place parked{!m.from.back, m.from.needle};
        if (!on[parked].empty()) fail("knitc cannot yet plan the transfers of this row", "this is a limit of knitc's writer; please report the pattern");
        set_rack(0.0, std::string(m.what));
        put("xfer " + needle_name(m.from) + " " + needle_name(parked));
        auto& here = on[m.from];
        here.erase(std::find(here.begin(), here.end(), m.stitch));
        on[parked].push_back(m.stitch);
        m.from = parked;
      }
      pending.push_back(m);
    }
    auto still_to_leave = [&](Place p) {
      for (const Move& m : pending)
        if (m.from == p) return true;
      return false;
    };
    while (!pending.empty()) {
      // A later priority waits for every earlier one: a cable's under group lands before
      // its top group, a decrease's loop on top after the others.
      int lowest = pending.front().priority;
      for (const Move& m : pending) lowest = std::min(lowest, m.priority);
      std::vector<std::size_t> ready;
      for (std::size_t i = 0; i < pending.size(); ++i)
        if (pending[i].priority == lowest && !still_to_leave(pending[i].to)) ready.push_back(i);
      if (ready.empty()) fail("knitc cannot yet plan the transfers of this row", "this is a limit of knitc's writer; please report the pattern");
      auto racking = [&](const Move& m) { return m.from.back ? m.to.needle - m.from.needle : m.from.needle - m.to.needle; };
      std::size_t pick = ready.front();
      for (std::size_t i : ready)
        if (std::abs(racking(pending[i]) - rack) < std::abs(racking(pending[pick]) - rack)) pick = i;
      const int r = racking(pending[pick]);
      set_rack(r, std::string(pending[pick].what));
      std::vector<Move> rest;
      for (std::size_t i = 0; i < pending.size(); ++i) {
        const Move& m = pending[i];
        if (std::find(ready.begin(), ready.end(), i) == ready.end() || racking(m) != r) {
          rest.push_back(m);
          continue;
        }
        use(m.to);
        put("xfer " + needle_name(m.from) + " " + needle_name(m.to));
        auto& here = on[m.from];
        here.erase(std::find(here.begin(), here.end(), m.stitch));
        on[m.to].push_back(m.stitch);
      }
      pending = std::move(rest);
    }
    set_rack(0.0, "");
    for (const Move& m : moves) live[static_cast<std::size_t>(m.stitch)] = m.to;
  }
};

}  // namespace

Exported export_pattern(const Pattern& pattern, const Profile& profile) {
  Writer w{pattern, profile, {}, 0.0, std::vector<char>(pattern.yarns.size(), 0), std::vector<char>(pattern.yarns.size(), 0), {}, {}, 0};
  Exported result;
  const bool round = pattern.knitting == Knitting::round;
  w.where = pattern.courses.empty() ? SourceLocation{pattern.name, 1} : pattern.courses.front().where;
  w.put(";!knitout-2");
  w.put(";;Machine: " + std::string(profile.name == "kniterate" ? "Kniterate" : "SWG091N2"));
  w.put(";;Gauge: " + number(profile.gauge));
  w.put(";;Width: " + std::to_string(profile.needles));
  std::string rails = ";;Carriers:";
  for (int c = 1; c <= profile.carriers; ++c) rails += " " + std::to_string(c);
  w.put(rails);
  for (std::size_t y = 0; y < pattern.yarns.size(); ++y)
    w.put(";;Yarn-" + w.carrier(static_cast<int>(y)) + ": " + pattern.yarns[y].id + " " + pattern.yarns[y].color);
  w.put(";;Position: Center");

  // Where live stitch p of n sits: flat, needle p + 1 (stitches keep their place, the
  // course's shifts are transfers); round, a tube: the front bed then the back bed.
  auto tube_place = [](int p, int n) {
    const int h = (n + 1) / 2;
    return p < h ? Place{false, p + 1} : Place{true, n - p};
  };
  // The cast-on: alternate tucks, right to left then back, on empty needles.
  const int n0 = pattern.cast_on;
  if (n0 <= 0) w.fail("the pattern casts on no stitches", "cast on before knitting");
  for (int p = 0; p < n0; ++p) w.live.push_back(round ? tube_place(p, n0) : Place{false, p + 1});
  w.put(";!source: " + w.where.file + ":" + std::to_string(w.where.line) + " (cast on " + std::to_string(n0) + ")");
  w.bring_in(pattern.cast_on_yarn);
  const std::string cast = w.carrier(pattern.cast_on_yarn);
  if (round) {
    for (int p = n0 - 1; p >= 0; --p)
      if (w.live[static_cast<std::size_t>(p)].back) w.put("tuck + " + needle_name(w.live[static_cast<std::size_t>(p)]) + " " + cast);
    for (int p = n0 - 1; p >= 0; --p)
      if (!w.live[static_cast<std::size_t>(p)].back) w.put("tuck - " + needle_name(w.live[static_cast<std::size_t>(p)]) + " " + cast);
  } else {
    for (int p = n0 - 1; p >= 0; p -= 2) w.put("tuck - " + needle_name(w.live[static_cast<std::size_t>(p)]) + " " + cast);
    for (int p = n0 % 2 == 0 ? 0 : 1; p < n0; p += 2) w.put("tuck + " + needle_name(w.live[static_cast<std::size_t>(p)]) + " " + cast);
  }
  for (const Place& p : w.live) w.use(p);

  for (const Course& course : pattern.courses) {
    w.where = course.where;
    w.put(";!source: " + course.where.file + ":" + std::to_string(course.where.line));
    // Each op: the stitches it takes (from), the loops it leaves (at), in face order.
    struct Step {
      const Op* op;
      int from = 0, to = 0;  // [from, from + consumes) of the live, [to, to + produces) of the next
    };
    std::vector<Step> steps;
    int taken = 0, made = 0;
    for (const Op& op : course.ops) {
      const StitchDef& s = stitch(op.stitch);
      const std::string name(s.name);
      const bool plain_cable = s.family == StitchFamily::cable && s.cable.middle == 0 && !s.cable.purl_background && !s.cable.purled && !s.twisted;
      const bool ok = name == "k" || name == "p" || name == "yo" || name == "tuck" || name == "held" || name == "sl wyib" || name == "sl wyif" ||
                      name == "drop" || name == "k2tog" || name == "ssk" || name == "p2tog" || name == "ssp" || name == "k3tog" ||
                      name == "sssk" || name == "cdd" || name == "p3tog" || plain_cable;
      if (!ok)
        w.fail("knitc cannot yet write '" + name + "' for a knitting machine", "the machine writer knows k, p, yo, tuck, slips, held stitches, drops, "
               "k2tog, ssk, p2tog, ssp, k3tog, sssk, cdd, p3tog and knit crosses (C4F, 2/1 LC, ...)");
      if (round && !(name == "k" || name == "tuck" || name == "held" || name == "sl wyib"))
        w.fail("knitc cannot yet write '" + name + "' in the round", "in the round the machine writer knows k, tuck, held and sl wyib (a tube on both beds)");
      steps.push_back({&op, taken, made});
      taken += s.consumes;
      made += s.produces;
    }
    if (taken != static_cast<int>(w.live.size())) w.fail("the row works " + std::to_string(taken) + " stitches of " + std::to_string(w.live.size()), "the pattern's rows must work every live stitch");
    // Where the next live stitches go: flat, contiguous from a left edge that keeps the
    // plain stitches where they are (the median of their shifts); round, the tube's places.
    std::vector<Place> next(static_cast<std::size_t>(made));
    int left = 1;
    if (!round) {
      std::vector<int> shifts;
      for (const Step& st : steps)
        if (stitch(st.op->stitch).consumes == 1 && stitch(st.op->stitch).produces == 1)
          shifts.push_back(w.live[static_cast<std::size_t>(st.from)].needle - st.to);
      if (!shifts.empty()) {
        std::sort(shifts.begin(), shifts.end());
        left = shifts[shifts.size() / 2];
      }
      left = std::max(left, 1);
    }
    std::vector<Move> moves;
    std::vector<Place> drops;
    for (const Step& st : steps) {
      const StitchDef& s = stitch(st.op->stitch);
      const std::string name(s.name);
      for (int j = 0; j < s.produces; ++j) {
        Place p = round ? tube_place(st.to + j, made) : Place{false, left + st.to + j};
        if (purled(s) || name == "sl wyif") p.back = true;
        if ((name == "held" || name == "tuck") && !round) p.back = w.live[static_cast<std::size_t>(st.from)].back;
        next[static_cast<std::size_t>(st.to + j)] = p;
      }
      if (s.family == StitchFamily::drop) {
        drops.push_back(w.live[static_cast<std::size_t>(st.from)]);
        continue;
      }
      if (s.family == StitchFamily::cable) {
        // The group that lands first lies underneath: the held group lands first unless it crosses on top.
        for (int j = 0; j < s.produces; ++j) {
          const int from = st.from + cable_source(s, j);
          const bool held_group = j < s.cable.held;
          moves.push_back({from, w.live[static_cast<std::size_t>(from)], next[static_cast<std::size_t>(st.to + j)],
                           held_group == s.cable.front ? 0 : 1, s.name});
        }
        continue;
      }
      if (s.consumes == 0) continue;
      const Place target = next[static_cast<std::size_t>(st.to)];
      // The stitch whose loop lies on top of a decrease lands last.
      int top = -1;
      if (s.consumes > 1) top = s.lean == Lean::left ? s.consumes - 1 : s.lean == Lean::centre ? s.consumes / 2 : 0;
      for (int k = 0; k < s.consumes; ++k) {
        const int from = st.from + k;
        moves.push_back({from, w.live[static_cast<std::size_t>(from)], target, k == top ? 1 : 0, s.name});
      }
    }
    for (const Place& p : drops) w.put("drop " + needle_name(p));
    // Drops leave the live list: the moves name live stitches by index, which stay valid.
    w.transfer(moves);
    // Knit the course, a pass per yarn, in working order.
    const bool leftwards = round || course.side == Side::right;
    std::vector<int> order(steps.size());
    for (std::size_t i = 0; i < steps.size(); ++i) order[i] = static_cast<int>(leftwards ? steps.size() - 1 - i : i);
    std::vector<int> yarns;
    for (int i : order)
      if (std::find(yarns.begin(), yarns.end(), steps[static_cast<std::size_t>(i)].op->yarn) == yarns.end())
        yarns.push_back(steps[static_cast<std::size_t>(i)].op->yarn);
    for (int y : yarns) {
      w.bring_in(y);
      const std::string c = w.carrier(y);
      // Plating: a loop knitted with a second yarn names both carriers, the first yarn's
      // first (docs/knitout.md, "Plating").
      std::vector<int> plating;
      for (int i : order) {
        const Op& op = *steps[static_cast<std::size_t>(i)].op;
        if (op.yarn == y && op.plated >= 0 && std::find(plating.begin(), plating.end(), op.plated) == plating.end())
          plating.push_back(op.plated);
      }
      for (int q : plating) w.bring_in(q);
      // The loops in working order; a tube's back bed goes rightwards, its front leftwards.
      std::vector<std::pair<int, const Step*>> work;  // (next index, step)
      for (int i : order) {
        const Step& st = steps[static_cast<std::size_t>(i)];
        if (st.op->yarn != y) continue;
        const int n = stitch(st.op->stitch).produces;
        for (int j = 0; j < n; ++j) work.push_back({st.to + (leftwards ? n - 1 - j : j), &st});
      }
      bool any = false;
      Place last{};
      std::vector<Place> slipped;
      auto direction = [&](Place p) { return round ? (p.back ? "+" : "-") : (leftwards ? "-" : "+"); };
      for (const auto& [index, st] : work) {
        const StitchDef& s = stitch(st->op->stitch);
        const Place p = next[static_cast<std::size_t>(index)];
        if (s.family == StitchFamily::slip && !s.unreached) {
          if (!any) {  // the yarn comes from beyond it
            const Place before{p.back, p.needle + (std::string(direction(p)) == "-" ? 1 : -1)};
            w.use(before);
            w.put("miss " + std::string(direction(p)) + " " + needle_name(before) + " " + c);
            any = true;
          }
          slipped.push_back(p);
          last = p;
          continue;
        }
        if (s.unreached) continue;
        w.use(p);
        w.put(std::string(s.family == StitchFamily::tuck ? "tuck " : "knit ") + direction(p) + " " + needle_name(p) + " " + c +
              (st->op->plated >= 0 ? " " + w.carrier(st->op->plated) : ""));
        slipped.clear();
        any = true;
        last = p;
      }
      if (!slipped.empty()) {  // and goes on past the last
        const Place beyond{last.back, last.needle + (std::string(direction(last)) == "-" ? -1 : 1)};
        if (beyond.needle >= 0) w.put("miss " + std::string(direction(last)) + " " + needle_name(beyond) + " " + c);
      }
      w.release(y);
      for (int q : plating) w.release(q);
    }
    w.live = std::move(next);
  }
  if (pattern.bound_off) {
    w.put(";!source: " + w.where.file + ":" + std::to_string(w.where.line) + " (bind off)");
    if (round && !profile.sliders) {
      result.warnings.push_back(w.where.file + ":" + std::to_string(w.where.line) + ": warning: the " + profile.name +
                                " has no sliders to bind off a tube with; the loops are left on the needles");
    } else if (round && !w.live.empty()) {
      // A chain round the tube, as the rounds go: the back bed rightwards, the front
      // leftwards; each loop parked on the slider facing it, racked one needle on, and
      // put down on the next stitch, which is knitted through both.
      const int yarn = pattern.courses.empty() ? pattern.cast_on_yarn : pattern.courses.back().ops.back().yarn;
      w.bring_in(yarn);
      const std::string c = w.carrier(yarn);
      const int n = static_cast<int>(w.live.size());
      for (int k = 0; k < n; ++k) {
        const Place p = w.live[static_cast<std::size_t>(n - 1 - k)];
        if (k > 0) {
          const Place q = w.live[static_cast<std::size_t>(n - k)];
          if (q.back != p.back) {  // round the edge, from the back bed onto the front
            w.set_rack(p.needle - q.needle, "the bind-off");
            w.put("xfer " + needle_name(q) + " " + needle_name(p));
          } else {
            w.set_rack(0.0, "the bind-off");
            const std::string slider = std::string(q.back ? "fs" : "bs") + std::to_string(q.needle);
            w.put("xfer " + needle_name(q) + " " + slider);
            w.set_rack(q.back ? q.needle - p.needle : p.needle - q.needle, "the bind-off");
            w.put("xfer " + slider + " " + needle_name(p));
          }
          w.set_rack(0.0, "the bind-off");
        }
        w.put(std::string("knit ") + (p.back ? "+ " : "- ") + needle_name(p) + " " + c);
      }
      w.release(yarn);
    } else if (!w.live.empty()) {
      // A chain: the first stitch knitted, then each loop moved onto the next stitch and
      // knitted through both, the way the next row would go.
      const bool leftwards = pattern.courses.empty() || pattern.courses.back().side != Side::right;
      const int yarn = pattern.courses.empty() ? pattern.cast_on_yarn : pattern.courses.back().ops.back().yarn;
      w.bring_in(yarn);
      const std::string c = w.carrier(yarn);
      const int n = static_cast<int>(w.live.size());
      const char* d = leftwards ? "-" : "+";
      for (int k = 0; k < n; ++k) {
        const int at = leftwards ? n - 1 - k : k;
        if (k > 0) {
          const int from = leftwards ? at + 1 : at - 1;
          w.transfer({{from, w.live[static_cast<std::size_t>(from)], w.live[static_cast<std::size_t>(at)], 1, "the bind-off"}});
        }
        w.put(std::string("knit ") + d + " " + needle_name(w.live[static_cast<std::size_t>(at)]) + " " + c);
      }
      w.release(yarn);
    }
  }
  for (std::size_t y = 0; y < pattern.yarns.size(); ++y)
    if (w.in[y]) w.put("outhook " + w.carrier(static_cast<int>(y)));
  result.text = std::move(w.out);
  return result;
}

}  // namespace knitc::knitout

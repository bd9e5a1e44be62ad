#include "stitches/stitches.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <deque>
#include <string>
#include <vector>

namespace knitc {

namespace {

using F = StitchFamily;

constexpr StitchDef plain(std::string_view name, int consumes, int produces, F family, Lean lean, std::string_view ws) {
  StitchDef d;
  d.name = name;
  d.consumes = consumes;
  d.produces = produces;
  d.family = family;
  d.lean = lean;
  d.wrong_side_face = ws;
  return d;
}

// Cn F/B: n stitches, n/2 held; Tn F/B: the knit stitches that travel are held in front
// (F) or the purl ones in back (B), over a purl background.
constexpr StitchDef cable(std::string_view name, int width, int held, bool front, bool twist) {
  StitchDef d = plain(name, width, width, F::cable, Lean::none, "");
  d.cable = {held, front, twist};
  return d;
}

constexpr auto core = std::to_array<StitchDef>({
    plain("k", 1, 1, F::knit, Lean::none, "p"),
    plain("p", 1, 1, F::purl, Lean::none, "k"),
    plain("yo", 0, 1, F::yarn_over, Lean::none, "yo"),
    plain("k2tog", 2, 1, F::decrease, Lean::right, "p2tog"),
    plain("ssk", 2, 1, F::decrease, Lean::left, "ssp"),
    plain("p2tog", 2, 1, F::decrease, Lean::right, "k2tog"),
    plain("ssp", 2, 1, F::decrease, Lean::left, "ssk"),
    plain("k3tog", 3, 1, F::decrease, Lean::right, "p3tog"),
    plain("p3tog", 3, 1, F::decrease, Lean::right, "k3tog"),
    plain("cdd", 3, 1, F::decrease, Lean::centre, ""),
    plain("sk2p", 3, 1, F::decrease, Lean::left, ""),
    plain("sl wyib", 1, 1, F::slip, Lean::none, "sl wyif"),
    plain("sl wyif", 1, 1, F::slip, Lean::none, "sl wyib"),
    plain("tuck", 1, 1, F::tuck, Lean::none, "tuck"),
    plain("no stitch", 0, 0, F::no_stitch, Lean::none, "no stitch"),
    cable("C2F", 2, 1, true, false),
    cable("C2B", 2, 1, false, false),
    cable("C4F", 4, 2, true, false),
    cable("C4B", 4, 2, false, false),
    cable("C6F", 6, 3, true, false),
    cable("C6B", 6, 3, false, false),
    cable("C8F", 8, 4, true, false),
    cable("C8B", 8, 4, false, false),
    cable("T2F", 2, 1, true, true),
    cable("T2B", 2, 1, false, true),
    cable("T3F", 3, 2, true, true),
    cable("T3B", 3, 1, false, true),
    cable("T4F", 4, 2, true, true),
    cable("T4B", 4, 2, false, true),
});


constexpr StitchDef with(StitchDef d, bool twisted, bool below) {
  d.twisted = twisted;
  d.below = below;
  return d;
}

constexpr StitchDef clustered(StitchDef d, double width) {
  d.cluster_width = width;
  return d;
}

constexpr StitchDef wrapping(StitchDef d, int turns) {
  d.wraps = turns;
  return d;
}

constexpr StitchDef unreached(StitchDef d) {
  d.unreached = true;
  return d;
}

constexpr StitchDef catching(StitchDef d) {
  d.catches = true;
  return d;
}

// After the core: the rest of the vocabulary knitters print. Ids are indices, so new
// stitches go at the end.
constexpr auto more = std::to_array<StitchDef>({
    with(plain("k tbl", 1, 1, F::knit, Lean::none, "p tbl"), true, false),
    with(plain("p tbl", 1, 1, F::purl, Lean::none, "k tbl"), true, false),
    with(plain("k below", 1, 1, F::knit, Lean::none, "p below"),
         false, true),
    with(plain("p below", 1, 1, F::purl, Lean::none, "k below"),
         false, true),
    plain("sssk", 3, 1, F::decrease, Lean::left, ""),
    with(plain("p2tog tbl", 2, 1, F::decrease, Lean::left, "ssk"),
         true, false),
    with(plain("k2tog tbl", 2, 1, F::decrease, Lean::left, "p2tog tbl"),
         true, false),
    with(plain("m1", 0, 1, F::yarn_over, Lean::none, "m1p"),
         true, false),
    with(plain("m1l", 0, 1, F::yarn_over, Lean::left, "m1p"), true, false),
    with(plain("m1r", 0, 1, F::yarn_over, Lean::right, "m1p"), true, false),
    with(plain("m1p", 0, 1, F::yarn_over, Lean::none, "m1"), true, false),
    plain("kfb", 1, 2, F::increase, Lean::none, "pfb"),
    plain("pfb", 1, 2, F::increase, Lean::none, "kfb"),
    plain("ctr dbl inc", 1, 3, F::increase, Lean::centre, ""),
    plain("k wrapping yarn twice", 1, 1, F::knit, Lean::none, "p wrapping yarn twice"),
    plain("p wrapping yarn twice", 1, 1, F::purl, Lean::none, "k wrapping yarn twice"),
    // Estonian lace's nupp, as Stitch Maps counts it: five loops out of one stitch, worked
    // loosely, gathered by a five-together on the next row. Printed (k1, yo, k1, yo, k1);
    // as an increase every loop, the yarn overs' too, is pulled through the old stitch.
    // Its loops bunch into the one stitch's width, a fifth each (the layout sets them at
    // alternating depths), so the nupp's row is no wider than the rows around it.
    clustered(plain("nupp", 1, 5, F::increase, Lean::centre, ""), 1.0),
    plain("k5tog", 5, 1, F::decrease, Lean::right, "p5tog"),
    plain("p5tog", 5, 1, F::decrease, Lean::right, "k5tog"),
    // Drop stitch patterns: a yarn over made rows below is let off the needle, and the
    // wale above it unravels into a ladder. The same worked from either side.
    plain("drop", 1, 0, F::drop, Lean::none, "drop"),
    // Quilting and butterfly stitches: a knit (purl) worked under the floats left by
    // stitches slipped rows below, catching them up.
    catching(plain("k under float", 1, 1, F::knit, Lean::none, "p under float")),
    catching(plain("p under float", 1, 1, F::purl, Lean::none, "k under float")),
    // Wrapped stitches: k2 (3, 4), then the yarn wound twice round them.
    wrapping(plain("wrap 2", 2, 2, F::knit, Lean::none, ""), 2),
    wrapping(plain("wrap 3", 3, 3, F::knit, Lean::none, ""), 2),
    wrapping(plain("wrap 4", 4, 4, F::knit, Lean::none, ""), 2),
    // Bound off within a row ("BO 3 sts, k to end"): knitted, and the stitch before it
    // passed over, so each lies over the next and none stays on the needle.
    plain("bo", 1, 0, F::bind_off, Lean::none, "bo"),
    // A short row's stitches beyond its turn, and a machine pass's needles it does not
    // reach: left as they were, with no yarn across them.
    unreached(plain("held", 1, 1, F::slip, Lean::none, "held")),
});

// Crosses in the Stitch Maps notation n/m XX and n/c/n XX, generated: n stitches cross
// over m (the first number is the one on top). RC/LC knit all, RPC/LPC purl the
// background, RT/LT and RPT/LPT work the travelling stitches through the back loop. A
// cross the core has already (C4F is 2/2 LC) is not made twice: the same facts are the
// same stitch.
struct CrossKind {
  std::string_view suffix;
  bool left, purl, twist;
};
constexpr CrossKind cross_kinds[] = {
    {"RC", false, false, false}, {"LC", true, false, false}, {"RPC", false, true, false}, {"LPC", true, true, false},
    {"RT", false, false, true},  {"LT", true, false, true},  {"RPT", false, true, true},  {"LPT", true, true, true},
};

bool same_cross(const StitchDef& a, const StitchDef& b) {
  return a.family == F::cable && b.family == F::cable && a.consumes == b.consumes && a.twisted == b.twisted &&
         a.cable.held == b.cable.held && a.cable.front == b.cable.front &&
         a.cable.purl_background == b.cable.purl_background && a.cable.middle == b.cable.middle &&
         a.cable.purled == b.cable.purled;
}

std::vector<StitchDef> build_table() {
  std::vector<StitchDef> all(core.begin(), core.end());
  all.insert(all.end(), more.begin(), more.end());
  static std::deque<std::string> text;  // the generated names' storage, for the program's life
  auto add = [&](int n, int c, int m, const CrossKind& k) {
    StitchDef d;
    d.consumes = d.produces = n + c + m;
    d.family = F::cable;
    d.twisted = k.twist;
    // A right cross holds the rightmost m behind and the n on top move right; a left
    // cross holds the rightmost n in front and they move left.
    d.cable = {c > 0 ? n : (k.left ? n : m), k.left, k.purl, c};
    if (std::any_of(all.begin(), all.end(), [&](const StitchDef& e) { return same_cross(e, d); })) return;
    d.name = text.emplace_back(cross_notation(d));
    all.push_back(d);
  };
  for (const CrossKind& k : cross_kinds) {
    for (int n = 1; n <= 4; ++n)
      for (int m = 1; m <= 4; ++m) add(n, 0, m, k);
    for (int n = 1; n <= 3; ++n)
      for (int c = 1; c <= 3; ++c) add(n, c, n, k);
  }
  // A cross worked from the wrong side, as its right-side words say ("sl 1 to cn, hold in
  // back, k2, p1 from cn"), seen from the face. The held stitches are then the leftmost,
  // and they end at the right; held in back (away from the knitter) they lie on top. In
  // a two-part cross the groups change places: the struct's held group (a right cross's
  // under stitches, a left cross's top ones) is the one that was not held; a three-part
  // cross is symmetric and keeps its facts. Every stitch shows the other face: a
  // purl-background cross keeps its knit stitches on top, so 2/1 RPC worked so is 1/2
  // RPC, and a cross of knit stitches shows purls crossing, a purled cross of its own
  // (C4B worked so is 2/2 RC purled), made here with its way back.
  const std::size_t crosses = all.size();
  for (std::size_t i = 0; i < crosses; ++i) {
    const StitchDef& d = all[i];
    if (d.family != F::cable || (d.cable.purl_background && d.cable.middle > 0)) continue;
    StitchDef face = d;
    if (d.cable.middle == 0) face.cable.held = d.consumes - d.cable.held;
    if (!d.cable.purl_background) face.cable.purled = true;
    auto same = std::find_if(all.begin(), all.end(), [&](const StitchDef& e) { return same_cross(e, face); });
    if (same == all.end()) {
      face.name = text.emplace_back(cross_notation(face));
      face.wrong_side_face = d.name;
      all.push_back(face);
      same = all.end() - 1;
    }
    all[i].wrong_side_face = same->name;
  }
  // Bobbles, every size knitters print: (k1, p1, k1) to seven loops in one stitch, worked
  // up to six rows high. Right side only: worked on a wrong-side row a bobble pops out of
  // the back, which knitc does not draw.
  for (int n = bobble_loops_min; n <= bobble_loops_max; ++n)
    for (int r = bobble_rows_min; r <= bobble_rows_max; ++r) {
      StitchDef d = plain("", 1, 1, F::knit, Lean::none, "");
      d.bobble_loops = n;
      d.bobble_rows = r;
      d.name = text.emplace_back(bobble_name(n, r));
      all.push_back(d);
    }
  return all;
}

const std::vector<StitchDef>& all_stitches() {
  static const std::vector<StitchDef> all = build_table();
  return all;
}

}  // namespace

int cable_source(const StitchDef& s, int j) {
  const int n = s.consumes, h = s.cable.held;
  if (s.cable.middle > 0) return j < h ? n - h + j : j >= n - h ? j - (n - h) : j;
  return j < h ? n - h + j : j - h;
}

std::span<const StitchDef> stitch_table() { return all_stitches(); }

const StitchDef& stitch(StitchId id) {
  assert(id < all_stitches().size());
  return all_stitches()[id];
}

StitchId stitch_id(std::string_view name) {
  for (std::size_t i = 0; i < all_stitches().size(); ++i) {
    if (all_stitches()[i].name == name) return static_cast<StitchId>(i);
  }
  assert(false && "no such stitch");
  return 0;
}

bool purled(const StitchDef& s) {
  switch (s.family) {
    case StitchFamily::purl: return true;
    case StitchFamily::cable: return s.cable.purled;
    case StitchFamily::decrease:
    case StitchFamily::increase:
    case StitchFamily::yarn_over: return s.name.front() == 'p' || s.name == "ssp" || s.name == "m1p";
    default: return false;
  }
}

std::optional<StitchId> wrong_side_face(StitchId id) {
  const std::string_view ws = stitch(id).wrong_side_face;
  if (ws.empty()) return std::nullopt;
  return stitch_id(ws);
}

CrossCounts cross_counts(const StitchDef& s) {
  assert(s.family == F::cable);
  const Cable& c = s.cable;
  // A left cross (and every n/c/n) holds the n on top; a right cross holds the m under.
  const int over = c.middle > 0 || c.front ? c.held : s.consumes - c.held;
  return {over, c.middle, s.consumes - over - c.middle};
}

std::string cross_notation(const StitchDef& s) {
  if (s.family != F::cable) return "";
  const Cable& c = s.cable;
  const CrossCounts n = cross_counts(s);
  std::string out = std::to_string(n.over) + "/" + (n.middle > 0 ? std::to_string(n.middle) + "/" : "") +
                    std::to_string(n.under) + " ";
  out += c.front ? "L" : "R";
  if (c.purl_background) out += "P";
  out += s.twisted ? "T" : "C";
  if (c.purled) out += " purled";
  return out;
}

std::string bobble_name(int loops, int rows) { return "bobble " + std::to_string(loops) + "x" + std::to_string(rows); }

}  // namespace knitc

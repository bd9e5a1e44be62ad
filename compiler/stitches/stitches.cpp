#include "stitches/stitches.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cctype>
#include <deque>
#include <map>
#include <string>
#include <vector>

namespace knitc {

namespace {

using F = StitchFamily;

constexpr StitchDef plain(std::string_view name, std::string_view aliases, std::string_view symbol,
                          std::string_view identifier, int consumes, int produces, bool counted, F family,
                          Lean lean, std::string_view ws, std::string_view summary) {
  StitchDef d;
  d.name = name;
  d.aliases = aliases;
  d.symbol = symbol;
  d.identifier = identifier;
  d.consumes = consumes;
  d.produces = produces;
  d.counted = counted;
  d.family = family;
  d.lean = lean;
  d.wrong_side_face = ws;
  d.summary = summary;
  return d;
}

// Cn F/B: n stitches, n/2 held; Tn F/B: the knit stitches that travel are held in front
// (F) or the purl ones in back (B), over a purl background.
constexpr StitchDef cable(std::string_view name, std::string_view aliases, int width, int held, bool front,
                          bool twist, std::string_view summary) {
  StitchDef d = plain(name, aliases, name, name, width, width, false, F::cable, Lean::none, "", summary);
  d.cable = {held, front, twist};
  return d;
}

constexpr auto core = std::to_array<StitchDef>({
    plain("k", "knit", "|", "k", 1, 1, true, F::knit, Lean::none, "p", "knit: a V on the face"),
    plain("p", "purl", ".", "p", 1, 1, true, F::purl, Lean::none, "k", "purl: a bump on the face"),
    plain("yo", "yfwd|yfd|yon|yrn|yf", "O", "yo", 0, 1, true, F::yarn_over, Lean::none, "yo",
          "yarn over: a new loop with no parent, an eyelet and one stitch more"),
    plain("k2tog", "k2 tog", "/", "k2tog", 2, 1, false, F::decrease, Lean::right, "p2tog",
          "knit two together: one stitch less, leaning right"),
    plain("ssk", "skp|skpo|sl1-k1-psso|sl1 k1 psso|sl 1 k1 psso", "\\", "ssk", 2, 1, false, F::decrease, Lean::left, "ssp",
          "slip, slip, knit: one stitch less, leaning left"),
    plain("p2tog", "", "p2tog", "p2tog", 2, 1, false, F::decrease, Lean::right, "k2tog",
          "purl two together: one stitch less; on a wrong-side row it shows as k2tog"),
    plain("ssp", "", "ssp", "ssp", 2, 1, false, F::decrease, Lean::left, "ssk",
          "slip, slip, purl: one stitch less; on a wrong-side row it shows as ssk"),
    plain("k3tog", "", "k3tog", "k3tog", 3, 1, false, F::decrease, Lean::right, "p3tog",
          "knit three together: two stitches less, leaning right"),
    plain("p3tog", "", "p3tog", "p3tog", 3, 1, false, F::decrease, Lean::right, "k3tog",
          "purl three together: two stitches less; on a wrong-side row it shows as k3tog"),
    plain("cdd", "s2kp|s2kpo|s2kp2|sl2-k1-p2sso|sl2 k1 p2sso|ctr dbl dec", "^", "cdd", 3, 1, false, F::decrease, Lean::centre, "",
          "central double decrease (slip 2 together, k1, pass the slipped stitches over): the centre stitch on top"),
    plain("sk2p", "sk2po|skpo2|sl1-k2tog-psso|sl1 k2tog psso|sl 1 k2tog psso", "sk2p", "sk2p", 3, 1, false, F::decrease, Lean::left, "",
          "slip 1, k2tog, pass the slipped stitch over: two stitches less, leaning left"),
    plain("sl wyib", "sl|slip|sl wyb|sl k-wise|sl kwise|sl knitwise|sl p-wise|sl pwise|sl purlwise|sl p-wise wyib|sl k-wise wyib", "V", "sl", 1, 1, true, F::slip, Lean::none, "sl wyif",
          "slip purlwise with the yarn in back: the old loop stretches up, the yarn floats behind it"),
    plain("sl wyif", "sl wyf|sl p-wise wyif|sl pwise wyif|sl purlwise wyif", "v", "sl_wyif", 1, 1, true, F::slip, Lean::none, "sl wyib",
          "slip purlwise with the yarn in front: the float lies across the face"),
    plain("tuck", "", "U", "tuck", 1, 1, true, F::tuck, Lean::none, "tuck",
          "tuck: the yarn is caught on the needle and the old loop held, to be knitted off with it next row"),
    plain("no stitch", "ns", "x", "no_stitch", 0, 0, true, F::no_stitch, Lean::none, "no stitch",
          "no stitch: a placeholder in charts where the stitch count changes"),
    cable("C2F", "1/1 LC|1/1 LSC|1/1 LSAC", 2, 1, true, false, "1 over 1 cross: the right stitch crosses in front to the left"),
    cable("C2B", "1/1 RC|1/1 RSC|1/1 RSAC", 2, 1, false, false, "1 over 1 cross: the right stitch crosses behind to the left"),
    cable("C4F", "2/2 LC", 4, 2, true, false, "2 over 2 cable: the front pair moves left"),
    cable("C4B", "2/2 RC", 4, 2, false, false, "2 over 2 cable: the front pair moves right"),
    cable("C6F", "3/3 LC", 6, 3, true, false, "3 over 3 cable: the front three move left"),
    cable("C6B", "3/3 RC", 6, 3, false, false, "3 over 3 cable: the front three move right"),
    cable("C8F", "4/4 LC", 8, 4, true, false, "4 over 4 cable: the front four move left"),
    cable("C8B", "4/4 RC", 8, 4, false, false, "4 over 4 cable: the front four move right"),
    cable("T2F", "1/1 LPC", 2, 1, true, true, "twist: a knit stitch crosses left in front of a purl"),
    cable("T2B", "1/1 RPC", 2, 1, false, true, "twist: a knit stitch crosses right in front of a purl"),
    cable("T3F", "2/1 LPC", 3, 2, true, true, "twist: two knit stitches cross left in front of a purl"),
    cable("T3B", "2/1 RPC", 3, 1, false, true, "twist: two knit stitches cross right in front of a purl"),
    cable("T4F", "2/2 LPC", 4, 2, true, true, "twist: two knit stitches cross left in front of two purls"),
    cable("T4B", "2/2 RPC", 4, 2, false, true, "twist: two knit stitches cross right in front of two purls"),
});


constexpr StitchDef with(StitchDef d, bool twisted, bool below) {
  d.twisted = twisted;
  d.below = below;
  return d;
}

// After the core: the rest of the vocabulary knitters print. Ids are indices, so new
// stitches go at the end.
constexpr auto more = std::to_array<StitchDef>({
    with(plain("k tbl", "ktbl|k through back loop|k tw|k twisted", "k_tbl", "k_tbl", 1, 1, true, F::knit, Lean::none, "p tbl",
               "knit through the back loop: a twisted knit, its legs crossed at the foot"), true, false),
    with(plain("p tbl", "ptbl|p through back loop|p tw|p twisted", "p_tbl", "p_tbl", 1, 1, true, F::purl, Lean::none, "k tbl",
               "purl through the back loop: a twisted purl"), true, false),
    with(plain("k below", "k b|kb1|k-b1|k in row below|k in st below|k in stitch below", "k_below", "k_below", 1, 1, true, F::knit, Lean::none,
               "p below", "knit into the stitch below (brioche): the live loop drops and lies on the new one like a tuck"),
         false, true),
    with(plain("p below", "p b|pb1|p-b1|p in row below|p in st below|p in stitch below", "p_below", "p_below", 1, 1, true, F::purl, Lean::none,
               "k below", "purl into the stitch below (brioche): the live loop drops and lies on the new one like a tuck"),
         false, true),
    plain("sssk", "", "sssk", "sssk", 3, 1, false, F::decrease, Lean::left, "",
          "slip, slip, slip, knit the three together: two stitches less, leaning left"),
    with(plain("p2tog tbl", "p2tog twisted|p2togtbl|p2tog-tbl", "p2tog_tbl", "p2tog_tbl", 2, 1, false, F::decrease,
               Lean::left, "ssk", "purl two together through the back loops: one stitch less; on a wrong-side row it shows as ssk"),
         true, false),
    with(plain("k2tog tbl", "k2togtbl|k2tog-tbl", "k2tog_tbl", "k2tog_tbl", 2, 1, false, F::decrease, Lean::left,
               "p2tog tbl", "knit two together through the back loops: one stitch less, leaning left, twisted"),
         true, false),
    with(plain("m1", "m", "m1", "m1", 0, 1, false, F::yarn_over, Lean::none, "m1p",
               "make one: the bar between two stitches lifted and knitted twisted, one stitch more and no hole"),
         true, false),
    with(plain("m1l", "m1 l|m1lf|m1 left", "m1l", "m1l", 0, 1, false, F::yarn_over, Lean::left, "m1p",
               "make one left: the bar lifted from the front, knitted through the back, leaning left"), true, false),
    with(plain("m1r", "m1 r|m1rb|m1 right", "m1r", "m1r", 0, 1, false, F::yarn_over, Lean::right, "m1p",
               "make one right: the bar lifted from the back, knitted through the front, leaning right"), true, false),
    with(plain("m1p", "m1 p|m1 purlwise|m1pw", "m1p", "m1p", 0, 1, false, F::yarn_over, Lean::none, "m1",
               "make one purlwise: the bar lifted and purled twisted, one stitch more"), true, false),
    plain("kfb", "kf&b|k1fb|k1f&b|inc|k into front and back", "kfb", "kfb", 1, 2, false, F::increase, Lean::none, "pfb",
          "knit into the front and back of one stitch: one stitch more, a bar at the second"),
    plain("pfb", "pf&b|p1fb|p1f&b", "pfb", "pfb", 1, 2, false, F::increase, Lean::none, "kfb",
          "purl into the front and back of one stitch: one stitch more"),
    plain("ctr dbl inc", "cdi|central double increase", "cdi", "cdi", 1, 3, false, F::increase, Lean::centre, "",
          "central double increase: three stitches worked out of one, the centre one on top"),
    plain("k wrapping yarn twice", "k wyt|k elongated|k double wrap", "k_wyt", "k_wyt", 1, 1, true, F::knit, Lean::none,
          "p wrapping yarn twice", "knit wrapping the yarn twice; the extra wrap is dropped on the next row: an elongated stitch"),
    plain("p wrapping yarn twice", "p wyt|p elongated|p double wrap", "p_wyt", "p_wyt", 1, 1, true, F::purl, Lean::none,
          "k wrapping yarn twice", "purl wrapping the yarn twice; the extra wrap is dropped on the next row: an elongated stitch"),
});

// Crosses in the Stitch Maps notation n/m XX and n/c/n XX, generated: n stitches cross
// over m (the first number is the one on top). RC/LC knit all, RPC/LPC purl the
// background, RT/LT and RPT/LPT work the travelling stitches through the back loop.
// Those the core names already (C4F is 2/2 LC) are its aliases instead.
struct CrossKind {
  std::string_view suffix;
  bool left, purl, twist;
  std::string_view verb;
};
constexpr CrossKind cross_kinds[] = {
    {"RC", false, false, false, "right cross"},      {"LC", true, false, false, "left cross"},
    {"RPC", false, true, false, "right purl cross"}, {"LPC", true, true, false, "left purl cross"},
    {"RT", false, false, true, "right twist"},       {"LT", true, false, true, "left twist"},
    {"RPT", false, true, true, "right purl twist"},  {"LPT", true, true, true, "left purl twist"},
};

// The stitch's name, then each of its aliases.
template <typename Visit>
void for_each_spelling(const StitchDef& d, Visit visit) {
  visit(d.name);
  std::string_view rest = d.aliases;
  while (!rest.empty()) {
    const auto bar = rest.find('|');
    visit(rest.substr(0, bar));
    rest = bar == std::string_view::npos ? std::string_view{} : rest.substr(bar + 1);
  }
}

std::vector<StitchDef> build_table() {
  std::vector<StitchDef> all(core.begin(), core.end());
  all.insert(all.end(), more.begin(), more.end());
  static std::deque<std::string> text;  // the generated names' storage, for the program's life
  auto keep = [](std::string s) -> std::string_view { return text.emplace_back(std::move(s)); };
  auto known = [&](const std::string& name) {
    const std::string key = lower(name);
    return std::any_of(all.begin(), all.end(), [&](const StitchDef& d) {
      bool found = false;
      for_each_spelling(d, [&](std::string_view w) { found = found || lower(w) == key; });
      return found;
    });
  };
  auto add = [&](int n, int c, int m, const CrossKind& k) {
    const bool three = c > 0;
    const std::string name = std::to_string(n) + "/" + (three ? std::to_string(c) + "/" : "") + std::to_string(m) + " " +
                             std::string(k.suffix);
    if (known(name)) return;
    StitchDef d;
    d.name = keep(name);
    std::string symbol = name;
    symbol.erase(std::remove(symbol.begin(), symbol.end(), ' '), symbol.end());
    d.symbol = keep(symbol);
    d.consumes = d.produces = n + c + m;
    d.family = F::cable;
    d.twisted = k.twist;
    // A right cross holds the rightmost m behind and the n on top move right; a left
    // cross holds the rightmost n in front and they move left.
    d.cable = {three ? n : (k.left ? n : m), k.left, k.purl, c};
    std::string what = std::string(k.verb) + ": " + std::to_string(n) + (k.twist ? " twisted" : "") + " over " +
                       (three ? std::to_string(c) + " and " + std::to_string(m) : std::to_string(m)) + ", the top " +
                       (k.left ? "moving left" : "moving right");
    if (k.purl) what += three ? ", the middle purled" : ", the one below purled";
    d.summary = keep(what);
    all.push_back(d);
  };
  for (const CrossKind& k : cross_kinds) {
    for (int n = 1; n <= 4; ++n)
      for (int m = 1; m <= 4; ++m) add(n, 0, m, k);
    for (int n = 1; n <= 3; ++n)
      for (int c = 1; c <= 3; ++c) add(n, c, n, k);
  }
  return all;
}

const std::vector<StitchDef>& all_stitches() {
  static const std::vector<StitchDef> all = build_table();
  return all;
}

// Every name and alias with its stitch, lower-cased.
const std::vector<std::pair<std::string, StitchId>>& spellings() {
  static const auto all = [] {
    std::vector<std::pair<std::string, StitchId>> v;
    for (std::size_t i = 0; i < all_stitches().size(); ++i) {
      const auto id = static_cast<StitchId>(i);
      for_each_spelling(all_stitches()[i], [&](std::string_view w) { v.emplace_back(lower(w), id); });
    }
    return v;
  }();
  return all;
}

}  // namespace

std::span<const StitchDef> stitch_table() { return all_stitches(); }

const StitchDef& stitch(StitchId id) {
  assert(id < all_stitches().size());
  return all_stitches()[id];
}

std::optional<StitchId> find_stitch(std::string_view word) {
  // Several hundred spellings, looked up for every word of every row: a map, the first
  // stitch in table order keeping a spelling two share.
  static const auto by_spelling = [] {
    std::map<std::string, StitchId, std::less<>> m;
    for (const auto& [spelling, id] : spellings()) m.emplace(spelling, id);
    return m;
  }();
  const auto it = by_spelling.find(lower(word));
  if (it == by_spelling.end()) return std::nullopt;
  return it->second;
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

int edit_distance(std::string_view a, std::string_view b) {
  std::vector<int> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = static_cast<int>(j);
  for (std::size_t i = 1; i <= a.size(); ++i) {
    int diagonal = row[0];
    row[0] = static_cast<int>(i);
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const int above = row[j];
      const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) == std::tolower(static_cast<unsigned char>(b[j - 1]));
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (same ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::string nearest_stitch_name(std::string_view word) {
  // No spelling is near a word many times its length; its start is what the hint can use
  // (and a megabyte of text must not cost a megabyte squared).
  word = word.substr(0, 48);
  std::string best;
  int best_distance = 1 << 30;
  for (const auto& [spelling, id] : spellings()) {
    const auto gap = static_cast<int>(word.size() > spelling.size() ? word.size() - spelling.size() : spelling.size() - word.size());
    if (gap >= best_distance) continue;  // the distance is at least the difference in length
    const int d = edit_distance(word, spelling);
    if (d < best_distance) {  // first in all_stitches() order wins ties: deterministic
      best_distance = d;
      best = spelling == lower(all_stitches()[id].name) ? std::string(all_stitches()[id].name) : spelling;
    }
  }
  return best;
}

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return std::tolower(c); });
  return out;
}

}  // namespace knitc

#include "stitches/stitches.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cctype>
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

constexpr auto table = std::to_array<StitchDef>({
    plain("k", "knit", "|", "k", 1, 1, true, F::knit, Lean::none, "p", "knit: a V on the face"),
    plain("p", "purl", ".", "p", 1, 1, true, F::purl, Lean::none, "k", "purl: a bump on the face"),
    plain("yo", "yfwd|yon|yrn", "O", "yo", 0, 1, true, F::yarn_over, Lean::none, "yo",
          "yarn over: a new loop with no parent, an eyelet and one stitch more"),
    plain("k2tog", "", "/", "k2tog", 2, 1, false, F::decrease, Lean::right, "p2tog",
          "knit two together: one stitch less, leaning right"),
    plain("ssk", "", "\\", "ssk", 2, 1, false, F::decrease, Lean::left, "ssp",
          "slip, slip, knit: one stitch less, leaning left"),
    plain("p2tog", "", "p2tog", "p2tog", 2, 1, false, F::decrease, Lean::right, "k2tog",
          "purl two together: one stitch less; on a wrong-side row it shows as k2tog"),
    plain("ssp", "", "ssp", "ssp", 2, 1, false, F::decrease, Lean::left, "ssk",
          "slip, slip, purl: one stitch less; on a wrong-side row it shows as ssk"),
    plain("k3tog", "", "k3tog", "k3tog", 3, 1, false, F::decrease, Lean::right, "p3tog",
          "knit three together: two stitches less, leaning right"),
    plain("p3tog", "", "p3tog", "p3tog", 3, 1, false, F::decrease, Lean::right, "k3tog",
          "purl three together: two stitches less; on a wrong-side row it shows as k3tog"),
    plain("cdd", "s2kp|s2kpo", "^", "cdd", 3, 1, false, F::decrease, Lean::centre, "",
          "central double decrease (slip 2 together, k1, pass the slipped stitches over): the centre stitch on top"),
    plain("sk2p", "sk2po|sl1-k2tog-psso", "sk2p", "sk2p", 3, 1, false, F::decrease, Lean::left, "",
          "slip 1, k2tog, pass the slipped stitch over: two stitches less, leaning left"),
    plain("sl wyib", "sl|slip", "V", "sl", 1, 1, true, F::slip, Lean::none, "sl wyif",
          "slip purlwise with the yarn in back: the old loop stretches up, the yarn floats behind it"),
    plain("sl wyif", "", "v", "sl_wyif", 1, 1, true, F::slip, Lean::none, "sl wyib",
          "slip purlwise with the yarn in front: the float lies across the face"),
    plain("tuck", "", "U", "tuck", 1, 1, true, F::tuck, Lean::none, "tuck",
          "tuck: the yarn is caught on the needle and the old loop held, to be knitted off with it next row"),
    plain("no stitch", "ns", "x", "no_stitch", 0, 0, true, F::no_stitch, Lean::none, "no stitch",
          "no stitch: a placeholder in charts where the stitch count changes"),
    cable("C2F", "", 2, 1, true, false, "1 over 1 cross: the right stitch crosses in front to the left"),
    cable("C2B", "", 2, 1, false, false, "1 over 1 cross: the right stitch crosses behind to the left"),
    cable("C4F", "", 4, 2, true, false, "2 over 2 cable: the front pair moves left"),
    cable("C4B", "", 4, 2, false, false, "2 over 2 cable: the front pair moves right"),
    cable("C6F", "", 6, 3, true, false, "3 over 3 cable: the front three move left"),
    cable("C6B", "", 6, 3, false, false, "3 over 3 cable: the front three move right"),
    cable("C8F", "", 8, 4, true, false, "4 over 4 cable: the front four move left"),
    cable("C8B", "", 8, 4, false, false, "4 over 4 cable: the front four move right"),
    cable("T2F", "", 2, 1, true, true, "twist: a knit stitch crosses left in front of a purl"),
    cable("T2B", "", 2, 1, false, true, "twist: a knit stitch crosses right in front of a purl"),
    cable("T3F", "", 3, 2, true, true, "twist: two knit stitches cross left in front of a purl"),
    cable("T3B", "", 3, 1, false, true, "twist: two knit stitches cross right in front of a purl"),
    cable("T4F", "", 4, 2, true, true, "twist: two knit stitches cross left in front of two purls"),
    cable("T4B", "", 4, 2, false, true, "twist: two knit stitches cross right in front of two purls"),
});

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return std::tolower(c); });
  return out;
}

// Every name and alias with its stitch, lower-cased.
const std::vector<std::pair<std::string, StitchId>>& spellings() {
  static const auto all = [] {
    std::vector<std::pair<std::string, StitchId>> v;
    for (std::size_t i = 0; i < table.size(); ++i) {
      const auto id = static_cast<StitchId>(i);
      v.emplace_back(lower(table[i].name), id);
      std::string_view rest = table[i].aliases;
      while (!rest.empty()) {
        const auto bar = rest.find('|');
        v.emplace_back(lower(rest.substr(0, bar)), id);
        rest = bar == std::string_view::npos ? std::string_view{} : rest.substr(bar + 1);
      }
    }
    return v;
  }();
  return all;
}

}  // namespace

std::span<const StitchDef> stitch_table() { return table; }

const StitchDef& stitch(StitchId id) {
  assert(id < table.size());
  return table[id];
}

std::optional<StitchId> find_stitch(std::string_view word) {
  const std::string key = lower(word);
  for (const auto& [spelling, id] : spellings()) {
    if (spelling == key) return id;
  }
  return std::nullopt;
}

StitchId stitch_id(std::string_view name) {
  for (std::size_t i = 0; i < table.size(); ++i) {
    if (table[i].name == name) return static_cast<StitchId>(i);
  }
  assert(false && "no such stitch");
  return 0;
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
  std::string best;
  int best_distance = 1 << 30;
  for (const auto& [spelling, id] : spellings()) {
    const int d = edit_distance(word, spelling);
    if (d < best_distance) {  // first in table order wins ties: deterministic
      best_distance = d;
      best = spelling == lower(table[id].name) ? std::string(table[id].name) : spelling;
    }
  }
  return best;
}

}  // namespace knitc

#include "language/words.hpp"

#include <algorithm>
#include <cassert>
#include <cctype>
#include <deque>
#include <map>
#include <vector>

namespace knitc::language {

namespace {

struct Entry {
  std::string_view name;  // the stitch table's canonical name
  StitchWords words;
};

// Every stitch the table declares by hand, in its order: {name, {aliases, symbol, Lua
// name, counted, summary}}. The generated crosses' words follow from their facts
// (cross_words below).
constexpr Entry entries[] = {
    {"k", {"knit", "|", "k", true,
      "knit: a V on the face"}},
    {"p", {"purl", ".", "p", true,
      "purl: a bump on the face"}},
    {"yo", {"yfwd|yfd|yon|yrn|yf", "O", "yo", true,
      "yarn over: a new loop with no parent, an eyelet and one stitch more"}},
    {"k2tog", {"k2 tog", "/", "k2tog", false,
      "knit two together: one stitch less, leaning right"}},
    {"ssk", {"skp|skpo|sl1-k1-psso|sl1 k1 psso|sl 1 k1 psso", "\\", "ssk", false,
      "slip, slip, knit: one stitch less, leaning left"}},
    {"p2tog", {"", "p2tog", "p2tog", false,
      "purl two together: one stitch less; on a wrong-side row it shows as k2tog"}},
    {"ssp", {"", "ssp", "ssp", false,
      "slip, slip, purl: one stitch less; on a wrong-side row it shows as ssk"}},
    {"k3tog", {"", "k3tog", "k3tog", false,
      "knit three together: two stitches less, leaning right"}},
    {"p3tog", {"", "p3tog", "p3tog", false,
      "purl three together: two stitches less; on a wrong-side row it shows as k3tog"}},
    {"cdd", {"s2kp|s2kpo|s2kp2|sl2-k1-p2sso|sl2 k1 p2sso|ctr dbl dec", "^", "cdd", false,
      "central double decrease (slip 2 together, k1, pass the slipped stitches over): the centre stitch on top"}},
    {"sk2p", {"sk2po|skpo2|sl1-k2tog-psso|sl1 k2tog psso|sl 1 k2tog psso", "sk2p", "sk2p", false,
      "slip 1, k2tog, pass the slipped stitch over: two stitches less, leaning left"}},
    {"sl wyib", {"sl|slip|s|sl wyb|sl k-wise|sl kwise|sl knitwise|sl p-wise|sl pwise|sl purlwise|sl p-wise wyib|sl k-wise wyib|sl k|sl p|sl pw|sl kw|sl wyib pwise|sl wyib kwise", "V", "sl", true,
      "slip purlwise with the yarn in back: the old loop stretches up, the yarn floats behind it"}},
    {"sl wyif", {"sl wyf|sl p-wise wyif|sl pwise wyif|sl purlwise wyif|sl p wyif|sl pw wyif|sl wyif pwise|sl wyif pw|sl wyif p", "v", "sl_wyif", true,
      "slip purlwise with the yarn in front: the float lies across the face"}},
    {"tuck", {"", "U", "tuck", true,
      "tuck: the yarn is caught on the needle and the old loop held, to be knitted off with it next row"}},
    {"no stitch", {"ns", "x", "no_stitch", true,
      "no stitch: a placeholder in charts where the stitch count changes"}},
    {"C2F", {"1/1 LC|1/1 LSC|1/1 LSAC", "C2F", "C2F", false,
      "1 over 1 cross: the right stitch crosses in front to the left"}},
    {"C2B", {"1/1 RC|1/1 RSC|1/1 RSAC", "C2B", "C2B", false,
      "1 over 1 cross: the right stitch crosses behind to the left"}},
    {"C4F", {"2/2 LC|C4L", "C4F", "C4F", false,
      "2 over 2 cable: the front pair moves left"}},
    {"C4B", {"2/2 RC|C4R", "C4B", "C4B", false,
      "2 over 2 cable: the front pair moves right"}},
    {"C6F", {"3/3 LC|C6L", "C6F", "C6F", false,
      "3 over 3 cable: the front three move left"}},
    {"C6B", {"3/3 RC|C6R", "C6B", "C6B", false,
      "3 over 3 cable: the front three move right"}},
    {"C8F", {"4/4 LC|C8L", "C8F", "C8F", false,
      "4 over 4 cable: the front four move left"}},
    {"C8B", {"4/4 RC|C8R", "C8B", "C8B", false,
      "4 over 4 cable: the front four move right"}},
    {"T2F", {"1/1 LPC", "T2F", "T2F", false,
      "twist: a knit stitch crosses left in front of a purl"}},
    {"T2B", {"1/1 RPC", "T2B", "T2B", false,
      "twist: a knit stitch crosses right in front of a purl"}},
    {"T3F", {"2/1 LPC|T3L", "T3F", "T3F", false,
      "twist: two knit stitches cross left in front of a purl"}},
    {"T3B", {"2/1 RPC|T3R", "T3B", "T3B", false,
      "twist: two knit stitches cross right in front of a purl"}},
    {"T4F", {"2/2 LPC|T4L", "T4F", "T4F", false,
      "twist: two knit stitches cross left in front of two purls"}},
    {"T4B", {"2/2 RPC|T4R", "T4B", "T4B", false,
      "twist: two knit stitches cross right in front of two purls"}},
    {"k tbl", {"ktbl|k through back loop|k tw|k twisted", "k_tbl", "k_tbl", true,
      "knit through the back loop: a twisted knit, its legs crossed at the foot"}},
    {"p tbl", {"ptbl|p through back loop|p tw|p twisted", "p_tbl", "p_tbl", true,
      "purl through the back loop: a twisted purl"}},
    {"k below", {"kb1|k-b1|k1 below|k in row below|k in st below|k in stitch below", "k_below", "k_below", true,
      "knit into the stitch below (brioche): the live loop drops and lies on the new one like a tuck"}},
    {"p below", {"pb1|p-b1|p1 below|p in row below|p in st below|p in stitch below", "p_below", "p_below", true,
      "purl into the stitch below (brioche): the live loop drops and lies on the new one like a tuck"}},
    {"sssk", {"", "sssk", "sssk", false,
      "slip, slip, slip, knit the three together: two stitches less, leaning left"}},
    {"p2tog tbl", {"p2tog twisted|p2togtbl|p2tog-tbl", "p2tog_tbl", "p2tog_tbl", false,
      "purl two together through the back loops: one stitch less; on a wrong-side row it shows as ssk"}},
    {"k2tog tbl", {"k2togtbl|k2tog-tbl", "k2tog_tbl", "k2tog_tbl", false,
      "knit two together through the back loops: one stitch less, leaning left, twisted"}},
    {"m1", {"m", "m1", "m1", false,
      "make one: the bar between two stitches lifted and knitted twisted, one stitch more and no hole"}},
    {"m1l", {"m1 l|m1lf|m1 left", "m1l", "m1l", false,
      "make one left: the bar lifted from the front, knitted through the back, leaning left"}},
    {"m1r", {"m1 r|m1rb|m1 right", "m1r", "m1r", false,
      "make one right: the bar lifted from the back, knitted through the front, leaning right"}},
    {"m1p", {"m1 p|m1 purlwise|m1pw", "m1p", "m1p", false,
      "make one purlwise: the bar lifted and purled twisted, one stitch more"}},
    {"kfb", {"kf&b|k1fb|k1f&b|k into front and back", "kfb", "kfb", false,
      "knit into the front and back of one stitch: one stitch more, a bar at the second"}},
    {"pfb", {"pf&b|p1fb|p1f&b", "pfb", "pfb", false,
      "purl into the front and back of one stitch: one stitch more"}},
    {"ctr dbl inc", {"cdi|central double increase", "cdi", "cdi", false,
      "central double increase: three stitches worked out of one, the centre one on top"}},
    {"k wrapping yarn twice", {"k wyt|k elongated|k double wrap", "k_wyt", "k_wyt", true,
      "knit wrapping the yarn twice; the extra wrap is dropped on the next row: an elongated stitch"}},
    {"p wrapping yarn twice", {"p wyt|p elongated|p double wrap", "p_wyt", "p_wyt", true,
      "purl wrapping the yarn twice; the extra wrap is dropped on the next row: an elongated stitch"}},
    {"nupp", {"", "nupp", "nupp", false,
      "nupp: five loops worked loosely into one stitch (printed (k1, yo, k1, yo, k1); knitc pulls all five through it), five stitches out of one; gather them with p5tog or k5tog on the next row"}},
    {"k5tog", {"k5 tog", "k5tog", "k5tog", false,
      "knit five together: four stitches less (a nupp gathered from the right side)"}},
    {"p5tog", {"p5 tog", "p5tog", "p5tog", false,
      "purl five together: four stitches less (a nupp gathered on the wrong side); on a wrong-side row it shows as k5tog"}},
    {"drop", {"drop st|drop stitch|drop next st|drop the next st|drop the next stitch|drop st and unravel|drop next st and unravel to yo|drop the next stitch and unravel it to the yo", "D", "drop", true,
      "drop: the stitch is let off the needle and its wale unravels down to the yarn over it grew from, a ladder of straight rungs; one stitch less"}},
    {"k under float", {"k1 under float|k under floats|k1 under floats|k under loose strand|k1 under loose strand|k under loose strands|k1 under loose strands|k under the loose strand|k1 under the loose strand|k under the loose strands|k1 under the loose strands|k under strand|k1 under strand|k next st under the loose strand|insert the needle under the loose strand in front and k the next st|insert the needle under the loose strand and k the next st|lift the loose strand and k it together with the next st|lift the loose strands and k them together with the next st",
      "k_under", "k_under", false,
      "knit under the loose strands (quilting, butterfly): the new loop catches every float lying over its stitch on the face from the rows below and lifts it"}},
    {"p under float", {"p1 under float|p under floats|p1 under floats|p under loose strand|p1 under loose strand|p under loose strands|p1 under loose strands|p under the loose strand|p1 under the loose strand|p under strand|p1 under strand",
      "p_under", "p_under", false,
      "purl under the loose strands: the new loop catches every float lying over its stitch on the back; on a wrong-side row it shows as k under float"}},
    {"wrap 2", {"w2|wrap2|wrap 2 sts|wrap next 2 sts", "wrap2", "wrap2", false,
      "wrap 2: knit 2, slip them back, wind the yarn twice round them, slip them again: the two drawn together"}},
    {"wrap 3", {"w3|wrap3|wrap 3 sts|wrap next 3 sts", "wrap3", "wrap3", false,
      "wrap 3: knit 3, slip them back, wind the yarn twice round them, slip them again: the three drawn together"}},
    {"wrap 4", {"w4|wrap4|wrap 4 sts|wrap next 4 sts", "wrap4", "wrap4", false,
      "wrap 4: knit 4, slip them back, wind the yarn twice round them, slip them again: the four drawn together"}},
    {"bo", {"bind off|cast off|b/o|bo st|bo sts|bind off st|bind off sts|cast off st|cast off sts", "BO", "bo", true,
      "bind off within a row: each bo knitted and passed over the next, one stitch less; written with a count (BO 3 sts) it also knits the stitch the last is passed over, left on the needle, as printed counts mean it"}},
    {"held", {"hold|on hold|unworked", "H", "held", true,
      "held: a stitch the row does not reach (a short row turns before it, a machine's pass stops short of it): left on the needle as it was, with no yarn across it"}},
};

// A generated cross: its notation is its name; its symbol the name without the space.
StitchWords cross_words(const StitchDef& d) {
  static std::deque<std::string> text;  // the generated words' storage, for the program's life
  std::string symbol(d.name);
  symbol.erase(std::remove(symbol.begin(), symbol.end(), ' '), symbol.end());
  const Cable& c = d.cable;
  const CrossCounts n = cross_counts(d);
  const bool three = n.middle > 0;
  std::string what = std::string(c.front ? "left" : "right") + (c.purl_background ? " purl" : "") +
                     (d.twisted ? " twist" : " cross") + ": " + std::to_string(n.over) + (d.twisted ? " twisted" : "") +
                     " over " + (three ? std::to_string(n.middle) + " and " + std::to_string(n.under) : std::to_string(n.under)) +
                     ", the top " + (c.front ? "moving left" : "moving right");
  if (c.purl_background) what += three ? ", the middle purled" : ", the one below purled";
  if (c.purled) what += ", every stitch purled (a knit cross worked on a wrong-side row, seen from the face)";
  StitchWords w;
  w.symbol = text.emplace_back(std::move(symbol));
  w.summary = text.emplace_back(std::move(what));
  return w;
}

// A generated bobble: "bobble 5x4", its symbol MB5x4; the usual one (five loops, four rows)
// is the printed MB.
StitchWords bobble_words(const StitchDef& d) {
  static std::deque<std::string> text;
  const std::string size(d.name.substr(d.name.find(' ') + 1));  // "5x4", as bobble_name() writes it
  const bool usual = d.bobble_loops == 5 && d.bobble_rows == 4;
  StitchWords w;
  w.symbol = text.emplace_back(usual ? "MB" : "MB" + size);
  if (usual) {
    w.aliases = "mb|make bobble|make a bobble|bobble|lg bobble|large bobble";
    w.identifier = "mb";
  }
  const int n = d.bobble_loops, r = d.bobble_rows;
  std::string what = "bobble: " + std::to_string(n) + " loops worked into one stitch (k1, p1, k1 ...)";
  if (r > 1) what += ", then " + std::to_string(r - 1) + (r == 2 ? " row" : " rows") + " worked back and forth over them";
  what += ", gathered into one again: one stitch out of one";
  if (usual) what += " (the printed MB: (k1, p1, k1, p1, k1) in the next st, turn, p5, turn, k5, turn, p5, turn, k5tog)";
  w.summary = text.emplace_back(std::move(what));
  return w;
}

const std::vector<StitchWords>& all_words() {
  static const std::vector<StitchWords> all = [] {
    const auto table = stitch_table();
    std::vector<StitchWords> v;
    v.reserve(table.size());
    std::size_t next = 0;  // entries are in table order
    for (const StitchDef& d : table) {
      if (next < std::size(entries) && entries[next].name == d.name) {
        v.push_back(entries[next++].words);
      } else if (d.bobble_loops > 0) {
        v.push_back(bobble_words(d));
      } else {
        assert(!cross_notation(d).empty() && cross_notation(d) == d.name && "a stitch without words");
        v.push_back(cross_words(d));
      }
    }
    assert(next == std::size(entries) && "words for a stitch the table does not have, or out of its order");
    return v;
  }();
  return all;
}

// Every name and alias with its stitch, lower-cased.
const std::vector<std::pair<std::string, StitchId>>& spellings() {
  static const auto all = [] {
    std::vector<std::pair<std::string, StitchId>> v;
    for (std::size_t i = 0; i < stitch_table().size(); ++i) {
      const auto id = static_cast<StitchId>(i);
      for_each_spelling(id, [&](std::string_view w) { v.emplace_back(lower(w), id); });
    }
    return v;
  }();
  return all;
}

}  // namespace

const StitchWords& words(StitchId id) {
  assert(id < all_words().size());
  return all_words()[id];
}

std::string_view long_name(StitchId id) {
  const std::string_view summary = words(id).summary;
  const auto colon = summary.find(':');
  return colon == std::string_view::npos || colon == 0 ? stitch(id).name : summary.substr(0, colon);
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
    if (d < best_distance) {  // first in table order wins ties: deterministic
      best_distance = d;
      best = spelling == lower(stitch(id).name) ? std::string(stitch(id).name) : spelling;
    }
  }
  return best;
}

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return std::tolower(c); });
  return out;
}

}  // namespace knitc::language

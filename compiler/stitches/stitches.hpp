// What every stitch is, declared once as data: its canonical name, the stitches it works
// and makes, and the facts its geometry and the wrong-side bookkeeping need. How patterns
// write a stitch (spellings, chart symbols, Lua names) is the language's, next to its
// parsers: runtime/language/words.hpp.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace knitc {

// An index into stitch_table().
using StitchId = std::uint16_t;

enum class StitchFamily : std::uint8_t {
  knit,       // a new loop pulled through from the back: a V on the face
  purl,       // pulled through from the front: a bump on the face
  yarn_over,  // a new loop with no parent: an eyelet
  decrease,   // several old loops gathered into one new loop
  slip,       // the old loop moves across unworked; the yarn floats past it
  tuck,       // the yarn is caught on the needle; the old loop stays and is knitted later
  cable,      // stitches crossed over their neighbours
  increase,   // one old loop worked several times (kfb, ctr dbl inc): every new loop through it
  no_stitch,  // a chart's grey square: a placeholder, no loop
  drop,       // the old loop let off the needle: its wale unravels down to a yarn over
  bind_off,   // knitted and passed over the next: a loop that stays off the needle
};

enum class Lean : std::uint8_t { none, left, right, centre };

struct Cable {
  int held = 0;        // stitches slipped to the cable needle: the rightmost `held` of the block
  bool front = false;  // cable needle held in front (the held stitches cross over)
  // Twists (T): the travelling stitches are knit, the rest purled. In F twists the held
  // stitches travel; in B twists the held stitches are the purls.
  bool purl_background = false;
  // Three-part crosses (n/c/n): the `middle` stitches stay in the centre, the outer
  // `held` on each side change places. 0 for two-part crosses.
  int middle = 0;
  // A cross of knit stitches worked on a wrong-side row, seen from the face: every stitch
  // of it shows as a purl.
  bool purled = false;
};

struct StitchDef {
  std::string_view name;         // canonical name: the stitch's identity in files and messages
  int consumes = 1;              // live stitches it works
  int produces = 1;              // loops it leaves on the needle
  StitchFamily family = StitchFamily::knit;
  Lean lean = Lean::none;
  Cable cable;                   // for the cable family
  bool twisted = false;          // worked through the back loop: the loop crossed on itself
  bool below = false;            // worked into the stitch below: the live loop drops onto it
  // Worked under the loose strands (quilting, butterfly): the new loop also takes every
  // float not yet caught that lies over its stitch on the side it is pulled out to (the
  // face for a knit, the back for a purl), lifting them to it.
  bool catches = false;
  // A cluster (the nupp): its new loops share this many loop widths of needle positions
  // between them, bunched, where each loop would otherwise take one. 0: one each.
  double cluster_width = 0.0;
  // A wrap (wrap 3): its stitches are each knitted, then the yarn is wound this many times
  // round them all. 0: no winding.
  int wraps = 0;
  // A bobble (MB): `bobble_loops` loops worked into the stitch, then worked back and
  // forth over them in short rows, `bobble_rows` rows in all counting the one that made
  // them, and gathered into one loop again (k5tog, or the others passed over the first).
  // It works one stitch and leaves one; 0: not a bobble.
  int bobble_loops = 0, bobble_rows = 0;
  // Held (a short row turns before it): the stitch is left on its needle as it was and
  // no yarn passes it, so, unlike a slip, it leaves no float.
  bool unreached = false;
  // The stitch as it shows on the face when worked on a wrong-side row (k shows as p);
  // empty if it has no wrong-side form.
  std::string_view wrong_side_face;
};

std::span<const StitchDef> stitch_table();
const StitchDef& stitch(StitchId id);
StitchId stitch_id(std::string_view canonical_name);                    // asserts it exists
// Whether the stitch's new loops are purled (pulled through from the front: a bump on
// the face): purls, p-decreases and p-increases, ssp, m1p.
bool purled(const StitchDef& s);
// The stitch of its block a cable's new loop j (left to right, face view) is pulled
// through: for n stitches with h held, new j comes from old (j < h ? n - h + j : j - h);
// in a three-part cross the outer h on each side change places around the middle.
int cable_source(const StitchDef& s, int j);
// The face-view stitch for `id` worked on a wrong-side row, if it has one.
std::optional<StitchId> wrong_side_face(StitchId id);
// A cross as the Stitch Maps notation counts it: `over` stitches on top cross `under`
// stitches (n/m), or the outer `over` on each side change places around `middle` (n/c/n).
struct CrossCounts {
  int over = 0, middle = 0, under = 0;
};
// For the cable family; asserts s is a cable.
CrossCounts cross_counts(const StitchDef& s);
// The cable family's crosses in the Stitch Maps notation ("2/2 LC", "2/1/2 RPC"): the
// name a cross's facts give it, "2/2 RC purled" for a knit cross seen from the back.
// Empty for other stitches.
std::string cross_notation(const StitchDef& s);
// The bobbles the table has: loops made in the stitch and rows worked over them, each
// within these bounds; and the name of one ("bobble 5x4", the printed MB).
inline constexpr int bobble_loops_min = 3, bobble_loops_max = 7, bobble_rows_min = 1, bobble_rows_max = 6;
std::string bobble_name(int loops, int rows);

}  // namespace knitc

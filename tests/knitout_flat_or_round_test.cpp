// Knitout in: whether a program knits flat or in the round, when it does some of each.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "compile.hpp"
#include "knitout.hpp"
#include "layout/layout.hpp"
#include "stitches/stitches.hpp"
#include "support.hpp"

using namespace knitc;
using namespace knitc::knitout;

namespace {

std::string n(char bed, int i) { return std::string(1, bed) + std::to_string(i); }

// An i-cord cast-on after CMU's (../shared/knitout/real/cmu-icord-cast-on.k): a cord of
// `cord` stitches a bed knitted round, moved one needle left each round, leaving a tuck
// on the needle it left, `stitches` times; the cord's back loops put on its front ones;
// then `rows` flat rows of jersey on the front bed across them all.
std::string icord_cast_on(int cord, int stitches, int rows) {
  const int s0 = stitches + 1;  // the cord starts on s0 .. s0 + cord - 1
  std::string k = ";!knitout-2\n;;Carriers: 3\ninhook 3\nrack -0.75\n";
  for (int i = s0 + cord - 1; i >= s0; --i) k += "tuck - " + n('f', i) + " 3\ntuck - " + n('b', i) + " 3\n";
  k += "rack 0\n";
  for (int i = s0; i < s0 + cord; ++i) k += "knit + " + n('f', i) + " 3\n";
  k += "releasehook 3\n";
  for (int i = s0 + cord - 1; i >= s0; --i) k += "knit - " + n('b', i) + " 3\n";
  for (int s = s0 - 1; s >= 1; --s) {  // the cord moves to s .. s + cord - 1
    for (int i = s + 1; i <= s + cord; ++i) k += "xfer " + n('f', i) + " bs" + std::to_string(i) + "\n";
    k += "rack -1\n";
    for (int i = s + 1; i <= s + cord; ++i) k += "xfer bs" + std::to_string(i) + " " + n('f', i - 1) + "\n";
    k += "rack 0\n";
    for (int i = s; i < s + cord; ++i) k += "knit + " + n('f', i) + " 3\n";
    k += "tuck + " + n('f', s + cord) + " 3\n";
    for (int i = s + 1; i <= s + cord; ++i) k += "xfer " + n('b', i) + " fs" + std::to_string(i) + "\n";
    k += "rack 1\n";
    for (int i = s + 1; i <= s + cord; ++i) k += "xfer fs" + std::to_string(i) + " " + n('b', i - 1) + "\n";
    k += "rack 0\n";
    for (int i = s + cord - 1; i >= s; --i) k += "knit - " + n('b', i) + " 3\n";
  }
  for (int i = 1; i <= cord; ++i) k += "xfer " + n('b', i) + " " + n('f', i) + "\n";
  const int last = stitches + cord;
  for (int r = 0; r < rows; ++r)
    for (int j = 1; j <= last; ++j) k += r % 2 == 0 ? "knit + " + n('f', j) + " 3\n" : "knit - " + n('f', last + 1 - j) + " 3\n";
  return k + "outhook 3\n";
}

}  // namespace

TEST(KnitoutFlatOrRound, AnICordCastOnsFabricIsFlat) {
  // The cord's rounds go round both beds; the fabric's rows go along the front bed and
  // back. Weighed by loops the fabric is the most of it, and is flat. Read round (as
  // before, when passes on one bed were not weighed), its rows were wrapped round a tube
  // 16 stitches round: 11 mm deep.
  const int stitches = 13, cord = 3, rows = 12;
  const Pattern p = import_text(icord_cast_on(cord, stitches, rows), "icord.k").pattern;
  EXPECT_EQ(p.knitting, Knitting::flat);
  ASSERT_GE(p.courses.size(), static_cast<std::size_t>(rows));
  for (std::size_t c = p.courses.size() - rows; c < p.courses.size(); ++c) {
    int made = 0;
    for (const Op& op : p.courses[c].ops) made += stitch(op.stitch).produces;
    EXPECT_EQ(made, stitches + cord) << "course " << c;
  }
  // Laid out, the fabric's rows lie in one sheet: their loops within a few yarn
  // diameters of the fabric's plane (5: its first row's loops are pulled 6 needles along
  // to the next row's, and a loop pulled that far passes its legs half a diameter either
  // side, layout/pull_through.cpp; 4 before).
  const Fabric f = compile(p, test::centrelines(false));
  const int first = static_cast<int>(p.courses.size()) - rows;
  double low = 1e9, high = -1e9;
  for (const auto& loop : f.layout.loops)
    if (loop.course >= first)
      for (const auto& q : loop.data_points) {
        const double z = layout::to_fabric(f.layout, q, loop.course).z;
        low = std::min(low, z), high = std::max(high, z);
      }
  EXPECT_LT(high - low, 5.0 * p.yarns.front().diameter);
}

TEST(KnitoutFlatOrRound, ATubeWithAFewFlatRowsIsRound) {
  // The same weighing keeps a tube a tube: two flat rows of waste on the front bed
  // before twenty rounds.
  const int w = 8;
  std::string k = ";!knitout-2\n;;Carriers: 1\ninhook 1\n";
  for (int i = w; i >= 1; --i) k += "tuck - " + n('f', i) + " 1\n";
  for (int i = 1; i <= w; ++i) k += "knit + " + n('f', i) + " 1\n";
  for (int i = w; i >= 1; --i) k += "knit - " + n('f', i) + " 1\n";
  for (int i = 1; i <= w; ++i) k += "tuck + " + n('b', i) + " 1\n";
  for (int r = 0; r < 20; ++r) {
    for (int i = w; i >= 1; --i) k += "knit - " + n('f', i) + " 1\n";
    for (int i = 1; i <= w; ++i) k += "knit + " + n('b', i) + " 1\n";
  }
  k += "outhook 1\n";
  EXPECT_EQ(import_text(k, "tube.k").pattern.knitting, Knitting::round);
}

// Knitout in: a tube's edges, read round: its cast-on and its bind-off.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include <glm/geometric.hpp>

#include "compile.hpp"
#include "knitout.hpp"
#include "layout/layout.hpp"
#include "support.hpp"

using namespace knitc;
using namespace knitc::knitout;

namespace {

std::string n(char bed, int i) { return std::string(1, bed) + std::to_string(i); }

// A tube of `needles` a bed, cast on by knitting the empty needles, `rounds` rounds,
// then bound off as CMU's mil-tube.k is (../shared/knitout/real): round the front bed
// and back along the back, each needle knitted three times, back and forth, before its
// loop is moved onto the next needle.
std::string tube_with_chain_bind_off(int needles, int rounds) {
  std::string k = ";!knitout-2\n;;Carriers: 3\ninhook 3\n";
  for (int r = 0; r <= rounds; ++r) {
    for (int i = 1; i <= needles; ++i) k += "knit + " + n('f', i) + " 3\n";
    for (int i = needles; i >= 1; --i) k += "knit - " + n('b', i) + " 3\n";
    if (r == 0) k += "releasehook 3\n";
  }
  auto chain = [&](char bed, int i, bool rightwards) {
    const std::string there = " " + n(bed, i) + " 3\n";
    k += (rightwards ? "knit +" : "knit -") + there + (rightwards ? "knit -" : "knit +") + there +
         (rightwards ? "knit +" : "knit -") + there;
  };
  for (int i = 1; i < needles; ++i) {
    chain('f', i, i % 2 == 1);
    k += "xfer " + n('f', i) + " bs" + std::to_string(i) + "\nrack 1\nxfer bs" + std::to_string(i) + " " +
         n('f', i + 1) + "\nrack 0\n";
  }
  chain('f', needles, needles % 2 == 1);
  k += "xfer " + n('f', needles) + " " + n('b', needles) + "\n";
  for (int i = needles; i > 1; --i) {
    chain('b', i, i % 2 == 0);
    k += "xfer " + n('b', i) + " fs" + std::to_string(i) + "\nrack 1\nxfer fs" + std::to_string(i) + " " +
         n('b', i - 1) + "\nrack 0\n";
  }
  chain('b', 1, true);
  return k + "outhook 3\ndrop b1\n";
}

}  // namespace

TEST(KnitoutTubeEdges, AChainBindOffsYarnGoesUpItsNeedleNotRoundTheTube) {
  // Each of the chain's knits on one needle is a course of one loop. The yarn went from
  // one to the next a turn round the tube, as rounds do: a float all round the top for
  // each (mil-tube.k: two of 155 mm). It goes straight up its needle.
  const int needles = 12;
  const Imported in = import_text(tube_with_chain_bind_off(needles, 4), "tube.k");
  ASSERT_EQ(in.pattern.knitting, Knitting::round);
  const Fabric f = compile(in.pattern, test::centrelines(false));
  const double round = 2.0 * needles * f.layout.loop_width;
  int between = 0;
  for (const auto& piece : f.pieces) {
    const auto& path = piece.path;
    for (std::size_t j = 0; j + 1 < path.loops.size(); ++j) {
      double length = 0.0;
      for (std::size_t k = path.loop_last[j]; k < path.loop_first[j + 1]; ++k)
        length += glm::distance(path.data_points[k], path.data_points[k + 1]);
      EXPECT_LT(length, 0.25 * round) << "between loops " << path.loops[j] << " and " << path.loops[j + 1];
      ++between;
    }
  }
  EXPECT_GT(between, 5 * 2 * needles);
}

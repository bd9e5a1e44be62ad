// Snapshots catch every real change and no noise: a data point moved by one micrometre
// changes the snapshot; running again does not.
#include <gtest/gtest.h>

#include "support.hpp"
#include "measure/measure.hpp"
#include "writers/writers.hpp"

namespace knitc {
namespace {

// The snapshot of a fabric, with its own measures.
std::string summary(const Pattern& p, const Fabric& f) { return writers::snapshot(p, f, measure::measure(p, f.layout, f.pieces)); }

TEST(Snapshot, AOneMicrometreChangeOfADataPointShows) {
  const Pattern p = test::jersey(6, 4);
  CompileOptions o;
  const layout::Layout base = layout::lay_out(p);
  const std::string before = summary(p, compile(p, base, o));
  EXPECT_EQ(before, summary(p, compile(p, base, o)));  // no noise on a rerun
  EXPECT_EQ(before, summary(p, compile(p, o)));
  int changed = 0;
  for (const int loop : {0, 7, 23}) {
    for (const int point : {1, 4, 8, 12}) {
      for (int axis = 0; axis < 3; ++axis) {
        layout::Layout moved = base;
        moved.loops[loop].data_points[point][axis] += 0.001;  // one micrometre
        changed += summary(p, compile(p, moved, o)) != before;
      }
    }
  }
  EXPECT_EQ(changed, 3 * 4 * 3);
}

TEST(Snapshot, SaysWhatTheFabricIs) {
  const Pattern p = test::jersey(4, 3);
  const std::string s = summary(p, compile(p, CompileOptions{}));
  EXPECT_EQ(s.rfind("knitc snapshot 2\npattern     jersey\ncourses     4\nwales       4\nloops       16\npieces      1\n", 0), 0u)
      << s;
  EXPECT_NE(s.find("\nyarn A mm  "), std::string::npos);
  EXPECT_NE(s.find("\npenetration "), std::string::npos);
  EXPECT_NE(s.find("\ngeometry    fnv1a64 "), std::string::npos);
  EXPECT_NE(s.find("\nmesh        flat: "), std::string::npos) << s;
  EXPECT_NE(s.find("\ndensity     12 sides, tolerance 0.0100 d, as given\n"), std::string::npos) << s;
}

}  // namespace
}  // namespace knitc

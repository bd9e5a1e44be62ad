// libFuzzer target for the work (runtime/language/work.hpp), the knitting's state the
// verbs drive: the input is a sequence of calls (cast on, rows of written text or of any
// stitches, yarn changes, a wrong-side first row, bind off, marks and restores). Whatever
// the calls: a call that fails changes nothing; each course works exactly the stitches
// the one below left; the live count is the last course's; a restore gives back exactly
// the marked work.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include <fuzzer/FuzzedDataProvider.h>

#include "language/work.hpp"

namespace {

using namespace knitc;
using language::Work;

[[noreturn]] void violated(const char* what) {
  std::fprintf(stderr, "fuzz_work: invariant violated: %s\n", what);
  std::fflush(stderr);
  __builtin_trap();
}

void check(bool ok, const char* what) {
  if (!ok) violated(what);
}

struct State {
  Pattern pattern;
  int live, yarn, next_row, cast_on_line, bind_off_line;
  std::vector<int> markers;
  bool operator==(const State&) const = default;
};

State state_of(const Work& w) {
  return {w.pattern(), w.live(), w.yarn(), w.next_row(), w.cast_on_line(), w.bind_off_line(), w.markers()};
}

void check_fabric(const Work& w) {
  const Pattern& p = w.pattern();
  int below = p.cast_on;
  for (const Course& c : p.courses) {
    check(consumed(c) == below, "a course works other stitches than the one below left");
    below = produced(c);
  }
  if (!p.bound_off && w.cast_on_line() != 0) check(w.live() == below, "the live count is not the last course's");
  if (p.bound_off) check(w.live() == 0, "stitches live after the bind-off");
}

const char* const texts[] = {"k", "p", "k2, p2", "k2tog", "yo, k2tog", "*k1, p1; rep from *", "k to end", "m1, k",
                             "kfb", "sl1 wyif, k1", "C4F", "k1, (p1, k1) x3", "p2tog, p", "knit the knit sts and purl the purl sts",
                             "k2 B", "cdd", "ssk, k, k2tog", "k1 tbl", "2/2 RC", "k3tog", "k3, pm, k to end",
                             "k to m, sm, p to end", "p to 2 sts before m, k2, rm, k to end", "*k1, p1; rep from * to m, pm, k", "BO 3 sts, k to end", "k2, drop, k", "wrap 3, k"};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  Pattern declared;
  declared.name = "fuzz";
  declared.knitting = in.ConsumeBool() ? Knitting::flat : Knitting::round;
  declared.yarns.push_back({"A", 1.0, "#d9c8a9"});
  declared.yarns.push_back({"B", 1.0, "#8a1c2b"});
  const std::vector<std::string> yarn_ids = {"A", "B"};
  Work w(declared, {in.ConsumeIntegralInRange<long long>(1, 400), in.ConsumeIntegralInRange<long long>(1, 20000)});
  std::vector<std::pair<Work::Mark, State>> marks;
  int line = 0;
  while (in.remaining_bytes() > 0) {
    ++line;
    const State before = state_of(w);
    std::optional<std::string> error;
    switch (in.ConsumeIntegralInRange(0, 8)) {
      case 0: error = w.cast_on(in.ConsumeIntegralInRange(-2, 500), in.ConsumeIntegralInRange(0, 1), line); break;
      case 1:
      case 2: {
        const std::string text = in.ConsumeBool() ? texts[in.ConsumeIntegralInRange<std::size_t>(0, std::size(texts) - 1)]
                                                  : in.ConsumeRandomLengthString(40);
        const auto parsed = language::parse_row(text, yarn_ids, false);
        if (const auto* row = std::get_if<language::RowText>(&parsed)) error = w.work_text(*row, text, {"fuzz.lua", line});
        break;
      }
      case 3: {  // any stitches in face view, fitting or not
        std::vector<Op> ops(in.ConsumeIntegralInRange<std::size_t>(0, 60));
        for (Op& op : ops) {
          op.stitch = static_cast<StitchId>(in.ConsumeIntegralInRange<std::size_t>(0, stitch_table().size() - 1));
          op.yarn = in.ConsumeIntegralInRange(0, 1);
        }
        error = w.add(std::move(ops), {"fuzz.lua", line});
        break;
      }
      case 4: w.change_yarn(in.ConsumeIntegralInRange(0, 1)); break;
      case 5: error = w.start_on_wrong_side(); break;
      case 6: error = w.bind_off(line); break;
      case 7: marks.emplace_back(w.mark(), state_of(w)); break;
      default:
        if (!marks.empty()) {  // marks nest, as the verbs take them: the later ones go
          const std::size_t i = in.ConsumeIntegralInRange<std::size_t>(0, marks.size() - 1);
          w.restore(marks[i].first);
          check(state_of(w) == marks[i].second, "a restore did not give back the marked work");
          marks.resize(i + 1);
        }
        break;
    }
    if (error) {
      check(!error->empty(), "an error without a message");
      check(state_of(w) == before, "a call that failed changed the work");
    }
    check_fabric(w);
  }
  return 0;
}

// libFuzzer target for written row instructions: the spelling normalisation, parse_row,
// then work_row and face_view on both sides, checking what must hold whatever the text.
//
// Input: two bytes (big-endian) that give the live stitch count, 1 + value % 2000,
// then the row's text.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "language/spelling.hpp"
#include "language/written.hpp"

namespace {

using namespace knitc;
using namespace knitc::language;

constexpr int max_live = 2000;

[[noreturn]] void violated(const char* what) {
  std::fprintf(stderr, "fuzz_written: invariant violated: %s\n", what);
  std::fflush(stderr);
  __builtin_trap();
}

void check(bool ok, const char* what) {
  if (!ok) violated(what);
}

bool valid_id(StitchId id) { return id < stitch_table().size(); }

void check_error(const TextError& e, const char* what) { check(!e.message.empty(), what); }

void check_sequence(const Sequence& seq, int yarns, int depth) {
  check(depth < 100'000, "nesting deeper than the text");
  for (const Element& e : seq) {
    check(e.count >= 1, "an element worked fewer than once");
    if (e.is_group) {
      check(!e.body.empty(), "an empty group was accepted");
      check_sequence(e.body, yarns, depth + 1);
    } else {
      check(valid_id(e.stitch.stitch), "parse_row gave an invalid stitch id");
      check(e.stitch.yarn >= -1 && e.stitch.yarn < yarns, "parse_row gave a yarn out of range");
    }
  }
}

// The normalisation the parser reads through: once is enough, and a spelling it reads is
// a stitch of the table or a refusal that names its candidates.
void check_spelling(std::string_view text) {
  const std::string once = normalise(text);
  check(normalise(once) == once, "normalise is not idempotent");
  const auto read = read_stitch(once);
  if (const auto* r = std::get_if<Reading>(&read)) {
    check(valid_id(r->stitch), "read_stitch gave an invalid stitch id");
    check(r->count >= 1 && r->count <= 100'000, "read_stitch gave a count out of range");
  } else if (const auto* a = std::get_if<Ambiguous>(&read)) {
    check(a->candidates.size() >= 2, "an ambiguous spelling names fewer than two candidates");
    check(!ambiguous_message(*a).empty(), "an ambiguous spelling has no message");
  }
}

void run(std::string_view text, int live) {
  static const std::vector<std::string> yarn_ids{"A", "B", "MC"};
  const int yarns = static_cast<int>(yarn_ids.size());
  if (text.size() <= 4096) check_spelling(text);

  const auto parsed = parse_row(text, yarn_ids);
  if (const auto* e = std::get_if<TextError>(&parsed)) {
    check_error(*e, "parse_row failed with an empty message");
    return;
  }
  const RowText& row = std::get<RowText>(parsed);
  if (!row.parts.empty()) {  // cut at stitch markers: the work gives each part its room
    check(row.before.empty() && !row.star && row.after.empty(), "a row cut at markers also lists stitches of its own");
    bool stitches = false;
    for (const MarkedPart& part : row.parts) {
      check(part.text.parts.empty(), "a part of a row has parts of its own");
      check_sequence(part.text.before, yarns, 0);
      if (part.text.star) check_sequence(*part.text.star, yarns, 0);
      check_sequence(part.text.after, yarns, 0);
      stitches = stitches || !part.text.before.empty() || part.text.star || !part.text.after.empty();
    }
    check(stitches, "a row of markers only was accepted");
    return;
  }
  check_sequence(row.before, yarns, 0);
  if (row.star) {
    check(!row.star->empty(), "an empty *repeat was accepted");
    check_sequence(*row.star, yarns, 0);
  }
  check_sequence(row.after, yarns, 0);
  if (row.as_they_appear) {  // "knit the knit sts and purl the purl sts": no stitches of its own
    check(row.before.empty() && !row.star && row.after.empty(), "a row worked as it appears also lists stitches");
    check(work_row(row, text, live, 1).index() == 1, "work_row worked a row as it appears without the stitches below");
    return;
  }
  check(!row.before.empty() || row.star || !row.after.empty(), "a row with no stitches was accepted");

  const auto result = work_row(row, text, live, 1);
  if (const auto* e = std::get_if<TextError>(&result)) {
    check_error(*e, "work_row failed with an empty message");
    return;
  }
  const std::vector<Worked>& worked = std::get<std::vector<Worked>>(result);
  long long used = 0;
  for (const Worked& w : worked) {
    check(valid_id(w.stitch), "work_row gave an invalid stitch id");
    check(w.yarn >= -1 && w.yarn < yarns, "work_row gave a yarn out of range");
    used += stitch(w.stitch).consumes;
  }
  check(used == live, "the worked row does not consume exactly the live stitches");
  check(consumed(worked) == live, "consumed() disagrees with the live stitches");

  for (const Side side : {Side::right, Side::wrong}) {
    const int current_yarn = side == Side::right ? 0 : 2;
    const auto face = face_view(worked, side, current_yarn);
    if (const auto* e = std::get_if<TextError>(&face)) {
      check(side == Side::wrong, "face_view failed on a right-side row");
      check_error(*e, "face_view failed with an empty message");
      continue;
    }
    const std::vector<Op>& ops = std::get<std::vector<Op>>(face);
    check(ops.size() == worked.size(), "face_view changed the number of stitches");
    for (std::size_t i = 0; i < ops.size(); ++i) {
      const Op& op = ops[i];
      // Right-side rows are worked right to left: face order is working order reversed.
      const Worked& w = side == Side::right ? worked[worked.size() - 1 - i] : worked[i];
      check(valid_id(op.stitch), "face_view gave an invalid stitch id");
      check(op.yarn == (w.yarn < 0 ? current_yarn : w.yarn), "face_view gave the wrong yarn");
      if (side == Side::right) check(op.stitch == w.stitch, "face_view changed a right-side stitch");
      else check(stitch(op.stitch).consumes == stitch(w.stitch).consumes, "a wrong-side face works a different count");
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 2) return 0;
  const int live = 1 + ((data[0] << 8) | data[1]) % max_live;
  const std::string_view text(reinterpret_cast<const char*>(data + 2), size - 2);
  try {
    run(text, live);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz_written: exception escaped: %s\n", e.what());
    violated("an exception escaped");
  } catch (...) {
    violated("an unknown exception escaped");
  }
  return 0;
}

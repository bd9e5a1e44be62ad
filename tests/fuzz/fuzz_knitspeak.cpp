// libFuzzer target for printed pattern text: read_knitspeak, checking what must hold
// whatever the text: rows and notes name lines of the block, rows in number order carry
// their printed number, a stated count is never negative, an error has a message.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "language/knitspeak.hpp"

namespace {

using namespace knitc::language;

void check(bool ok, const char* what) {
  if (ok) return;
  std::fprintf(stderr, "fuzz_knitspeak: invariant violated: %s\n", what);
  std::fflush(stderr);
  __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::vector<std::string> yarn_ids{"A", "B"};
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const int lines = static_cast<int>(std::count(text.begin(), text.end(), '\n')) + 1;
  const auto read = read_knitspeak(text, yarn_ids);
  if (const auto* e = std::get_if<KnitspeakNote>(&read)) {
    check(!e->message.empty(), "an error without a message");
    check(e->line >= 0 && e->line < lines, "an error on a line the text does not have");
    return 0;
  }
  const auto& k = std::get<Knitspeak>(read);
  for (const auto& r : k.rows) {
    check(r.line >= 0 && r.line < lines, "a row from a line the text does not have");
    check(!r.text.empty(), "a row without stitches");
    check(!r.stitches_after || *r.stitches_after >= 0, "a negative stated count");
  }
  for (const auto& n : k.skipped) check(n.line >= 0 && n.line < lines, "a skipped line the text does not have");
  return 0;
}

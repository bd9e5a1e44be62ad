// libFuzzer target for knitout in: any text is parsed and run on the machine; it either
// reads into a pattern the knit graph takes, or fails with a KnitoutError at a line of
// the text. Nothing else may escape, and nothing may crash or hang.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

#include "knit_graph/knit_graph.hpp"
#include "knitout.hpp"

namespace {

void check(bool ok, const char* what) {
  if (ok) return;
  std::fprintf(stderr, "fuzz_knitout: invariant violated: %s\n", what);
  std::fflush(stderr);
  __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const int lines = static_cast<int>(std::count(text.begin(), text.end(), '\n')) + 1;
  try {
    const knitc::knitout::Imported in = knitc::knitout::import_text(text, "fuzz.k");
    check(in.pattern.cast_on > 0, "a pattern read with no cast-on");
    knitc::knit_graph::build(in.pattern);  // the courses work exactly the live stitches
    // What reads back also writes, or is refused at a row.
    try {
      const auto out = knitc::knitout::export_pattern(in.pattern, knitc::knitout::profile_named("swg"));
      check(out.text.starts_with(";!knitout-2\n"), "an export without its version line");
    } catch (const knitc::knitout::KnitoutError&) {
    }
  } catch (const knitc::knitout::KnitoutError& e) {
    check(e.line >= 1 && e.line <= lines, "a knitout error's line is outside the text");
    check(std::string(e.what()).starts_with("fuzz.k:"), "a knitout error without its file");
  }
  return 0;
}

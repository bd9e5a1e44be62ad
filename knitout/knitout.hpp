// A knitout program in, the Pattern the rest of knitc compiles out: the machine is run
// (machine.hpp), the loops it made grouped into courses, and each course said in the
// stitches patterns use, as seen from the face. docs/knitout.md says what is drawn
// exactly and what is approximated.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "machine.hpp"
#include "pattern.hpp"
#include "program.hpp"

namespace knitc::knitout {

struct Imported {
  Pattern pattern;
  std::vector<std::string> warnings;  // the parser's and the machine's, "file:line: warning: ..."
  Profile profile;
  long long front_loops = 0, back_loops = 0;  // loops the machine made on each bed (tucks too)
};

// Runs the program on the profile's machine and says what it knitted as a Pattern.
// Throws KnitoutError ("file:line: ...; hint") for what the machine cannot do or knitc
// cannot yet draw.
Imported import_program(const Program& program, const Profile& profile);

// Parses and imports; the profile from the program's header.
Imported import_text(std::string_view text, const std::string& file);

}  // namespace knitc::knitout

namespace knitc::knitout {

// A pattern as a V-bed program for a profile: a cast-on of alternate tucks, each course
// knitted (purls on the back bed, decreases, lace and cables by transfers in the crossing
// order the pattern asks, tucks, slips), one carrier per yarn, a chain bind-off, and a
// ";!source:" before each course naming its pattern line. Flat work; in the round, a
// tube on both beds of knit, tuck and slip stitches. Throws KnitoutError at the
// pattern's "file:line" for a stitch the profile cannot knit (or knitc cannot yet write)
// or a racking it cannot reach.
struct Exported {
  std::string text;
  std::vector<std::string> warnings;
};
Exported export_pattern(const Pattern& pattern, const Profile& profile);

}  // namespace knitc::knitout

namespace knitc::knitout {

// The checker an export must pass: the program runs on the profile's machine (every
// operation legal there: needles on the bed, transfers aligned, racking in reach,
// carriers in before use), every course reads exactly (nothing drawn approximately), and
// no loop is dropped unsecured (every drop runs down a wale to a yarn over). Returns
// what is wrong, one line each; empty when it passes. `imported` gets what it read.
std::vector<std::string> check_program(std::string_view text, const std::string& file, const Profile& profile, Imported* imported = nullptr);

}  // namespace knitc::knitout

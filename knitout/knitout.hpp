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

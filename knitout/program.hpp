// A knitout (.k) program as plain data: its header and its operations, each with the
// line it was written on. Parsing only: nothing here knows what the operations do to the
// loops (machine.hpp does). The format: "The Knitout (.k) File Format", CMU textiles lab.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace knitc::knitout {

// A problem in a knitout program a machine programmer can act on. what() is
// "file:line: message (;!source: ...). hint", the source part only when the program gave one.
class KnitoutError : public std::runtime_error {
 public:
  KnitoutError(const std::string& message, int at_line) : std::runtime_error(message), line(at_line) {}
  int line;
};

enum class Opcode : unsigned char {
  in, inhook, releasehook, out, outhook,  // carriers
  knit, tuck, split, miss, drop, amiss, xfer,  // needles
  rack, stitch, pause, extension,
};
std::string_view name(Opcode op);

// The beds: front, back, and their sliders (which hold loops in transfers, never knit).
enum class Bed : unsigned char { f, b, fs, bs };
inline bool front(Bed bed) { return bed == Bed::f || bed == Bed::fs; }
inline bool slider(Bed bed) { return bed == Bed::fs || bed == Bed::bs; }

struct Needle {
  Bed bed = Bed::f;
  int index = 0;
  bool operator==(const Needle&) const = default;
};
std::string name(Needle needle);  // "f12", "bs-3"

struct Operation {
  Opcode op = Opcode::pause;
  int line = 0;             // 1-based line of the file
  int source = -1;          // the ";!source:" in effect: index into Program::sources, or -1
  int direction = 0;        // knit, tuck, split, miss: +1 (increasing needle index) or -1
  Needle needle, target;    // target: split's and xfer's second needle
  std::vector<int> carriers;  // indices into Program::carriers, as written
  double racking = 0.0;     // rack
  double loop = 0.0, extra = 0.0;  // stitch L T
  std::string words;        // an extension's name and arguments, as written
};

struct Program {
  std::string file;                       // the name messages use
  int version = 0;                        // N of ";!knitout-N"
  std::vector<std::pair<std::string, std::string>> headers;  // ";;Name: value", in order
  std::vector<std::string> rails;         // ";;Carriers:" names, or empty when it is missing
  std::vector<std::string> carriers;      // every carrier name the operations use, first use first
  std::vector<Operation> operations;
  std::vector<std::string> sources;       // ";!source:" texts
  std::vector<std::string> warnings;      // "file:line: ..." each
  const std::string* header(std::string_view name) const;  // its value, or null
};

// Reads the text of a knitout program: CRLF or LF, comments glued to operations, blank
// carrier sets, negative and slider needles, rackings spelled "+1" or "0.0". Throws
// KnitoutError for a line that is not knitout (an unknown operation, a malformed needle
// or direction); warns for an unknown extension, a missing ";;Carriers:" header, a newer
// version.
Program parse(std::string_view text, const std::string& file);

// Whether a file's name or first bytes say knitout: ".k", ".knitout", or ";!knitout-".
bool looks_like_knitout(const std::string& path, std::string_view first_bytes);

// "file:line: message (;!source: ...); hint" at an operation: what KnitoutError carries.
std::string located(const Program& program, const Operation& op, const std::string& message, const std::string& hint);

}  // namespace knitc::knitout

#include "program.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <optional>

namespace knitc::knitout {

namespace {

constexpr std::array<std::string_view, 16> opcode_names = {
    "in", "inhook", "releasehook", "out", "outhook", "knit", "tuck", "split",
    "miss", "drop", "amiss", "xfer", "rack", "stitch", "pause", "x-"};

// The extensions the real programs use: none of them changes the fabric's topology.
constexpr std::array<std::string_view, 13> known_extensions = {
    "x-stitch-number", "x-speed-number", "x-sub-roller-number", "x-presser-mode", "x-roller-advance",
    "x-add-roller-advance", "x-xfer-style", "x-carrier-spacing", "x-carrier-stopping-distance",
    "x-vis-color", "x-end-pass", "x-fabric-presser", "x-loop-shape"};

// The newest knitout version these rules are written for.
constexpr int known_version = 2;

bool blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

std::vector<std::string_view> split_words(std::string_view s) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && blank(s[i])) ++i;
    const std::size_t start = i;
    while (i < s.size() && !blank(s[i])) ++i;
    if (i > start) out.push_back(s.substr(start, i - start));
  }
  return out;
}

// The opcode a word names, or none (`x-` extensions are not looked up here).
std::optional<Opcode> opcode_of(std::string_view word) {
  const auto known = std::find(opcode_names.begin(), opcode_names.end() - 1, word);
  if (known == opcode_names.end() - 1) return std::nullopt;
  return static_cast<Opcode>(known - opcode_names.begin());
}

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && blank(s.back())) s.remove_suffix(1);
  return s;
}

struct Reader {
  Program& program;
  int line = 0;

  [[noreturn]] void fail(const std::string& message, const std::string& hint, int source) const {
    std::string text = program.file + ":" + std::to_string(line) + ": " + message;
    if (source >= 0) text += " (;!source: " + program.sources[static_cast<std::size_t>(source)] + ")";
    if (!hint.empty()) text += "; " + hint;
    throw KnitoutError(text, line);
  }

  void warn(const std::string& message) { program.warnings.push_back(program.file + ":" + std::to_string(line) + ": warning: " + message); }

  Needle needle(std::string_view word, int source) const {
    Needle n;
    std::size_t at = 0;
    if (word.starts_with("fs")) n.bed = Bed::fs, at = 2;
    else if (word.starts_with("bs")) n.bed = Bed::bs, at = 2;
    else if (word.starts_with("f")) n.bed = Bed::f, at = 1;
    else if (word.starts_with("b")) n.bed = Bed::b, at = 1;
    else fail("'" + std::string(word) + "' is not a needle", "a needle is a bed (f, b, fs or bs) and an index, like f12 or b-3", source);
    const char* first = word.data() + at;
    const char* last = word.data() + word.size();
    const auto [end, error] = std::from_chars(first, last, n.index);
    if (first == last || error != std::errc() || end != last || std::abs(static_cast<long long>(n.index)) > 1'000'000)
      fail("'" + std::string(word) + "' is not a needle", "a needle is a bed (f, b, fs or bs) and a whole index of at most a million, like f12 or b-3", source);
    return n;
  }

  int direction(std::string_view word, int source) const {
    if (word == "+") return 1;
    if (word == "-") return -1;
    fail("'" + std::string(word) + "' is not a direction", "write + (towards higher needles) or - (towards lower)", source);
  }

  double number(std::string_view word, const char* what, int source) const {
    if (!word.empty() && word.front() == '+') word.remove_prefix(1);
    double v = 0.0;
    const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), v);
    const bool read = !word.empty() && end == word.data() + word.size() && (error == std::errc() || error == std::errc::result_out_of_range);
    if (!read || (error == std::errc() && std::isnan(v)))
      fail("'" + std::string(word) + "' is not a number", std::string("write the ") + what + " as a number, like 1, -0.75 or +0.25", source);
    if (error != std::errc() || !std::isfinite(v) || std::abs(v) > 1e6)
      fail("the " + std::string(what) + " " + std::string(word) + " is out of range", std::string("write the ") + what + " as a number of at most a million either way", source);
    return v;
  }

  int carrier(std::string_view word) {
    auto& names = program.carriers;
    const auto it = std::find(names.begin(), names.end(), word);
    if (it != names.end()) return static_cast<int>(it - names.begin());
    names.emplace_back(word);
    return static_cast<int>(names.size()) - 1;
  }

  void arity(const std::vector<std::string_view>& w, std::size_t least, std::size_t most, const char* usage, int source) const {
    if (w.size() < least || w.size() > most)
      fail("'" + std::string(w.front()) + "' takes " + (least == most ? std::to_string(least - 1) : std::to_string(least - 1) + " to " + std::to_string(most - 1)) +
               " arguments, not " + std::to_string(w.size() - 1),
           std::string("write it as: ") + usage, source);
  }
};

}  // namespace

std::string_view name(Opcode op) { return opcode_names[static_cast<std::size_t>(op)]; }

std::string name(Needle needle) {
  static constexpr std::array<const char*, 4> beds = {"f", "b", "fs", "bs"};
  return beds[static_cast<std::size_t>(needle.bed)] + std::to_string(needle.index);
}

const std::string* Program::header(std::string_view key) const {
  for (const auto& [k, v] : headers)
    if (k == key) return &v;
  return nullptr;
}

std::string located(const Program& program, const Operation& op, const std::string& message, const std::string& hint) {
  std::string text = program.file + ":" + std::to_string(op.line) + ": " + message;
  if (op.source >= 0) text += " (;!source: " + program.sources[static_cast<std::size_t>(op.source)] + ")";
  if (!hint.empty()) text += "; " + hint;
  return text;
}

bool looks_like_knitout(const std::string& path, std::string_view first_bytes) {
  const std::string ext = std::filesystem::path(path).extension().string();
  return ext == ".k" || ext == ".knitout" || first_bytes.starts_with(";!knitout-");
}

Program parse(std::string_view text, const std::string& file) {
  Program program;
  program.file = file;
  Reader r{program};
  bool in_header = true, carriers_header = false;
  int source = -1;
  std::size_t at = 0;
  while (at < text.size() || r.line == 0) {
    const std::size_t end = std::min(text.find('\n', at), text.size());
    std::string_view raw = text.substr(at, end - at);
    at = end + 1;
    ++r.line;
    if (raw.find('\0') != std::string_view::npos)
      r.fail("the file holds a NUL byte: it is not a text file", "a knitout program is plain text", -1);
    if (r.line == 1) {
      if (raw.starts_with("\xEF\xBB\xBF")) raw.remove_prefix(3);
      const std::string_view first = trimmed(raw);
      int version = 0;
      const auto [end_v, error] = std::from_chars(first.data() + std::min<std::size_t>(10, first.size()), first.data() + first.size(), version);
      const bool version_line = first.starts_with(";!knitout-") && error == std::errc() && end_v == first.data() + first.size() && version >= 1;
      // Without the version line (knitout requires it; some tools' programs and tests
      // leave it out), a first line that is itself knitout, an operation or a comment, is
      // read as the newest version, as CMU's visualizer reads it, with a warning; noise
      // is refused at line 1.
      if (!version_line) {
        const auto words = split_words(first.substr(0, first.find(';')));
        const bool operation = !words.empty() && (words.front().starts_with("x-") || opcode_of(words.front()));
        if (first.starts_with(";!knitout-") || (!operation && !first.starts_with(";")))
          r.fail("the first line is not ';!knitout-N'", "a knitout program starts with its version line, like ;!knitout-2", -1);
        r.warn("no ';!knitout-N' version line (knitout requires one); read as knitout-" + std::to_string(known_version));
        program.version = known_version;
      } else {
        program.version = version;
        if (version > known_version)
          r.warn("knitout version " + std::to_string(version) + " is newer than the " + std::to_string(known_version) +
                 " knitc knows; read as version " + std::to_string(known_version));
        if (at >= text.size()) break;
        continue;
      }
    }
    const std::size_t semicolon = raw.find(';');
    const std::string_view code = trimmed(raw.substr(0, semicolon));
    const std::string_view comment = semicolon == std::string_view::npos ? std::string_view{} : raw.substr(semicolon + 1);
    if (in_header && code.empty() && comment.starts_with(";")) {  // ";;Name: value"
      const std::string_view h = comment.substr(1);
      const std::size_t colon = h.find(':');
      if (colon != std::string_view::npos) {
        const std::string key(trimmed(h.substr(0, colon)));
        const std::string value(trimmed(h.substr(colon + 1)));
        if (key == "Carriers") {
          carriers_header = true;
          for (std::string_view w : split_words(value)) program.rails.emplace_back(w);
        }
        program.headers.emplace_back(key, value);
      }
      if (at >= text.size()) break;
      continue;
    }
    int this_source = source;
    if (comment.starts_with("!source:")) {
      program.sources.emplace_back(trimmed(comment.substr(8)));
      this_source = static_cast<int>(program.sources.size()) - 1;
      if (code.empty()) source = this_source;  // on a line of its own: for the operations after it
    }
    if (!code.empty()) {
      in_header = false;
      const auto w = split_words(code);
      Operation op;
      op.line = r.line;
      op.source = this_source;
      const std::string_view opcode = w.front();
      auto carriers_from = [&](std::size_t first) {
        for (std::size_t i = first; i < w.size(); ++i) op.carriers.push_back(r.carrier(w[i]));
      };
      if (opcode.starts_with("x-")) {
        op.op = Opcode::extension;
        op.words = std::string(code);
        if (std::find(known_extensions.begin(), known_extensions.end(), opcode) == known_extensions.end())
          r.warn("unknown extension '" + std::string(opcode) + "' ignored");
      } else {
        const std::optional<Opcode> known = opcode_of(opcode);
        if (!known)
          r.fail("unknown operation '" + std::string(opcode) + "'",
                 "knitout's operations are in, inhook, releasehook, out, outhook, knit, tuck, split, miss, drop, amiss, xfer, rack, stitch, pause and x-... extensions", this_source);
        op.op = *known;
        switch (op.op) {
          case Opcode::in: case Opcode::inhook: case Opcode::releasehook: case Opcode::out: case Opcode::outhook:
            if (w.size() < 2) r.fail("'" + std::string(opcode) + "' names no carrier", "write it with the carriers it moves, like: " + std::string(opcode) + " 3", this_source);
            carriers_from(1);
            break;
          case Opcode::knit: case Opcode::tuck: case Opcode::miss:
            r.arity(w, 3, 1000, (std::string(opcode) + " D N CS (direction, needle, carriers)").c_str(), this_source);
            op.direction = r.direction(w[1], this_source);
            op.needle = r.needle(w[2], this_source);
            carriers_from(3);
            break;
          case Opcode::split:
            r.arity(w, 4, 1000, "split D N N2 CS (direction, needle, target needle, carriers)", this_source);
            op.direction = r.direction(w[1], this_source);
            op.needle = r.needle(w[2], this_source);
            op.target = r.needle(w[3], this_source);
            carriers_from(4);
            break;
          case Opcode::drop: case Opcode::amiss:
            r.arity(w, 2, 2, (std::string(opcode) + " N").c_str(), this_source);
            op.needle = r.needle(w[1], this_source);
            break;
          case Opcode::xfer:
            r.arity(w, 3, 3, "xfer N N2", this_source);
            op.needle = r.needle(w[1], this_source);
            op.target = r.needle(w[2], this_source);
            break;
          case Opcode::rack:
            r.arity(w, 2, 2, "rack R", this_source);
            op.racking = r.number(w[1], "racking", this_source);
            break;
          case Opcode::stitch:
            r.arity(w, 3, 3, "stitch L T", this_source);
            op.loop = r.number(w[1], "loop length", this_source);
            op.extra = r.number(w[2], "length after the loop", this_source);
            break;
          case Opcode::pause: break;
          case Opcode::extension: break;
        }
      }
      program.operations.push_back(std::move(op));
    }
    if (at >= text.size()) break;
  }
  if (!carriers_header)
    program.warnings.push_back(file + ":1: warning: no ';;Carriers:' header (knitout requires one); the carriers are taken as named by the operations");
  return program;
}

}  // namespace knitc::knitout

// Printed text line by line, for read_knitspeak (knitspeak.cpp). Internal to the
// language layer.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pattern.hpp"

namespace knitc::language::knitspeak_lines {

std::string_view trim(std::string_view s);
// Bullets and list marks before a line; never "*", which starts a repeat.
std::string_view without_bullet(std::string_view s);
bool is_fence(std::string_view line);  // a Markdown code fence

struct Label {
  std::vector<int> rows;
  std::optional<Side> side;
  std::string body;
  bool every_other = false;  // "Row 2 and all other WS rows": the text of every such row not given
};

// "Row 1 (RS): ...", "Rnds 2 and 4: ...", "1st row.-K 2", "Row 15 P2": the label and its
// row's text, or nothing (then `problem` may say why a row list cannot be honoured).
std::optional<Label> label(std::string_view line, std::string& problem);

// "Repeat rows 1-4", "As 1st and 2nd rows": the rows, if that is what the text says.
std::optional<std::vector<int>> repeated_rows(std::string_view body, std::string& problem);

// A row's text without a trailing "(14 sts)" (kept in `count`), note in brackets, full
// stop or "Turn work".
std::string without_count(std::string text, std::optional<int>& count);

// A paragraph that runs several rows together, cut before each label.
std::vector<std::string_view> paragraph_rows(std::string_view line);

// "On WS rows, work sts as they appear": the text for every wrong-side row, if that is it.
std::optional<std::string> wrong_side_text(std::string_view line);

// The block's lines, plain (typography as ASCII, "»" bullets as breaks), a row broken
// across lines joined; each with its 0-based line number.
std::vector<std::pair<int, std::string>> plain_lines(std::string_view block);

}  // namespace knitc::language::knitspeak_lines

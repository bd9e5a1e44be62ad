// Rows with stitch markers: "k3, pm, k to m, sm, p2", "rep from * to 2 sts before m, k2".
// The text is cut at its markers into parts, each worked (language/work.cpp) across the
// stitches up to the marker it ends at, so a part's "to end" and "to last 2 sts" mean the
// marker, as knitters mean them.
#include <algorithm>
#include <cctype>
#include <charconv>

#include "language/written.hpp"

namespace knitc::language {

namespace {

// A row's items: the text between commas and semicolons outside brackets, with where
// each starts and ends in the text.
struct Item {
  std::size_t from = 0, to = 0;
  std::string words;  // lower case, single spaces, no full stop at the end
};

std::vector<Item> items_of(std::string_view text) {
  std::vector<Item> out;
  int depth = 0;
  std::size_t start = 0;
  auto close = [&](std::size_t end) {
    Item item{start, end, {}};
    for (std::size_t i = start; i < end; ++i) {
      const char c = static_cast<char>(std::tolower(static_cast<unsigned char>(text[i])));
      if (std::isspace(static_cast<unsigned char>(c))) {
        if (!item.words.empty() && item.words.back() != ' ') item.words += ' ';
      } else {
        item.words += c;
      }
    }
    while (!item.words.empty() && (item.words.back() == ' ' || item.words.back() == '.')) item.words.pop_back();
    out.push_back(std::move(item));
    start = end + 1;
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '(' || c == '[') ++depth;
    else if ((c == ')' || c == ']') && depth > 0) --depth;
    else if ((c == ',' || c == ';') && depth == 0) close(i);
  }
  close(text.size());
  return out;
}

bool ends_with(std::string_view s, std::string_view tail) { return s.size() >= tail.size() && s.substr(s.size() - tail.size()) == tail; }

// "... to m", "... to marker", "... to the next marker": the words before, or nothing.
std::optional<std::string> to_marker(const std::string& w) {
  for (std::string_view tail : {" to m", " to marker", " to the marker", " to next marker", " to the next marker", " to next m"})
    if (ends_with(w, tail)) return w.substr(0, w.size() - tail.size());
  return std::nullopt;
}

// "... to 2 sts before m", "... to last st before marker": the words before and the
// stitches left, or nothing.
std::optional<std::pair<std::string, int>> before_marker(const std::string& w) {
  for (std::string_view tail : {" before m", " before marker", " before the marker", " before next marker", " before the next marker"}) {
    if (!ends_with(w, tail)) continue;
    std::string head = w.substr(0, w.size() - tail.size());
    for (std::string_view unit : {" sts", " st", " stitches", " stitch"}) {
      if (!ends_with(head, unit)) continue;
      head.resize(head.size() - unit.size());
      int n = 1;
      const auto space = head.rfind(' ');
      if (space == std::string::npos) return std::nullopt;
      const std::string_view last = std::string_view(head).substr(space + 1);
      if (last == "last") {
        head.resize(space);
      } else {
        const auto [end, ec] = std::from_chars(last.data(), last.data() + last.size(), n);
        if (ec != std::errc() || end != last.data() + last.size() || n < 1 || n > max_count) return std::nullopt;
        head.resize(space);
        if (ends_with(head, " last")) head.resize(head.size() - 5);
      }
      if (!ends_with(head, " to")) return std::nullopt;
      head.resize(head.size() - 3);
      return std::pair{head, n};
    }
  }
  return std::nullopt;
}

}  // namespace

std::optional<MarkerEnd> marker_word(std::string_view w) {
  for (std::string_view p : {"pm", "place marker", "place a marker", "place m"})
    if (w == p) return MarkerEnd::place;
  for (std::string_view s : {"sm", "slip marker", "slip m", "sl m", "slm", "move marker"})
    if (w == s) return MarkerEnd::slip;
  for (std::string_view r : {"rm", "remove marker", "remove m"})
    if (w == r) return MarkerEnd::remove;
  return std::nullopt;
}

std::optional<std::vector<MarkedText>> split_at_markers(std::string_view text) {
  const std::vector<Item> items = items_of(text);
  bool any = false;
  for (const Item& i : items) any = any || marker_word(i.words) || to_marker(i.words) || before_marker(i.words);
  if (!any) return std::nullopt;
  std::vector<MarkedText> parts;
  std::string current;
  auto add_text = [&](std::string_view t) {
    if (t.find_first_not_of(" \t") == std::string_view::npos) return;
    if (!current.empty()) current += ", ";
    current += t;
  };
  auto cut = [&](MarkerEnd end, int before) {
    parts.push_back({std::move(current), end, before});
    current.clear();
  };
  for (const Item& i : items) {
    if (const auto m = marker_word(i.words)) {
      cut(*m, 0);
    } else if (const auto head = to_marker(i.words)) {
      add_text(*head + " to end");
      cut(MarkerEnd::to_marker, 0);
    } else if (const auto b = before_marker(i.words)) {
      // Worked to the end of the room the work leaves it (the marker less those stitches);
      // the stitches before the marker are the next part's first.
      add_text(b->first + " to end");
      cut(MarkerEnd::before_marker, b->second);
    } else {
      add_text(text.substr(i.from, i.to - i.from));
    }
  }
  parts.push_back({std::move(current), MarkerEnd::row_end, 0});
  return parts;
}

}  // namespace knitc::language

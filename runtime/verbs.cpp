// The pattern verbs after pattern{}: each binding checks its arguments and adds courses.
// The verb table at the end declares them for the bindings and the reference docs.
// One idea over 400 lines: every binding is the same few steps (read the Lua arguments,
// locate, hand the work to language::Work), and the table that declares them must sit
// beside them; the knitting itself is in language/work.cpp.
#include <algorithm>

#include "fields.hpp"
#include "language/knitspeak.hpp"
#include "language/spelling.hpp"
#include "script.hpp"

namespace knitc::runtime {

namespace {

constexpr std::size_t max_item_bytes = 100;  // a course{} item names one stitch

void need_pattern(lua_State* L, const char* verb) {
  if (!script_of(L).declared) fail(L, std::string(verb) + " comes before pattern{}; declare the pattern first");
}

int next_row(const Script& s) { return s.work.next_row(); }

void need_live(lua_State* L, const Script& s) {
  if (auto e = s.work.no_live_stitches()) fail(L, *e);
}

// Where a course is said: its own line in the pattern file, or the pattern's line that
// called the library function working it.
SourceLocation course_location(lua_State* L, const SourceLocation& where) {
  return where.file == sandbox_of(L).file ? where : pattern_location(L, where);
}

// What a course of `stitches` costs to work and keep, charged to the script first.
void charge_course(lua_State* L, std::size_t stitches, const SourceLocation& where) {
  charge(L, 200 + 5 * stitches);  // measured: about 30 ns a stitch, 6 instructions' time
  hold(L, script_of(L).work.cost(stitches, where));
}

// Adds a course in face view.
void add_course(lua_State* L, std::vector<Op> ops, const SourceLocation& at) {
  const SourceLocation where = course_location(L, at);
  charge_course(L, ops.size(), where);
  if (auto e = script_of(L).work.add(std::move(ops), where)) fail(L, *e);
}

// Works written text (already parsed) as the next row. `line` is where the course comes
// from; `located`: errors point at it too (a line inside a text block), not the caller.
void work_written(lua_State* L, const language::RowText& text, const std::string& source, const SourceLocation& line,
                  bool located = false) {
  Script& s = script_of(L);
  const SourceLocation where = course_location(L, line);
  charge_course(L, static_cast<std::size_t>(s.work.live()), where);
  if (auto e = s.work.work_text(text, source, where)) located ? fail_at(L, line, *e) : fail(L, *e);
}

language::RowText parse_written(lua_State* L, const std::string& text, const SourceLocation* at = nullptr) {
  charge(L, text.size() / 4 + 1);
  const Script& s = script_of(L);
  if (!s.glossary.empty()) charge(L, text.size() * s.glossary.size() / 16 + 1);
  auto parsed = language::parse_row(s.glossary.empty() ? text : language::with_glossary(text, s.glossary), s.yarn_ids);
  if (auto* e = std::get_if<language::TextError>(&parsed)) {
    const std::string m = "row " + std::to_string(next_row(script_of(L))) + " " + language::quote_row(text) + ": " + e->message;
    at ? fail_at(L, *at, m) : fail(L, m);
  }
  return std::get<language::RowText>(std::move(parsed));
}

// Where a text block passed to the running binding (chart [[...]], knitspeak [[...]])
// starts: the file and the line of its first line.
SourceLocation block_start(lua_State* L) {
  SourceLocation at{sandbox_of(L).file, caller_line(L)};
  lua_Debug ar;
  for (int level = 1; lua_getstack(L, level, &ar) != 0; ++level) {
    if (lua_getinfo(L, "Sl", &ar) != 0 && ar.currentline > 0) {
      const auto& sources = sandbox_of(L).sources;
      const auto it = ar.source[0] == '@' ? sources.find(ar.source + 1) : sources.end();
      if (it != sources.end()) at = {it->first, long_string_first_line(it->second, ar.currentline)};
      break;
    }
  }
  return at;
}

int cast_on_verb(lua_State* L) {
  need_pattern(L, "cast_on");
  Script& s = script_of(L);
  if (s.work.cast_on_line() != 0) fail(L, "cast_on was already called at line " + std::to_string(s.work.cast_on_line()));
  const int stitches = static_cast<int>(whole_number(L, 1, "cast_on's stitch count", 1, max_stitches));
  int yarn = s.work.yarn();
  if (!lua_isnoneornil(L, 2)) {
    if (lua_type(L, 2) != LUA_TSTRING) fail(L, "cast_on's yarn must be a declared yarn's name, e.g. cast_on(24, \"B\")");
    yarn = yarn_index(L, text_of(L, 2));
  }
  if (auto e = s.work.cast_on(stitches, yarn, caller_line(L))) fail(L, *e);
  return 0;
}

std::string text_argument(lua_State* L, int arg, const char* verb) {
  if (lua_type(L, arg) != LUA_TSTRING)
    fail(L, std::string(verb) + " takes the row's written instructions as a string, e.g. " + verb + "(\"k2, p2\"), not a " +
                luaL_typename(L, arg));
  return text_of(L, arg);
}

int row_verb(lua_State* L) {
  need_pattern(L, "row");
  const std::string text = text_argument(L, 1, "row");
  work_written(L, parse_written(L, text), text, caller_location(L));
  return 0;
}

int rows_verb(lua_State* L) {
  need_pattern(L, "rows");
  const long long count = whole_number(L, 1, "rows' count", 1, max_stitches);
  const std::string text = text_argument(L, 2, "rows");
  const auto parsed = parse_written(L, text);
  const SourceLocation line = caller_location(L);
  for (long long i = 0; i < count; ++i) work_written(L, parsed, text, line);
  return 0;
}

// course { k, k, p, p, rep = 6, yarn = "B" }: stitches in working order, as written
// instructions would list them; a table item { "k", yarn = "B" } works one in another yarn.
int course_verb(lua_State* L) {
  need_pattern(L, "course");
  Script& s = script_of(L);
  if (lua_type(L, 1) != LUA_TTABLE) fail(L, std::string("course takes a table, e.g. course { k, p, rep = 6 }, not a ") + luaL_typename(L, 1));
  only_known_fields(L, 1, "course{}", "course");
  const lua_Integer n = luaL_len(L, 1);
  if (n == 0) fail(L, "course{} lists no stitches; give some, e.g. course { k, p }");
  if (n < 0 || n > max_stitches)
    fail(L, "course{} lists " + std::to_string(n) + " stitches; a course lists at most " + std::to_string(max_stitches));
  std::string text;
  for (lua_Integer i = 1; i <= n; ++i) {
    lua_geti(L, 1, i);
    std::string item;
    charge(L, 20);
    if (lua_type(L, -1) == LUA_TSTRING) {
      item = text_of(L, -1);
    } else if (lua_type(L, -1) == LUA_TTABLE) {
      lua_geti(L, -1, 1);
      if (lua_type(L, -1) != LUA_TSTRING) fail(L, "course{} item " + std::to_string(i) + " must name its stitch first, e.g. { k, yarn = \"B\" }");
      item = text_of(L, -1);
      lua_pop(L, 1);
      const auto yarn = string_field(L, lua_gettop(L), "course{} item " + std::to_string(i), "yarn");
      if (yarn) {
        yarn_index(L, *yarn);
        item += " " + *yarn;
      }
    } else {
      fail(L, "course{} item " + std::to_string(i) + " is a " + luaL_typename(L, -1) +
                  "; give stitches such as k, p, k2tog or \"sl1 wyif\"");
    }
    if (item.size() > max_item_bytes)
      fail(L, "course{} item " + std::to_string(i) + " is " + std::to_string(item.size()) + " bytes long; give one stitch per item, such as k2tog");
    if (item.find_first_of(",;*()[]") != std::string::npos)
      fail(L, "course{} item " + std::to_string(i) + " is \"" + item + "\"; give one stitch per item");
    text += (text.empty() ? "" : ", ") + item;
    lua_pop(L, 1);
  }
  lua_getfield(L, 1, "rep");
  if (!lua_isnil(L, -1)) text = "(" + text + ") x" + std::to_string(whole_number(L, lua_gettop(L), "course{}.rep", static_cast<long long>(field("course", "rep").lo),
                                                                                   static_cast<long long>(field("course", "rep").hi)));
  lua_pop(L, 1);
  const int saved_yarn = s.work.yarn(), saved_plated = s.work.plated();
  if (const auto yarn = string_field(L, 1, "course{}", "yarn")) s.work.change_yarn(yarn_index(L, *yarn));
  work_written(L, parse_written(L, text), text, caller_location(L));
  s.work.change_yarn(saved_yarn, saved_plated);
  return 0;
}

// Reads a legend table { ["#"] = "k", ["*"] = { "p", yarn = "B" } } into the legend.
void read_legend(lua_State* L, int index, language::Legend& legend, const std::string& where) {
  for (const std::string& symbol : sorted_keys(L, index, where)) {
    lua_getfield(L, index, symbol.c_str());
    std::string name;
    int yarn = -1;
    if (lua_type(L, -1) == LUA_TSTRING) {
      name = text_of(L, -1);
    } else if (lua_type(L, -1) == LUA_TTABLE) {
      lua_geti(L, -1, 1);
      if (lua_type(L, -1) != LUA_TSTRING) fail(L, where + "[\"" + symbol + "\"] must name its stitch first, e.g. { \"k\", yarn = \"B\" }");
      name = text_of(L, -1);
      lua_pop(L, 1);
      if (const auto y = string_field(L, lua_gettop(L), where + "[\"" + symbol + "\"]", "yarn")) yarn = yarn_index(L, *y);
    } else {
      fail(L, where + "[\"" + symbol + "\"] must be a stitch name, not a " + luaL_typename(L, -1));
    }
    const auto reading = language::read_stitch(language::normalise(name));
    if (const auto* a = std::get_if<language::Ambiguous>(&reading)) fail(L, where + "[\"" + symbol + "\"]: " + language::ambiguous_message(*a));
    const auto* r = std::get_if<language::Reading>(&reading);
    if (!r || (r->count_written && r->count != 1))
      fail(L, where + "[\"" + symbol + "\"] is '" + name + "', " + (r ? "a stitch with a count; a symbol stands for one stitch" : "an unknown stitch; did you mean " + language::nearest_stitch_name(name) + "?"));
    const auto id = std::optional<StitchId>(r->stitch);
    if (!legend.set(symbol, {*id, yarn})) fail(L, where + " symbol \"" + symbol + "\" must be one or more characters without spaces");
    lua_pop(L, 1);
  }
}

int legend_verb(lua_State* L) {
  need_pattern(L, "legend");
  if (lua_type(L, 1) != LUA_TTABLE) fail(L, "legend takes a table, e.g. legend { [\"#\"] = { \"k\", yarn = \"B\" } }");
  language::Legend legend = script_of(L).legend;  // kept only if all of it reads
  read_legend(L, 1, legend, "legend");
  script_of(L).legend = std::move(legend);
  return 0;
}

// chart [[ ... ]] or chart { [[ ... ]], legend = {...}, rep = 2 }
int chart_verb(lua_State* L) {
  need_pattern(L, "chart");
  Script& s = script_of(L);
  language::Legend legend = s.legend;
  std::string text;
  auto repeats = static_cast<long long>(field("chart", "rep").value);
  if (lua_type(L, 1) == LUA_TSTRING) {
    text = text_of(L, 1);
  } else if (lua_type(L, 1) == LUA_TTABLE) {
    only_known_fields(L, 1, "chart{}", "chart");
    lua_geti(L, 1, 1);
    if (lua_type(L, -1) != LUA_TSTRING) fail(L, "chart{} needs the chart text first: chart { [[ ... ]], rep = 2 }");
    text = text_of(L, -1);
    lua_pop(L, 1);
    lua_getfield(L, 1, "legend");
    if (!lua_isnil(L, -1)) {
      if (!lua_istable(L, -1)) fail(L, "chart{}.legend must be a table of symbols");
      read_legend(L, lua_gettop(L), legend, "chart{}.legend");
    }
    lua_pop(L, 1);
    lua_getfield(L, 1, "rep");
    if (!lua_isnil(L, -1))
      repeats = whole_number(L, lua_gettop(L), "chart{}.rep", static_cast<long long>(field("chart", "rep").lo),
                             static_cast<long long>(field("chart", "rep").hi));
    lua_pop(L, 1);
  } else {
    fail(L, std::string("chart takes the chart as a string, chart [[ ... ]], or a table, not a ") + luaL_typename(L, 1));
  }
  // The chart text's first line: where its long string starts, in the chunk that called.
  const SourceLocation start = block_start(L);
  const int first_line = start.line;
  const std::string& chart_file = start.file;
  charge(L, text.size() / 4 + 1);
  auto parsed = language::parse_chart(text, legend);
  if (auto* e = std::get_if<language::ChartError>(&parsed)) fail_at(L, {chart_file, first_line + e->line}, e->message);
  const auto& rows = std::get<std::vector<language::ChartRow>>(parsed);
  if (rows.empty()) fail(L, "the chart has no rows");
  for (long long r = 0; r < repeats; ++r) {
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const int line = first_line + rows[i].line;
      need_live(L, s);
      const int width = language::consumed(rows[i].cells);
      const std::string name = "chart row " + std::to_string(i + 1) + " (row " + std::to_string(next_row(s)) + ")";
      const SourceLocation at{chart_file, line};
      auto located = [&](const std::string& m) { fail_at(L, at, m); };
      if (width == 0) located(name + " works no stitches; draw a stitch in each column");
      const int live = s.work.live();
      if (width > live || live % width != 0) {
        const int left = width > live ? live - width : live % width;
        located(name + " is " + std::to_string(width) + " stitches wide and does not repeat evenly across " +
                std::to_string(live) + " live stitches (" +
                (left > 0 ? std::to_string(left) + " left over" : std::to_string(-left) + " missing") +
                "); make the live count a multiple of " + std::to_string(width));
      }
      std::vector<Op> ops;
      ops.reserve(rows[i].cells.size() * static_cast<std::size_t>(live / width));
      // A chart is drawn as the face looks: its cells are face view already, on either side.
      if (s.work.side_of(next_row(s)) == Side::wrong) {
        for (const auto& cell : rows[i].cells) {
          if (!wrong_side_face(cell.stitch))
            located(name + " is a wrong-side row: " + std::string(stitch(cell.stitch).name) +
                    " has no wrong-side form in knitc; put it on a right-side (odd) row");
        }
      }
      for (int k = 0; k < live / width; ++k) {
        for (const auto& cell : rows[i].cells) ops.push_back({cell.stitch, cell.yarn < 0 ? s.work.yarn() : cell.yarn});
      }
      add_course(L, std::move(ops), at);
    }
  }
  return 0;
}

// knitspeak [[ Row 1 (RS): ... ]]: printed pattern text, each row worked as written
// instructions; errors point at the text's own line.
int knitspeak_verb(lua_State* L) {
  need_pattern(L, "knitspeak");
  Script& s = script_of(L);
  if (lua_type(L, 1) != LUA_TSTRING)
    fail(L, std::string("knitspeak takes the printed pattern as a string, knitspeak [[ Row 1: ... ]], not a ") + luaL_typename(L, 1));
  const std::string text = text_of(L, 1);
  const SourceLocation start = block_start(L);
  auto at = [&](int line) { return SourceLocation{start.file, start.line + line}; };
  charge(L, text.size() / 4 + 1);
  auto read = language::read_knitspeak(text, s.yarn_ids);
  if (auto* e = std::get_if<language::KnitspeakNote>(&read)) fail_at(L, at(e->line), e->message);
  const auto& block = std::get<language::Knitspeak>(read);
  for (const auto& skipped : block.skipped) warn(L, at(skipped.line), skipped.message);
  if (block.rows.empty()) fail(L, "the knitspeak text has no rows; write them as Row 1: ..., Row 2: ...");
  for (const auto& r : block.rows) {
    const SourceLocation where = at(r.line);
    std::string label = r.number > 0 ? "row " + std::to_string(r.number) + " of the text" : "this line";
    if (r.repeat) label = "the repeat of " + label;
    // A first row printed as a wrong-side row: the knitter turned the work first.
    const bool flat = s.work.pattern().knitting == Knitting::flat;
    if (s.work.pattern().courses.empty() && r.side == Side::wrong) s.work.start_on_wrong_side();
    if (r.side && flat && *r.side != s.work.side_of(next_row(s)))
      fail_at(L, where, label + " is printed as a " + (*r.side == Side::right ? "right" : "wrong") + "-side row but is row " +
                            std::to_string(next_row(s)) + " of the fabric, a " +
                            (*r.side == Side::right ? "wrong" : "right") + "-side row; check the rows before it");
    // An abbreviation the text defines in words knitc cannot read: say so, with its line.
    if (const auto* unread = language::unread_abbreviation_in(r.text, block.glossary);
        unread && language::parse_row(r.text, s.yarn_ids, false).index() != 0)
      fail_at(L, where, label + " uses '" + unread->abbreviation + "', which line " + std::to_string(at(unread->line).line) +
                            " defines as " + language::quote_row(unread->definition) +
                            "; knitc cannot read that working yet: write the row with stitches it knows (knitc reference "
                            "lists them)");
    work_written(L, parse_written(L, r.text, &where), r.text, where, true);
    if (r.stitches_after && *r.stitches_after != s.work.live())
      fail_at(L, where, label + " says it leaves " + std::to_string(*r.stitches_after) + " sts but its stitches leave " +
                            std::to_string(s.work.live()) + "; the text's count does not come out (check the row or the cast-on)");
  }
  return 0;
}

// stitch("C4Bp", "sl 2 to cn, hold in back, k2, p2 from cn"): an abbreviation of the
// pattern's own, for the rows, charts and knitspeak blocks that follow.
int stitch_verb(lua_State* L) {
  need_pattern(L, "stitch");
  Script& s = script_of(L);
  if (lua_type(L, 1) != LUA_TSTRING || lua_type(L, 2) != LUA_TSTRING)
    fail(L, "stitch takes the abbreviation and its working as two strings, e.g. stitch(\"C4Bp\", \"sl 2 to cn, hold in "
            "back, k2, p2 from cn\")");
  const std::string name = text_of(L, 1), working = text_of(L, 2);
  if (name.size() > language::longest_abbreviation || working.size() > language::longest_definition)
    fail(L, "stitch's abbreviation is at most " + std::to_string(language::longest_abbreviation) + " bytes and its working " +
                std::to_string(language::longest_definition));
  auto entry = language::read_glossary_line(name + ": " + working, caller_line(L));
  if (!entry || entry->abbreviation != name)
    fail(L, "'" + printable(name, 40) + "' is not an abbreviation knitc can declare: give letters, digits, '/', '-' or "
            "spaces, at most three words");
  if (entry->known) fail(L, "'" + name + "' is a stitch knitc knows already; declare a name of the pattern's own");
  if (!entry->means)
    fail(L, "knitc cannot read the working of '" + name + "' (" + language::quote_row(working) +
                "): give a stitch it knows (knitc reference lists them), a few of them (\"k2, p2\") or a cross in words "
                "(\"sl 2 to cn, hold in front, k2, k2 from cn\")");
  for (const auto& e : s.glossary)
    if (language::lower(e.abbreviation) == language::lower(name)) fail(L, "'" + name + "' is declared already at line " + std::to_string(e.line));
  if (s.glossary.size() >= language::max_glossary)
    fail(L, "a pattern declares at most " + std::to_string(language::max_glossary) + " stitches");
  // A chart may draw it too, when it stands for one stitch.
  if (const auto one = language::find_stitch(*entry->means); one && name.find(' ') == std::string::npos)
    s.legend.set(name, {*one, -1, false});
  s.glossary.push_back(std::move(*entry));
  return 0;
}

int yarn_verb(lua_State* L) {
  need_pattern(L, "yarn");
  if (lua_type(L, 1) != LUA_TSTRING) fail(L, "yarn takes a declared yarn's name, e.g. yarn \"B\"");
  const int yarn = yarn_index(L, text_of(L, 1));
  int plated = -1;
  if (!lua_isnoneornil(L, 2)) {
    if (lua_type(L, 2) != LUA_TSTRING) fail(L, "yarn's second yarn, knitted with the first, must be a declared yarn's name, e.g. yarn(\"A\", \"B\")");
    plated = yarn_index(L, text_of(L, 2));
    if (plated == yarn) fail(L, "yarn(\"" + text_of(L, 1) + "\", \"" + text_of(L, 2) + "\") plates a yarn with itself; name two different yarns, or one");
  }
  script_of(L).work.change_yarn(yarn, plated);
  return 0;
}

int bind_off_verb(lua_State* L) {
  need_pattern(L, "bind_off");
  if (auto e = script_of(L).work.bind_off(caller_line(L))) fail(L, *e);
  return 0;
}

int live_verb(lua_State* L) {
  lua_pushinteger(L, script_of(L).work.live());
  return 1;
}

int knitting_verb(lua_State* L) {
  need_pattern(L, "knitting");
  lua_pushstring(L, script_of(L).work.pattern().knitting == Knitting::flat ? "flat" : "round");
  return 1;
}

int row_number_verb(lua_State* L) {
  lua_pushinteger(L, next_row(script_of(L)));
  return 1;
}

// The one side rule, for library functions: Lua keeps no copy of it.
int right_side_verb(lua_State* L) {
  need_pattern(L, "right_side");
  const Script& s = script_of(L);
  const long long row = lua_isnoneornil(L, 1) ? next_row(s) : whole_number(L, 1, "right_side's row", 1, max_loops);
  lua_pushboolean(L, s.work.side_of(static_cast<int>(row)) == Side::right);
  return 1;
}

constexpr Verb verbs[] = {
    {"pattern", pattern_verb, "pattern { name = S, gauge = {...}, yarns = {...}, knitting = \"round\"|\"flat\", seed = N }",
     "Declares the pattern, once, before anything else. The gauge is stitches and rows per 10 cm, or loop_width and "
     "loop_height in mm (not both); each yarn has a diameter or a weight (not both). The fields are below.",
     "pattern { name = \"rib\", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = \"dk\", color = \"#8a1c2b\" } } }"},
    {"cast_on", cast_on_verb, "cast_on(n [, yarn])", "Casts on n stitches, in the given yarn or the first declared one.",
     "cast_on(24)"},
    {"row", row_verb, "row(text)",
     "Works one row of written instructions. The text repeats across the row until the live stitches are used; "
     "*...; rep from * [to end | to last N sts, ...] and (...) xN say repeats explicitly.",
     "row \"*k2, p2; rep from * to last 2 sts, k2\""},
    {"rows", rows_verb, "rows(n, text)", "Works n rows of the same written instructions.", "rows(6, \"k2, p2\")"},
    {"course", course_verb, "course { stitch, ..., rep = N, yarn = id }",
     "Works one row from a Lua list of stitches in working order (the globals k, p, yo, k2tog, ssk, cdd, sl, C4F, ... "
     "or any written name as a string); rep repeats the list N times, else it repeats to fill the row. "
     "An item { k, yarn = \"B\" } works that stitch in another yarn.",
     "course { k, k, p, p, rep = 6 }"},
    {"chart", chart_verb, "chart(text) or chart { text, legend = {...}, rep = N }",
     "Works the rows of a chart drawn as the face looks, the last line first (row 1). Each row repeats across the live "
     "stitches; rep repeats the whole chart upward. On wrong-side rows the knitter reads the chart from the left and "
     "works each symbol's wrong-side form; the face looks as drawn.",
     "chart [[\n  | | . .\n  | | . .\n]]"},
    {"knitspeak", knitspeak_verb, "knitspeak(text)",
     "Works a stitch pattern pasted as a book or Stitch Maps prints it: lines such as `Row 1 (RS): K1, *p1, k1; "
     "repeat from *.`, `Rows 2 and 4: Purl.`, `Rnds 3-5: Knit.`, `Rows 5-8: Repeat rows 1-4.`, `Repeat rows 3-6.` "
     "(once more, there), an unnumbered line of stitches, and a stated count `(14 sts)`, which is checked. Rows are "
     "worked in number order; a first row printed (WS) is worked from the wrong side. Lines that are not rows "
     "(headings, notes) are skipped with a warning; errors name the text's own line.",
     "knitspeak [[\n  Row 1 (RS): *K2, p2; rep from *.\n  Row 2: Knit the knit sts and purl the purl sts.\n]]"},
    {"stitch", stitch_verb, "stitch(abbreviation, working)",
     "Declares an abbreviation of the pattern's own, as its glossary prints it, for the rows, charts and knitspeak "
     "blocks that follow: the working is a stitch knitc knows, a few of them, or a cross in words (`sl 2 to cn, hold "
     "in back, k2, p2 from cn`). A working knitc cannot read is refused with the reason. A knitspeak block's own "
     "glossary lines (`C4Bp: ...`) are read the same way.",
     "stitch(\"C4Bp\", \"sl 2 to cn, hold in back, k2, p2 from cn\")"},
    {"legend", legend_verb, "legend { [symbol] = stitch | { stitch, yarn = id }, ... }",
     "Adds or changes chart symbols for the charts that follow.", "legend { [\"#\"] = { \"k\", yarn = \"B\" } }"},
    {"yarn", yarn_verb, "yarn(id [, plated])",
     "Changes to another declared yarn for the rows that follow: stripes. With a second yarn, both are knitted into every loop "
     "the first makes, the second on the loops' technical face (plating: a plated jersey shows the second yarn on its face and "
     "the first on its back).",
     "yarn \"B\"\nyarn(\"A\", \"B\")"},
    {"live", live_verb, "live()", "The number of live stitches on the needle now.", "local n = live()"},
    {"knitting", knitting_verb, "knitting()", "\"flat\" or \"round\", as pattern{} declared: for library functions.",
     "if knitting() == \"flat\" then rows(2, \"k\") end"},
    {"row_number", row_number_verb, "row_number()",
     "The number of the next row to be worked (1 for the first). Which side a row is worked from is right_side()'s "
     "to say: in flat knitting a first row printed (WS) makes the odd rows the wrong-side rows.",
     "local n = row_number()"},
    {"right_side", right_side_verb, "right_side([row])",
     "True when the next row (or row number `row` of the piece) is worked from the right side: every row in the "
     "round; in flat knitting the odd rows, or the even ones when row 1 was worked from the wrong side "
     "(knitspeak's `Row 1 (WS):`).",
     "if right_side() then row \"k\" else row \"p\" end"},
    {"bind_off", bind_off_verb, "bind_off()", "Binds off every live stitch; no rows may follow.", "bind_off()"},
    {"require", require_verb, "require(name)",
     "Loads a module of the pattern library: name.lua from the -I folders, the pattern's own lib/ folder, then "
     "knitc's patterns/lib. Dots in the name are folders. Each module runs once; require returns what it returns.",
     "local ribs = require \"ribs\""},
};

}  // namespace

std::span<const Verb> verb_table() { return verbs; }

int verb_entry(lua_State* L) {
  const Verb& verb = *static_cast<const Verb*>(lua_touserdata(L, lua_upvalueindex(1)));
  Script& s = script_of(L);
  // A verb reading its arguments can run the script's metamethods; one that called a
  // verb would change the pattern under the verb still reading it.
  if (s.running_verb != nullptr)
    fail(L, std::string(verb.name) + " was called while " + s.running_verb +
                " was still running (from a metamethod of its arguments); call the pattern's verbs from the script "
                "itself");
  charge(L, 300);  // a verb call, its checks and its undo mark
  // require runs a module, whose own lines call verbs: it does not hold the others off.
  const bool holds = verb.function != require_verb;
  struct Hold {
    Script& s;
    bool on;
    ~Hold() {
      if (on) s.running_verb = nullptr;
    }
  } hold_verbs{s, holds};
  if (holds) s.running_verb = verb.name;
  // All or nothing: a verb that fails (and is caught by pcall) leaves the work as it was.
  // require is not undone: the rows its module worked were the module's own verbs'.
  const language::Work::Mark mark = holds ? s.work.mark() : language::Work::Mark{};
  const std::size_t held = sandbox_of(L).host_bytes;
  try {
    try {
      return verb.function(L);
    } catch (const std::bad_alloc&) {  // the C++ side out of memory: a stop like the Lua side's
      stop(L, Stop::memory);
    } catch (const std::length_error&) {
      stop(L, Stop::memory);
    } catch (const std::exception& e) {  // never let a C++ exception cross Lua's frames
      fail(L, std::string("knitc could not work this verb: ") + e.what());
    }
  } catch (...) {  // a Lua error on its way out: undo, and let it go on
    if (holds) {
      s.work.restore(mark);
      sandbox_of(L).host_bytes = held;
    }
    throw;
  }
}

}  // namespace knitc::runtime

// The sandbox's string.find, match, gmatch, gsub and rep against Lua's own: the same
// results and the same error messages for thousands of generated patterns and subjects,
// and the patterns Lua's matcher takes forever on stopped by the budget.
#include <random>

#include <gtest/gtest.h>

#include "sandbox.hpp"

namespace knitc {
namespace {

// Runs `code` with (s, p, init) in L; its result, or the error's message.
std::string run(lua_State* L, const std::string& code, const std::string& s, const std::string& p, int init) {
  if (luaL_loadbufferx(L, code.data(), code.size(), "=probe", "t") != LUA_OK) return lua_tostring(L, -1);
  lua_pushlstring(L, s.data(), s.size());
  lua_pushlstring(L, p.data(), p.size());
  lua_pushinteger(L, init);
  if (lua_pcall(L, 3, 1, 0) != LUA_OK) {
    std::string e = lua_type(L, -1) == LUA_TSTRING ? lua_tostring(L, -1) : "(not a string)";
    lua_pop(L, 1);
    return "error: " + e;
  }
  std::size_t n = 0;
  const char* r = lua_tolstring(L, -1, &n);
  std::string out(r, n);
  lua_pop(L, 1);
  return out;
}

// Every way of calling the five functions on one subject and pattern, as one string.
const std::string probe = R"(
local s, p, init = ...
local out = {}
local function keep(ok, ...)
  out[#out + 1] = tostring(ok)
  for i = 1, select('#', ...) do out[#out + 1] = tostring((select(i, ...))) end
end
keep(pcall(string.find, s, p, init))
keep(pcall(string.find, s, p, init, true))
keep(pcall(string.match, s, p, init))
keep(pcall(string.gsub, s, p, "<%0>"))
keep(pcall(string.gsub, s, p, "%1-%%"))
keep(pcall(string.gsub, s, p, function(a, b) return b or a end))
keep(pcall(string.gsub, s, p, { a = "A", ["1"] = false }, 2))
keep(pcall(function()
  local r = {}
  for a, b in string.gmatch(s, p, init) do r[#r + 1] = tostring(a) .. "," .. tostring(b) end
  return table.concat(r, ";")
end))
keep(pcall(string.rep, s, init, p))
return table.concat(out, "|")
)";

struct States {
  runtime::SandboxState sandbox_state;
  lua_State* sandbox = nullptr;
  lua_State* plain = nullptr;
  States() {
    sandbox_state.file = "probe.lua";
    sandbox_state.limits.instructions = 1ull << 60;  // thousands of probes in one state
    sandbox_state.limits.seconds = 1e6;
    sandbox = runtime::open_sandbox(sandbox_state);
    plain = luaL_newstate();
    luaL_openlibs(plain);
  }
  ~States() {
    lua_close(sandbox);
    lua_close(plain);
  }
  void expect_same(const std::string& s, const std::string& p, int init) {
    const std::string ours = run(sandbox, probe, s, p, init);
    const std::string theirs = run(plain, probe, s, p, init);
    EXPECT_EQ(ours, theirs) << "subject \"" << s << "\", pattern \"" << p << "\", init " << init;
  }
};

TEST(LuaPatterns, MatchLuasOwnOnWrittenCases) {
  States states;
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"hello world", "o w"},        {"hello world", "^(h)(e)"},     {"hello", "l+"},
      {"hello", "l*"},               {"hello", "l-"},                {"hello", "l?l"},
      {"key = value", "(%w+)%s*=%s*(%w+)"}, {"THE (quick) fox", "%((%a+)%)"}, {"f(a(b)c)d", "%b()"},
      {"THE (quick) fox", "%f[%a]%a+"}, {"abc", "()b()"},            {"aaa", "(a)%1"},
      {"[]]", "[]]"},                {"a]b", "[^]]"},                {"a-b", "[a%-]+"},
      {"a.b", "%."},                 {"abc", "[a-"},                 {"abc", "%"},
      {"abc", "(()"},                {"abc", "%b"},                  {"abc", "%f"},
      {"abc", "%f[a"},               {"abc", "(a)%2"},               {"abc", "%0"},
      {"abc", "a)"},                 {"", ""},                       {"", "^$"},
      {"abc", "$"},                  {"a$c", "a$c"},                 {"abc", "^"},
      {"x^y", "^^"},                 {"abc", ".-$"},                 {"a\0b", "%z"},
      {std::string("a\0b", 3), "."}, {std::string("a\0b", 3), std::string("%z?\0", 4)}, {"caf\xc3\xa9", "[\x80-\xff]+"}, {"((a))", "%b()"},
      {"abc", "(a)(b)(c)(.?)(.?)(.?)(.?)(.?)(.?)(.?)(.?)(.?)(.?)(.?)(.?)(.?)(.?)(.?)(.?)(.?)(.?)(.?)(.?)(.?)(.?)(.?)(.?)(.?)(.?)(.?)(.?)(.?)(.?)"},
      {"hello world from Lua", "%a+"}, {"  trim  ", "^%s*(.-)%s*$"},   {"k2tog, p2", "(%a+)(%d*)"},
      {"abc", "[%a-z]"},             {"a-z", "[a-]"},                {"abc", "[]"},
      {"abc", "[^]"},                {"ab", "a*?"},                  {"aaa", "a-b"},
  };
  for (const auto& [s, p] : cases) {
    for (int init : {1, 2, 0, -1, -2, 10}) states.expect_same(s, p, init);
  }
}

// Patterns made of the language's pieces at random, on short subjects.
TEST(LuaPatterns, MatchLuasOwnOnGeneratedCases) {
  States states;
  std::mt19937 random(20261201);
  const std::vector<std::string> pieces = {
      "a", "b", "c", "(", ")", "()", ".", "%a", "%d", "%s", "%w", "%p", "%A", "%S", "%%", "%.", "[ab]", "[^a]",
      "[a-c]", "[%d%s]", "[]a]", "*", "+", "-", "?", "^", "$", "%1", "%2", "%b()", "%bab", "%f[%a]", "%f[%A]",
      "%", "[", "]", "%z", "%x", "1", " ", "[^%s]", "[.-]"};
  const std::string letters = "ab c()1.a]";
  for (int n = 0; n < 4000; ++n) {
    std::string p;
    const int length = static_cast<int>(random() % 7);
    for (int i = 0; i < length; ++i) p += pieces[random() % pieces.size()];
    std::string s;
    const int subject = static_cast<int>(random() % 10);
    for (int i = 0; i < subject; ++i) s += letters[random() % letters.size()];
    states.expect_same(s, p, static_cast<int>(random() % 5) - 1);
  }
}

// What Lua's own matcher backtracks on for hours stops at the budget, with the line.
TEST(LuaPatterns, BacktrackingStopsAtTheBudget) {
  runtime::RunOptions options;
  options.limits.instructions = 20'000'000;
  const std::string header =
      "pattern { gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = \"dk\" } } }\ncast_on(4)\n";
  for (const char* attack : {"local s = ('a'):rep(40) local _ = s:find(('a*'):rep(40) .. 'b')",
                             "local s = ('a'):rep(3000) local _ = s:gsub('.-.-.-.-b', '')",
                             "local s = ('a'):rep(2000) for _ in s:gmatch('.-.-.-b') do end",
                             "local s = ('a'):rep(2000) local _ = s:match('(.-)(.-)(.-)b')"}) {
    try {
      runtime::run_pattern(header + attack + "\nrows(2, 'k')\n", "t.lua", options);
      ADD_FAILURE() << attack << " ran to the end";
    } catch (const runtime::PatternError& e) {
      EXPECT_EQ(std::string(e.what()).rfind("t.lua:3: pattern ran too long (over 20 million", 0), 0u) << e.what();
    }
  }
}

}  // namespace
}  // namespace knitc

// require "name": the pattern library's modules, and nothing else of the file system.
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "script.hpp"

namespace knitc::runtime {

namespace {

constexpr const char* loaded_key = "knitc.loaded";  // registry table: name -> value
constexpr std::uintmax_t max_module_bytes = 1u << 20;

bool valid_module_name(const std::string& name) {
  if (name.empty() || name.size() > 100 || name.front() == '.' || name.back() == '.') return false;
  for (std::size_t i = 0; i < name.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(name[i]);
    if (c == '.' && name[i + 1] == '.') return false;
    if (!std::isalnum(c) && c != '_' && c != '.' && c != '-') return false;
  }
  return true;
}

}  // namespace

std::vector<std::string> module_folders(const Script& s) {
  std::vector<std::string> dirs = s.options.module_dirs;
  dirs.push_back((std::filesystem::path(s.directory) / "lib").string());
  dirs.push_back(KNITC_LIBRARY_DIR);
  return dirs;
}

int require_verb(lua_State* L) {
  Script& s = script_of(L);
  if (lua_type(L, 1) != LUA_TSTRING) fail(L, "require takes a module name, e.g. require \"cables\"");
  const std::string name = lua_tostring(L, 1);
  if (!valid_module_name(name))
    fail(L, "module name \"" + name + "\" must be letters, digits, _ and -, with dots between folders, e.g. \"lace.edgings\"");
  lua_getfield(L, LUA_REGISTRYINDEX, loaded_key);
  const int loaded = lua_gettop(L);
  lua_getfield(L, loaded, name.c_str());
  if (lua_toboolean(L, -1)) {
    if (lua_type(L, -1) == LUA_TLIGHTUSERDATA) fail(L, "module \"" + name + "\" requires itself, directly or through others");
    return 1;
  }
  lua_pop(L, 1);

  std::string relative = name;
  for (char& c : relative) {
    if (c == '.') c = '/';
  }
  relative += ".lua";
  std::string path, tried;
  for (const std::string& dir : module_folders(s)) {
    const auto candidate = std::filesystem::path(dir) / relative;
    std::error_code ec;
    if (std::filesystem::is_regular_file(candidate, ec)) {
      path = candidate.string();
      break;
    }
    tried += "\n\t" + candidate.string();
  }
  if (path.empty()) fail(L, "module \"" + name + "\" not found; looked for:" + tried);
  std::error_code ec;
  if (std::filesystem::file_size(path, ec) > max_module_bytes) fail(L, "module " + path + " is larger than 1 MiB");
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in) fail(L, "cannot read module " + path);
  const std::string source = text.str();
  sandbox_of(L).sources[path] = source;

  lua_pushlightuserdata(L, &s);  // "loading": catches a module that requires itself
  lua_setfield(L, loaded, name.c_str());
  const std::string chunk = "@" + path;
  int status = luaL_loadbufferx(L, source.data(), source.size(), chunk.c_str(), "t");
  if (status == LUA_OK) {
    lua_pushstring(L, name.c_str());
    status = lua_pcall(L, 1, 1, 0);
  }
  if (status != LUA_OK) {
    // Not loading any more: a later require reports the module's own error again.
    lua_pushnil(L);
    lua_setfield(L, loaded, name.c_str());
    lua_error(L);
  }
  if (lua_isnil(L, -1)) {
    lua_pop(L, 1);
    lua_pushboolean(L, 1);
  }
  lua_pushvalue(L, -1);
  lua_setfield(L, loaded, name.c_str());
  return 1;
}

void open_modules(lua_State* L) {
  lua_newtable(L);
  lua_setfield(L, LUA_REGISTRYINDEX, loaded_key);
}

}  // namespace knitc::runtime

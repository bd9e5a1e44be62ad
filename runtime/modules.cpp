// require "name": the pattern library's modules, and nothing else of the file system.
#include <cctype>
#include <filesystem>

#include "script.hpp"
#include "source_files.hpp"

namespace knitc::runtime {

namespace {

constexpr const char* loaded_key = "knitc.loaded";  // registry table: name -> value
constexpr std::size_t max_module_bytes = 1u << 20;

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

// A folder `require` searches, and the real folder its modules must lie in: a module
// file may be a symlink only to a file inside it. The pattern's lib/ is taken as it is
// found next to the pattern, never through a symlink of its own.
struct ModuleFolder {
  std::filesystem::path path;  // as searched (and named in messages)
  std::filesystem::path root;  // the real folder, symlinks resolved
};

std::vector<ModuleFolder> module_folders(const Script& s) {
  namespace fs = std::filesystem;
  std::vector<ModuleFolder> folders;
  auto real = [](const fs::path& p) {
    std::error_code ec;
    const fs::path r = fs::canonical(p, ec);
    return ec ? fs::path() : r;
  };
  for (const std::string& dir : s.options.module_dirs) folders.push_back({dir, real(dir)});
  const fs::path own_real = real(s.directory.empty() ? fs::path(".") : fs::path(s.directory));
  folders.push_back({fs::path(s.directory) / "lib", own_real.empty() ? fs::path() : own_real / "lib"});
  folders.push_back({KNITC_LIBRARY_DIR, real(KNITC_LIBRARY_DIR)});
  return folders;
}

// True if `file` (a real path) lies inside the folder `root`.
bool inside(const std::filesystem::path& root, const std::filesystem::path& file) {
  if (root.empty()) return false;
  auto r = root.begin(), f = file.begin();
  for (; r != root.end(); ++r, ++f) {
    if (f == file.end() || *r != *f) return false;
  }
  return f != file.end();
}

int require_verb(lua_State* L) {
  Script& s = script_of(L);
  if (lua_type(L, 1) != LUA_TSTRING) fail(L, "require takes a module name, e.g. require \"cables\"");
  const std::string name = text_of(L, 1);
  if (!valid_module_name(name))
    fail(L, "module name \"" + printable(name, 120) +
                "\" must be letters, digits, _ and -, with dots between folders, e.g. \"lace.edgings\"");
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
  for (const ModuleFolder& folder : module_folders(s)) {
    const auto candidate = folder.path / relative;
    std::error_code ec;
    if (std::filesystem::is_regular_file(candidate, ec)) {
      const auto real = std::filesystem::canonical(candidate, ec);
      if (ec || !inside(folder.root, real))
        fail(L, "module \"" + name + "\" is " + candidate.string() + ", a link to " + (ec ? std::string("nowhere") : real.string()) +
                    " outside " + folder.path.string() + "; knitc reads modules only from inside their folders");
      path = candidate.string();
      break;
    }
    tried += "\n\t" + candidate.string();
  }
  if (path.empty()) fail(L, "module \"" + name + "\" not found; looked for:" + tried);
  s.modules.push_back(path);
  std::string source;
  try {
    source = read_source(path, max_module_bytes);
  } catch (const SourceTooLarge&) {
    fail(L, "module " + path + " is larger than " + std::to_string(max_module_bytes >> 20) + " MiB");
  } catch (const FileError& e) {
    fail(L, std::string("module \"") + name + "\": " + e.what());
  }
  charge(L, source.size() / 4 + 1);
  hold(L, source.size());
  sandbox_of(L).sources[path] = source;

  lua_pushlightuserdata(L, &s);  // "loading": catches a module that requires itself
  lua_setfield(L, loaded, name.c_str());
  const std::string chunk = "@" + path;
  int status = luaL_loadbufferx(L, source.data(), source.size(), chunk.c_str(), "t");
  if (status == LUA_OK) {
    lua_pushstring(L, name.c_str());
    status = lua_pcall(L, 1, 1, 0);
  }
  raise_if_stopped(L, status);  // a limit the module reached ends the script
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

// The live view's own files: the page, its script and style, and the three.js modules it
// imports (from the pinned npm package the install step brings in). The one list the
// server serves from and the gallery copies from.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace knitc::view {

struct Asset {
  const char* address;  // as the page asks for it, e.g. "/three/three.module.js"
  std::string path;     // where it is read from
  // Its media type. Not one cpp-httplib compresses (it picks brotli at its slowest
  // setting: a megabyte of three.js took seconds a request, a garment's JSON 35 s).
  const char* type;
  bool module;          // an ES module (the gallery loads these from blob URLs)
};

std::span<const Asset> assets();

// The file at `path`, or false if it cannot be read.
bool read_asset(const std::string& path, std::string& out);

// The page (page/pattern.html) with its parts: `{{key}}` replaced by each value, as given
// (HTML: the caller escapes what it quotes).
std::string filled(std::string page, const std::vector<std::pair<std::string, std::string>>& values);

// `text` safe inside HTML's text and attributes.
std::string html_escaped(std::string_view text);

}  // namespace knitc::view

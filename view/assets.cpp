#include "view/assets.hpp"

#include <array>
#include <fstream>
#include <iterator>

namespace knitc::view {

std::span<const Asset> assets() {
  static const std::array<Asset, 11> files{{
      {"/view.css", KNITC_VIEW_PAGE_DIR "/view.css", "text/css", false},
      {"/gallery.js", KNITC_VIEW_PAGE_DIR "/gallery.js", "application/javascript; charset=utf-8", false},
      {"/three/three.core.js", KNITC_THREE_DIR "/build/three.core.js", "application/javascript; charset=utf-8", true},
      {"/three/three.module.js", KNITC_THREE_DIR "/build/three.module.js", "application/javascript; charset=utf-8", true},
      {"/three/addons/utils/BufferGeometryUtils.js", KNITC_THREE_DIR "/examples/jsm/utils/BufferGeometryUtils.js", "application/javascript; charset=utf-8", true},
      {"/three/addons/utils/SkeletonUtils.js", KNITC_THREE_DIR "/examples/jsm/utils/SkeletonUtils.js", "application/javascript; charset=utf-8", true},
      {"/three/addons/loaders/GLTFLoader.js", KNITC_THREE_DIR "/examples/jsm/loaders/GLTFLoader.js", "application/javascript; charset=utf-8", true},
      {"/three/addons/controls/OrbitControls.js", KNITC_THREE_DIR "/examples/jsm/controls/OrbitControls.js", "application/javascript; charset=utf-8", true},
      {"/three/addons/libs/meshopt_decoder.module.js", KNITC_THREE_DIR "/examples/jsm/libs/meshopt_decoder.module.js", "application/javascript; charset=utf-8",
       true},
      {"/view.js", KNITC_VIEW_PAGE_DIR "/view.js", "application/javascript; charset=utf-8", true},  // last: it imports the others
      {"/pattern.html", KNITC_VIEW_PAGE_DIR "/pattern.html", "text/html; charset=utf-8", false},
  }};
  return files;
}

bool read_asset(const std::string& path, std::string& out) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  out.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return !in.bad();
}

}  // namespace knitc::view

namespace knitc::view {

std::string filled(std::string page, const std::vector<std::pair<std::string, std::string>>& values) {
  for (const auto& [key, value] : values) {
    const std::string mark = "{{" + key + "}}";
    for (std::size_t at = page.find(mark); at != std::string::npos; at = page.find(mark, at + value.size()))
      page.replace(at, mark.size(), value);
  }
  return page;
}

std::string html_escaped(std::string_view text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace knitc::view

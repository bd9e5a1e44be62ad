#include "gallery.hpp"

#include <algorithm>
#include <filesystem>
#include <system_error>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "render.hpp"
#include "trace.hpp"
#include "view/assets.hpp"
#include "view/info.hpp"
#include "writers/writers.hpp"

namespace knitc::cli {

namespace {

namespace fs = std::filesystem;

std::string base64(const std::string& bytes) {
  static constexpr char digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const auto at = [&](std::size_t k) { return k < bytes.size() ? static_cast<unsigned char>(bytes[k]) : 0u; };
    const unsigned v = at(i) << 16 | at(i + 1) << 8 | at(i + 2);
    out += digits[v >> 18 & 63];
    out += digits[v >> 12 & 63];
    out += i + 1 < bytes.size() ? digits[v >> 6 & 63] : '=';
    out += i + 2 < bytes.size() ? digits[v & 63] : '=';
  }
  return out;
}

struct Built {
  std::string stem, name, figures;
};

}  // namespace

int gallery(const GalleryOptions& o) {
  std::error_code ec;
  if (!fs::is_directory(o.dir, ec)) {
    fmt::print(stderr, "knitc: {} is not a folder of patterns\n", runtime::printable(o.dir, 500));
    return 2;
  }
  std::vector<fs::path> patterns;
  for (const auto& entry : fs::directory_iterator(o.dir, ec))
    if (entry.is_regular_file() && entry.path().extension() == ".lua") patterns.push_back(entry.path());
  std::sort(patterns.begin(), patterns.end());
  if (patterns.empty()) {
    fmt::print(stderr, "knitc: {} holds no pattern (*.lua)\n", runtime::printable(o.dir, 500));
    return 2;
  }

  // The site's own files: three.js and the view as strings a page turns into modules
  // (gallery.js), the style, the page template.
  std::vector<writers::OutputFile> files;
  nlohmann::ordered_json modules = nlohmann::ordered_json::object();
  std::string page_template;
  for (const view::Asset& asset : view::assets()) {
    std::string text;
    if (!view::read_asset(asset.path, text)) {
      fmt::print(stderr, "knitc: cannot read {}; run ./scripts/install-deps\n", asset.path);
      return 3;
    }
    const std::string address = asset.address;
    if (asset.module) modules[address] = std::move(text);
    else if (address == "/pattern.html") page_template = std::move(text);
    else files.push_back(writers::text_file((fs::path(o.site) / "assets" / address.substr(1)).string(), std::move(text)));
  }
  files.push_back(writers::text_file((fs::path(o.site) / "assets/modules.js").string(), "window.knitcModules = " + modules.dump() + ";\n"));

  std::vector<Built> built;
  int failed = 0;
  for (const fs::path& path : patterns) {
    const std::string stem = path.stem().string();
    try {
      const runtime::RunResult run = runtime::run_pattern_file(path.string(), o.run);
      const Fabric fabric = compile(run.pattern, o.compile);
      const std::string glb = writers::glb(fabric.mesh, "knitc " KNITC_VERSION, {true, true, o.compile.threads});
      const std::string info = view::fabric_info(run.pattern, fabric);
      render::TraceOptions thumbnail;  // lit like a photograph, as knitc render draws by default
      thumbnail.width = 480;
      thumbnail.height = 360;
      thumbnail.threads = o.compile.threads;
      files.push_back(
          writers::text_file((fs::path(o.site) / (stem + ".png")).string(), render::traced_png(fabric.mesh, thumbnail)));
      files.push_back(writers::text_file((fs::path(o.site) / (stem + ".fabric.js")).string(),
                                         "window.knitcStatic = {\"glb\": \"" + base64(glb) + "\", \"info\": " + info + "};\n"));
      std::string source;
      view::read_asset(path.string(), source);
      files.push_back(writers::text_file(
          (fs::path(o.site) / (stem + ".html")).string(),
          view::filled(page_template, {{"title", view::html_escaped(run.pattern.name)},
                                       {"head", "<link rel=\"stylesheet\" href=\"assets/view.css\">"},
                                       {"home", "<a id=\"home\" href=\"index.html\">&larr; the library</a>"},
                                       {"source", "<pre id=\"source\">" + view::html_escaped(source) + "</pre>"},
                                       {"scripts", "<script src=\"" + view::html_escaped(stem + ".fabric.js") +
                                                       "\"></script>\n<script src=\"assets/modules.js\"></script>\n"
                                                       "<script src=\"assets/gallery.js\"></script>"}})));
      const auto figures = nlohmann::json::parse(info)["figures"];
      built.push_back({stem, run.pattern.name,
                       fmt::format("{:.1f} × {:.1f} cm, {} loops", figures["width_cm"].get<double>(), figures["height_cm"].get<double>(),
                                   figures["loops"].get<std::size_t>())});
      if (!o.quiet) fmt::print(stderr, "knitc: {}\n", runtime::printable(path.string(), 500));
    } catch (const runtime::PatternError& e) {
      fmt::print(stderr, "{}\n", e.what());
      ++failed;
    } catch (const runtime::FileError& e) {
      fmt::print(stderr, "knitc: {}\n", e.what());
      ++failed;
    } catch (const CompileError& e) {
      fmt::print(stderr, "{}\n", runtime::printable(e.what(), 4000));
      ++failed;
    }
  }
  std::string cards;
  for (const Built& b : built)
    cards += "<a class=\"card\" href=\"" + view::html_escaped(b.stem) + ".html\"><img src=\"" + view::html_escaped(b.stem) + ".png\" alt=\"" + view::html_escaped(b.name) +
             "\"><b>" + view::html_escaped(b.name) + "</b><span>" + view::html_escaped(b.figures) + "</span></a>\n";
  files.push_back(writers::text_file(
      (fs::path(o.site) / "index.html").string(),
      "<!doctype html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>knitc gallery</title>\n<style>\n"
      "body { font: 14px/1.4 system-ui, sans-serif; margin: 16px; background: #f4f1ec; color: #222; }\n"
      ".cards { display: grid; grid-template-columns: repeat(auto-fill, minmax(240px, 1fr)); gap: 12px; }\n"
      ".card { display: flex; flex-direction: column; background: #fff; border: 1px solid #ddd; padding: 8px; color: inherit; "
      "text-decoration: none; }\n.card img { width: 100%; }\n.card span { color: #777; font-size: 12px; }\n</style>\n</head>\n<body>\n"
      "<h1>" + view::html_escaped(fs::path(o.dir).filename().string()) + "</h1>\n<div class=\"cards\">\n" + cards + "</div>\n</body>\n</html>\n"));

  fs::create_directories(fs::path(o.site) / "assets", ec);
  if (ec) {
    fmt::print(stderr, "knitc: cannot make {}: {}\n", runtime::printable(o.site, 500), ec.message());
    return 3;
  }
  try {
    writers::write_files(files);
  } catch (const writers::OutputError& e) {
    fmt::print(stderr, "knitc: {}\n", e.what());
    return 3;
  }
  if (!o.quiet) fmt::print(stderr, "knitc: wrote {} pages to {}\n", built.size(), runtime::printable(o.site, 500));
  return failed > 0 ? 1 : 0;
}

}  // namespace knitc::cli

#include "sources.hpp"

#include <filesystem>
#include <fstream>

#include "knitout.hpp"
#include "source_files.hpp"

namespace knitc::cli {

bool is_knitout(const std::string& path) {
  const std::string ext = std::filesystem::path(path).extension().string();
  if (ext == ".lua") return false;
  if (ext == ".k" || ext == ".knitout") return true;
  std::ifstream in(path, std::ios::binary);
  char first[10] = {};
  in.read(first, sizeof first);
  return knitout::looks_like_knitout(path, std::string_view(first, static_cast<std::size_t>(in.gcount())));
}

runtime::RunResult read_pattern(const std::string& path, const runtime::PrintedOptions& printed, const runtime::RunOptions& run) {
  if (is_knitout(path)) {
    std::string text;
    try {
      text = runtime::read_source(path, max_knitout_bytes);
    } catch (const runtime::SourceTooLarge& e) {
      throw runtime::PatternError(e.what());
    }
    try {
      knitout::Imported imported = knitout::import_text(text, path);
      return {std::move(imported.pattern), std::move(imported.warnings), {path}};
    } catch (const knitout::KnitoutError& e) {
      throw runtime::PatternError(e.what(), {}, {path});
    }
  }
  return runtime::is_printed_pattern(path) ? runtime::run_printed_file(path, printed, run) : runtime::run_pattern_file(path, run);
}

}  // namespace knitc::cli

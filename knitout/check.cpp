#include "knitout.hpp"

namespace knitc::knitout {

std::vector<std::string> check_program(std::string_view text, const std::string& file, const Profile& profile, Imported* imported) {
  std::vector<std::string> problems;
  try {
    const Program program = parse(text, file);
    Imported in = import_program(program, profile);
    for (const std::string& w : in.warnings)
      if (w.find("drawn approximately") != std::string::npos || w.find("cannot run down") != std::string::npos ||
          w.find("more courses drawn") != std::string::npos)
        problems.push_back(w);
    if (imported) *imported = std::move(in);
  } catch (const KnitoutError& e) {
    problems.push_back(e.what());
  }
  return problems;
}

}  // namespace knitc::knitout

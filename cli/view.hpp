// knitc view: compiles a pattern, serves it to a browser on 127.0.0.1, and rebuilds it
// whenever the pattern or a module it requires changes on disk (docs/view.md).
#pragma once

#include <string>

#include "compile.hpp"
#include "runtime.hpp"

namespace knitc::cli {

struct ViewOptions {
  std::string pattern;
  runtime::RunOptions run;
  runtime::PrintedOptions printed;
  CompileOptions compile;
  int port = 0;       // 0: a free port
  bool open = true;   // open the page in a browser where there is one
  bool quiet = false;
};

// Serves until SIGINT, SIGTERM or SIGHUP; returns the exit code (0 when stopped, 2 when
// it cannot listen). Writes no file.
int view(const ViewOptions& options);

}  // namespace knitc::cli

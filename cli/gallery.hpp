// knitc gallery: a pattern library as a static site, readable from disk or any static
// host: an index with a thumbnail per pattern, and a page per pattern with its 3D view,
// chart, figures and source (docs/view.md).
#pragma once

#include <string>

#include "compile.hpp"
#include "runtime.hpp"

namespace knitc::cli {

struct GalleryOptions {
  std::string dir;   // the patterns: every *.lua directly in it
  std::string site;  // the folder the site is written to
  runtime::RunOptions run;
  CompileOptions compile;
  bool quiet = false;
};

// Writes the site; returns 0, 1 if a pattern failed (the others are written; its message
// printed), 2 on misuse, 3 if the site cannot be written.
int gallery(const GalleryOptions& options);

}  // namespace knitc::cli

// knitc bench: the whole job on a jersey swatch, timed stage by stage.
#pragma once

#include "compile.hpp"

namespace knitc::cli {

// Compiles a wales x courses jersey (the default pattern's gauge) at `options`, writes
// its .glb to a temporary file, and prints one line of figures: loops, triangles, output
// bytes, the time of each stage, loops and triangles per second, the ratio of mesh
// generation to a memcpy of the output's bytes timed in the same run, and peak memory.
// Returns the process exit code.
// `flat`: jersey knitted flat and bound off (a garment piece: relaxed by its repeat, and
// instanced past the size written flat), else in the round (the earlier tables').
int bench(int wales, int courses, const CompileOptions& options, bool header, bool flat = false);

}  // namespace knitc::cli

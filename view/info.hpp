// What the live view's page shows beside the 3D fabric, as JSON: the chart (a cell per
// stitch, as `knitc chart` draws it), every loop with the stitch, row and script line that
// made it and a few of its centreline points (to point at it and draw it), and the
// figures a designer asks next (size, gauge, yarn per colour).
#pragma once

#include <string>

#include "compile.hpp"

namespace knitc::view {

// The page's JSON for `fabric`, compiled from `pattern`. Loop points in mm, as the mesh.
std::string fabric_info(const Pattern& pattern, const Fabric& fabric);

}  // namespace knitc::view

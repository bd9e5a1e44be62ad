// knitc's --stats: what a fabric is made of and how it measures, on standard error.
#pragma once

#include "compile.hpp"

// Counts, bounds, the yarns' sizes and lengths, clearance, loop shape, and the
// relaxation's figures; relax_seconds is its wall time.
void print_stats(const knitc::Pattern& pattern, const knitc::Fabric& fabric, double relax_seconds);

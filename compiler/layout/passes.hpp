// The passes of lay_out that have files of their own; layout.cpp calls them in order.
// Internal to layout/.
#pragma once

#include <array>
#include <vector>

#include "knit_graph/knit_graph.hpp"
#include "layout/layout.hpp"
#include "pattern.hpp"

namespace knitc::layout {

// How much of a shift a parent's head takes, per point: 1 over the needle loop (P6..P10),
// 0 at the sinker loops. (A tuck's and a bind-off's templates are shaped by it too.)
inline constexpr std::array<double, loop_points> head_weights = {0.0, 0.0, 0.1, 0.3, 0.55, 0.8, 1.0, 1.0, 1.0,
                                                                 1.0, 1.0, 0.8, 0.55, 0.3, 0.1, 0.0, 0.0};

// templates.cpp
// How each tuck lies against the loop it is held with, per loop (TuckLie bits in
// templates.cpp; 0 for every loop but a tuck). parents: every loop's, the bind-off's too.
std::vector<char> tuck_lies(const Layout& out, const knit_graph::Graph& graph, const std::vector<std::vector<int>>& parents);
// Every loop at its needle position by its stitch's template. tucks: from tuck_lies.
void place_templates(Layout& out, const Pattern& pattern, const std::vector<char>& tucks);

// pull_through.cpp
// Each loop pulled through its parents. parents: every loop's, the bind-off's too.
void pull_through(Layout& out, const Pattern& pattern, const std::vector<std::vector<int>>& parents);

}  // namespace knitc::layout

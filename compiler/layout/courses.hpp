// The courses of the layout, for its passes (layout.cpp). Internal to layout/: the stages
// after it read the courses through layout.hpp's accessors.
#pragma once

#include "knit_graph/knit_graph.hpp"
#include "layout/layout.hpp"

namespace knitc::layout {

// The courses: their needle positions (Layout::needle, slot_x, needle_widths, layers,
// heights), where each starts (origin_x: flat work's plain loops over their parents),
// which way each is worked; no loops yet. bind_off: a course after the graph's for the
// pattern's bind-off.
Layout frame_courses(const Pattern& pattern, const knit_graph::Graph& graph, bool bind_off);

// x of a needle position's centre in its course, mm.
double centre_x(const Layout& out, int course, int slot);

// A loop's width, mm: W, its share of a cluster's, or its needle position's where a
// machine's needles set the course's widths.
double width_of(const Layout& out, const Loop& l);

}  // namespace knitc::layout

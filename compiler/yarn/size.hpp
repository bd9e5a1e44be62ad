// A yarn's size from what a designer gives: a standard weight, wraps per inch, tex, or a
// diameter. Every yarn has two diameters (docs/yarn.md, "Size"):
//   - the free diameter: the loose, visible width of the yarn, which wraps per inch
//     measure; the tube is drawn at it;
//   - the core diameter: the compact fibre mass at the yarn's centre, which no squeeze
//     between yarns reduces. Between core and surface the yarn compresses.
// The rules for both live here alone; the language reads the yarn's fields and calls them.
#pragma once

#include <optional>
#include <span>
#include <string_view>

namespace knitc::yarn {

struct Size {
  double free_diameter = 0.0;  // mm, > core_diameter
  double core_diameter = 0.0;  // mm, > 0
};

// Wrapping flattens the yarn, so 25.4 / WPI overstates its round free width: the free
// diameter is this fraction of it.
inline constexpr double wraps_flattening = 0.85;
// Wraps packed to refusal give about twice the knitters' WPI, and fibre density puts the
// compact core at 1/2 to 1/2.5 of 25.4 / WPI: the middle, 1/2.25.
inline constexpr double wraps_per_core = 2.25;
// The free diameter over the core's when only one of them is known: 0.85 x 2.25.
inline constexpr double free_per_core = wraps_flattening * wraps_per_core;
// The fraction of a compact core's cross-section that is fibre: spun yarns pack 0.4 to
// 0.6; 0.45 puts the cores of typical labels (fingering 250 tex at 16 WPI to bulky 830
// tex at 8 WPI) within 8% of the WPI rule's (tests/yarn_size_test.cpp).
inline constexpr double core_packing = 0.45;

// A standard yarn weight (Craft Yarn Council) at the middle of its wraps-per-inch range,
// and the length per 100 g typical of its labels.
struct Weight {
  std::string_view name;
  std::string_view aliases;  // '|'-separated
  double wpi = 0.0;
  double metres_per_100g = 0.0;
};
std::span<const Weight> weights();
// The weight a name or alias spells; `name` already in lower case.
const Weight* find_weight(std::string_view name);

// A fibre's density, for the core of a yarn given by tex.
struct Fibre {
  std::string_view name;
  double density = 0.0;  // g/cm³
};
std::span<const Fibre> fibres();
const Fibre* find_fibre(std::string_view name);  // exact name, lower case
inline constexpr std::string_view default_fibre = "wool";

// wpi > 0: free = 0.85 x 25.4 / wpi, core = 25.4 / (2.25 wpi).
Size from_wpi(double wpi);
// tex > 0 (grams per km), density > 0 (g/cm³): the core holds the fibre at core_packing;
// the free diameter follows at free_per_core.
Size from_tex(double tex, double density);
// free_diameter > 0 (mm): the core at 1 / free_per_core of it.
Size from_free_diameter(double free_diameter);
// core_diameter > 0 (mm): the free diameter at free_per_core times it.
Size from_core_diameter(double core_diameter);
// Grams per metre of a yarn whose core (mm, > 0) holds a fibre of `density` (g/cm³, > 0)
// at core_packing: from_tex's rule read the other way (g/m = tex / 1000).
double grams_per_metre(double core_diameter, double density);

}  // namespace knitc::yarn

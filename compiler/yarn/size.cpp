#include "yarn/size.hpp"

#include <array>
#include <cassert>
#include <cmath>
#include <numbers>

namespace knitc::yarn {

namespace {

// Lengths per 100 g: the middle of what labels of each weight give (Craft Yarn Council's
// yardage ranges, in metres).
constexpr std::array<Weight, 8> weight_table{{
    {"lace", "", 35.0, 800.0},
    {"super fine", "fingering|sock", 22.0, 400.0},
    {"fine", "sport", 15.0, 300.0},
    {"light", "dk", 13.0, 230.0},
    {"medium", "worsted|aran", 10.5, 180.0},
    {"bulky", "chunky", 7.5, 120.0},
    {"super bulky", "", 5.5, 80.0},
    {"jumbo", "", 4.0, 40.0},
}};

// Densities of the dry fibres (Morton and Hearle, Physical Properties of Textile Fibres).
constexpr std::array<Fibre, 11> fibre_table{{
    {"wool", 1.31},
    {"cotton", 1.52},
    {"linen", 1.50},
    {"silk", 1.34},
    {"viscose", 1.52},
    {"acrylic", 1.17},
    {"polyester", 1.38},
    {"nylon", 1.14},
    {"mohair", 1.31},  // animal hair: keratin, as wool
    {"alpaca", 1.31},
    {"cashmere", 1.31},
}};

bool spells(const Weight& w, std::string_view name) {
  if (w.name == name) return true;
  std::string_view rest = w.aliases;
  while (!rest.empty()) {
    const auto bar = rest.find('|');
    if (rest.substr(0, bar) == name) return true;
    rest = bar == std::string_view::npos ? std::string_view{} : rest.substr(bar + 1);
  }
  return false;
}

}  // namespace

std::span<const Weight> weights() { return weight_table; }

const Weight* find_weight(std::string_view name) {
  for (const Weight& w : weight_table) {
    if (spells(w, name)) return &w;
  }
  return nullptr;
}

std::span<const Fibre> fibres() { return fibre_table; }

const Fibre* find_fibre(std::string_view name) {
  for (const Fibre& f : fibre_table) {
    if (f.name == name) return &f;
  }
  return nullptr;
}

Size from_wpi(double wpi) {
  assert(wpi > 0.0);
  return {wraps_flattening * 25.4 / wpi, 25.4 / (wraps_per_core * wpi)};
}

Size from_tex(double tex, double density) {
  assert(tex > 0.0 && density > 0.0);
  // tex g/km is tex * 1e-6 g/mm; density g/cm³ is density * 1e-3 g/mm³: the fibre's
  // section is tex / (1000 density) mm², the core's that over the packing.
  const double fibre_area = tex / (1000.0 * density);
  const double core = std::sqrt(4.0 * fibre_area / (std::numbers::pi * core_packing));
  return from_core_diameter(core);
}

double grams_per_metre(double core_diameter, double density) {
  assert(core_diameter > 0.0 && density > 0.0);
  // The fibre's section in mm² times a metre is that many cm³.
  return density * core_packing * std::numbers::pi * 0.25 * core_diameter * core_diameter;
}

Size from_free_diameter(double free_diameter) {
  assert(free_diameter > 0.0);
  return {free_diameter, free_diameter / free_per_core};
}

Size from_core_diameter(double core_diameter) {
  assert(core_diameter > 0.0);
  return {core_diameter * free_per_core, core_diameter};
}

}  // namespace knitc::yarn

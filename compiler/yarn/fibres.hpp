// A spun yarn's fibres, after Zhao, Luan and Bala, "Fitting Procedural Yarn Models for
// Realistic Cloth Rendering" (SIGGRAPH 2016): plies twisted about the yarn's centreline;
// in each ply, fibres twisted about the ply's centre at a radius drawn from a density over
// the ply's cross-section, each migrating in and out as it turns; and flyaways, fibres that
// leave the body: loops (a fibre bulging out and back) and hairs (a fibre's free end). The
// model is written from the paper's description; its presets are set per fibre from the
// fibres' known diameters and by eye, not fitted to measurements (docs/yarn.md, "Fibres").
#pragma once

#include <string_view>

namespace knitc::yarn {

struct FibreModel {
  int plies = 2;                // plies twisted together (a yarn declared plied gives its own)
  double ply_twist = 15.0;      // the plies' turns per 10 cm (S; a plied yarn's own direction wins)
  int fibres_per_ply = 48;      // fibres drawn in each ply (a real ply holds hundreds)
  double fibre_diameter = 0.022;  // mm
  double fibre_twist = 25.0;    // the fibres' turns per 10 cm about their ply's centre, against the ply twist
  // Where fibres sit across the ply (radius R in [0, 1] of the ply's): density
  // (1 - 2 spread) ((e - e^R) / (e - 1))^packing + spread, Zhao et al.'s eq. 2.
  double packing = 0.4;  // > 0: higher crowds the fibres toward the ply's middle
  double spread = 0.1;   // in [0, 0.5): the density's floor, out to the ply's edge
  // Migration: a fibre's radius swings between `migration` x R and R, once every
  // `migration_period` turns about the ply.
  double migration = 0.3;         // in [0, 1]
  double migration_period = 2.0;  // turns, > 0
  double hairs = 6.0;             // hair flyaways per cm of yarn
  double hair_length = 2.0;       // mm along the yarn a hair spans
  double loops = 2.0;             // loop flyaways per cm of yarn
  double halo = 0.6;              // how far flyaways reach beyond the yarn's surface, in yarn radii
  bool operator==(const FibreModel&) const = default;
};

// The preset for a fibre name (yarn::fibres()), lower case; wool's for a name without one.
FibreModel fibre_preset(std::string_view fibre);

}  // namespace knitc::yarn

#include "yarn/fibres.hpp"

#include <array>
#include <utility>

namespace knitc::yarn {

namespace {

// plies, ply twist, fibres a ply, fibre diameter, fibre twist, packing, spread, migration,
// migration period, hairs, hair length, loops, halo. Diameters: wool 18-25 um (a knitting
// wool's), cotton 12-20, silk 10-13, acrylic 15-20, mohair 25-40, alpaca 20-30. Twist: silk
// and mohair are spun soft; cotton hard. Hairiness: cotton and silk are smooth, wool and
// alpaca fuzzy, mohair's long hairs are its halo.
constexpr std::array<std::pair<std::string_view, FibreModel>, 11> presets{{
    {"wool", {2, 15.0, 48, 0.022, 25.0, 0.4, 0.10, 0.30, 2.0, 6.0, 2.0, 2.0, 0.6}},
    {"cotton", {3, 20.0, 40, 0.016, 40.0, 0.6, 0.05, 0.35, 2.0, 2.0, 1.0, 1.0, 0.3}},
    {"linen", {2, 15.0, 36, 0.020, 30.0, 0.8, 0.05, 0.50, 3.0, 2.0, 1.5, 0.5, 0.3}},
    {"silk", {2, 10.0, 60, 0.012, 15.0, 1.0, 0.02, 0.60, 3.0, 1.0, 0.8, 0.5, 0.2}},
    {"viscose", {2, 12.0, 56, 0.014, 20.0, 0.8, 0.03, 0.50, 3.0, 1.0, 0.8, 0.5, 0.2}},
    {"acrylic", {2, 15.0, 48, 0.018, 25.0, 0.5, 0.08, 0.30, 2.0, 4.0, 1.5, 1.5, 0.4}},
    {"polyester", {2, 15.0, 56, 0.016, 25.0, 0.7, 0.05, 0.40, 2.0, 2.0, 1.0, 1.0, 0.3}},
    {"nylon", {2, 15.0, 56, 0.016, 25.0, 0.7, 0.05, 0.40, 2.0, 2.0, 1.0, 1.0, 0.3}},
    {"mohair", {2, 12.0, 32, 0.032, 15.0, 0.3, 0.10, 0.30, 2.0, 120.0, 6.0, 4.0, 3.0}},
    {"alpaca", {2, 12.0, 40, 0.026, 18.0, 0.4, 0.10, 0.30, 2.0, 14.0, 3.5, 3.0, 1.2}},
    {"cashmere", {2, 12.0, 48, 0.016, 18.0, 0.4, 0.10, 0.30, 2.0, 10.0, 2.5, 2.0, 0.8}},
}};

}  // namespace

FibreModel fibre_preset(std::string_view fibre) {
  for (const auto& [name, model] : presets)
    if (name == fibre) return model;
  return presets[0].second;
}

}  // namespace knitc::yarn

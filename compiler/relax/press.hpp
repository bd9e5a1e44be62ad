// Pressing: where the relaxed yarns press on each other, each yarn's section flattens,
// an ellipse across the contact normal with the round section's area (issue 16). From
// the relaxed points alone, so it holds for whatever the sweeps left. Internal to the
// relaxation's output: relax() fills yarn_paths::Piece::pressed.
#pragma once

#include <cstdint>
#include <vector>

#include "yarn/size.hpp"
#include "yarn_paths/yarn_paths.hpp"

namespace knitc::relax {

// No section flattens past this minor / major (spun yarns' sections run about 0.6 to 0.9
// where they cross; Kawabata's worsted loses 31% of its height at 10 gf).
inline constexpr double flattest_aspect = 0.6;

// Fills every piece's `pressed`, a vector per data point: along the direction the yarn is
// pressed from (across the yarn), of length 1 - aspect (0: round). A point's aspect makes
// its minor radius, f sqrt(aspect), what its free radius f keeps of the two yarns' free
// surfaces' overlap there, shared as their shells' thicknesses (f - core): the visible
// surfaces meet instead of passing into each other. Then smoothed along the yarn (two
// passes of 1-2-1), so the section varies smoothly. Contacts are as the relaxation's:
// other pieces, or the same one more than 1.8 free diameters along it. sizes: per
// Pattern::yarns; threads >= 1, the result the same for any count. Linear in the points.
// same_as: empty, or per point (the pieces' points in order) the point whose surroundings
// are this one's moved (a tiled interior's, Relaxed::same_as): only those equal to their
// own index are pressed, the rest take their pressing.
void press(std::vector<yarn_paths::Piece>& pieces, const std::vector<yarn::Size>& sizes, int threads,
           const std::vector<std::uint32_t>& same_as = {});

}  // namespace knitc::relax

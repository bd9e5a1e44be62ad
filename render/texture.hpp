// A material's maps read at a point of the surface, for the traced preview: bilinear
// filtering, repeated both ways, as a glTF viewer's sampler does (no mipmaps: the tracer's
// many samples a pixel average the texels a pixel covers).
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "mesh/mesh.hpp"

namespace knitc::render {

// The image's channels at texture coordinate `st` (s across, t down from the top row),
// each in [0, 1] as stored; a grey image gives its value in all three.
glm::vec3 texel(const mesh::Image& image, glm::vec2 st);

// An sRGB-encoded colour (a colour map's) as linear RGB.
glm::vec3 linear_from_srgb(glm::vec3 srgb);

}  // namespace knitc::render

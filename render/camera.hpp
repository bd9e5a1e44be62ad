// Where the camera stands: an orthographic view that frames the mesh's bounding box.
#pragma once

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "mesh/bounds.hpp"

namespace knitc::render::detail {

using mesh::Bounds;

struct Camera {
  glm::mat4 view{1.0f};        // world (mm) to eye: the camera looks down eye -Z, +Y up
  glm::mat4 projection{1.0f};  // eye to clip
  glm::mat3 normal{1.0f};      // world normals to eye (the rotation part of view)
};

// Looks at the box from +Z (from_back false) or from -Z turned about the vertical axis
// (from_back true), fitting its XY extent plus a margin into a frame of the given aspect
// (width / height). The same box gives the same scale and centre from both sides.
Camera frame(const Bounds& box, bool from_back, float aspect);

}  // namespace knitc::render::detail

// Drawing the mesh into the current OSMesa context: one GLSL program, lit in linear light.
#pragma once

#include "camera.hpp"
#include "gl_context.hpp"
#include "mesh/mesh.hpp"

namespace knitc::render::detail {

// Throws std::runtime_error if the mesh cannot be drawn as it stands: an index past the
// primitive's positions, normals neither empty nor one per position, a material that does not
// exist.
void validate(const mesh::Mesh& mesh);

class MeshDrawer {
 public:
  // Compiles and links the shaders in the current context. Throws std::runtime_error on failure.
  explicit MeshDrawer(const GlFunctions& gl);
  ~MeshDrawer();
  MeshDrawer(const MeshDrawer&) = delete;
  MeshDrawer& operator=(const MeshDrawer&) = delete;

  // Draws the (validated) mesh over whatever the frame holds, with depth testing; lines are
  // line_width pixels wide. The vertex arrays are read straight from the mesh, not copied.
  void draw(const mesh::Mesh& mesh, const Camera& camera, float line_width) const;

 private:
  const GlFunctions& gl_;
  GLuint program_ = 0;
  GLint u_mvp_ = -1, u_view_ = -1, u_normal_ = -1, u_color_ = -1, u_shading_ = -1;
};

}  // namespace knitc::render::detail

#include "draw.hpp"

#include <algorithm>
#include <climits>
#include <stdexcept>
#include <string>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

namespace knitc::render::detail {

static_assert(sizeof(glm::vec3) == 3 * sizeof(float), "vertex arrays are read straight from glm::vec3");

namespace {

// Eye space: the camera looks down -Z with +Y up, so the lights below stay put relative to the
// picture whichever side of the fabric is shown.
constexpr const char* vertex_source = R"(#version 330 core
in vec3 position;
in vec3 normal;
in vec3 color;  // the yarn's colour here (a dyed yarn), else white
uniform mat4 mvp;
uniform mat4 view;
uniform mat3 normal_matrix;
out vec3 eye_position;
out vec3 eye_normal;
out vec3 vertex_color;
void main() {
  vertex_color = color;
  gl_Position = mvp * vec4(position, 1.0);
  eye_position = (view * vec4(position, 1.0)).xyz;
  eye_normal = normal_matrix * normal;
}
)";

// All in linear light; the caller encodes sRGB after averaging the samples. A surface facing
// the viewer gets about 1.0 in all, so it shows its base colour as written.
constexpr const char* fragment_source = R"(#version 330 core
in vec3 eye_position;
in vec3 eye_normal;
in vec3 vertex_color;
uniform vec3 base_color;
uniform int shading;  // 0 smooth from the normals, 1 flat from the surface, 2 unlit
out vec4 frag_color;

const vec3 key_dir = normalize(vec3(-0.45, 0.55, 0.70));   // upper left, in front
const vec3 fill_dir = normalize(vec3(0.55, -0.15, 0.82));  // right, a little low
const float key = 0.80;
const float fill = 0.25;

void main() {
  if (shading == 2) {
    frag_color = vec4(base_color * vertex_color, 1.0);
    return;
  }
  vec3 n = shading == 0 ? eye_normal : cross(dFdx(eye_position), dFdy(eye_position));
  float len = length(n);
  n = len > 1e-20 ? n / len : vec3(0.0, 0.0, 1.0);
  // Winding is not known, so a normal pointing away from the viewer belongs to a sheet seen
  // from behind (or a tube's silhouette): turn it toward the viewer, keeping its slant.
  n.z = abs(n.z);
  float ambient = mix(0.16, 0.26, 0.5 + 0.5 * n.y);  // a brighter sky than ground
  float diffuse = ambient + key * max(dot(n, key_dir), 0.0) + fill * max(dot(n, fill_dir), 0.0);
  vec3 half_vector = normalize(key_dir + vec3(0.0, 0.0, 1.0));
  float sheen = 0.06 * pow(max(dot(n, half_vector), 0.0), 24.0);
  frag_color = vec4(base_color * vertex_color * diffuse + vec3(sheen), 1.0);
}
)";

GLuint compile(const GlFunctions& gl, GLenum type, const char* source) {
  const GLuint shader = gl.CreateShader(type);
  if (!shader) throw std::runtime_error("render: cannot create a shader");
  gl.ShaderSource(shader, 1, &source, nullptr);
  gl.CompileShader(shader);
  GLint ok = GL_FALSE;
  gl.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    char log[2048] = {};
    gl.GetShaderInfoLog(shader, sizeof log, nullptr, log);
    gl.DeleteShader(shader);
    throw std::runtime_error(std::string("render: shader does not compile: ") + log);
  }
  return shader;
}

GLenum gl_mode(mesh::Mode mode) {
  switch (mode) {
    case mesh::Mode::triangles: return GL_TRIANGLES;
    case mesh::Mode::lines: return GL_LINES;
    case mesh::Mode::line_strip: return GL_LINE_STRIP;
  }
  return GL_TRIANGLES;
}

}  // namespace

void validate(const mesh::Mesh& mesh) {
  std::vector<const mesh::Primitive*> all;
  for (const auto& p : mesh.primitives) all.push_back(&p);
  for (const auto& group : mesh.instanced)
    for (const auto& p : group.primitives) all.push_back(&p);
  for (std::size_t i = 0; i < all.size(); ++i) {
    const auto& p = *all[i];
    const std::string which = "render: primitive " + std::to_string(i);
    if (p.material < 0 || static_cast<std::size_t>(p.material) >= mesh.materials.size())
      throw std::runtime_error(which + " uses material " + std::to_string(p.material) + " of " +
                               std::to_string(mesh.materials.size()));
    if (!p.normals.empty() && p.normals.size() != p.positions.size())
      throw std::runtime_error(which + " has " + std::to_string(p.normals.size()) + " normals for " +
                               std::to_string(p.positions.size()) + " positions");
    if (!p.colors.empty() && p.colors.size() != p.positions.size())
      throw std::runtime_error(which + " has " + std::to_string(p.colors.size()) + " colours for " +
                               std::to_string(p.positions.size()) + " positions");
    if (p.positions.size() > static_cast<std::size_t>(INT_MAX))
      throw std::runtime_error(which + " has too many positions to draw");
    std::uint32_t top = 0;
    for (const std::uint32_t k : p.indices) top = std::max(top, k);
    if (!p.indices.empty() && top >= p.positions.size())
      throw std::runtime_error(which + " has index " + std::to_string(top) + " past its " +
                               std::to_string(p.positions.size()) + " positions");
  }
}

MeshDrawer::MeshDrawer(const GlFunctions& gl) : gl_(gl) {
  const GLuint vs = compile(gl, GL_VERTEX_SHADER, vertex_source);
  GLuint fs = 0;
  try {
    fs = compile(gl, GL_FRAGMENT_SHADER, fragment_source);
  } catch (...) {
    gl.DeleteShader(vs);
    throw;
  }
  program_ = gl.CreateProgram();
  gl.AttachShader(program_, vs);
  gl.AttachShader(program_, fs);
  gl.BindAttribLocation(program_, 0, "position");
  gl.BindAttribLocation(program_, 1, "normal");
  gl.BindAttribLocation(program_, 2, "color");
  gl.LinkProgram(program_);
  gl.DeleteShader(vs);  // freed with the program
  gl.DeleteShader(fs);
  GLint ok = GL_FALSE;
  gl.GetProgramiv(program_, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    char log[2048] = {};
    gl.GetProgramInfoLog(program_, sizeof log, nullptr, log);
    gl.DeleteProgram(program_);
    throw std::runtime_error(std::string("render: shaders do not link: ") + log);
  }
  u_mvp_ = gl.GetUniformLocation(program_, "mvp");
  u_view_ = gl.GetUniformLocation(program_, "view");
  u_normal_ = gl.GetUniformLocation(program_, "normal_matrix");
  u_color_ = gl.GetUniformLocation(program_, "base_color");
  u_shading_ = gl.GetUniformLocation(program_, "shading");
  check_gl(gl, "building the shaders");
}

MeshDrawer::~MeshDrawer() { gl_.DeleteProgram(program_); }

void MeshDrawer::draw(const mesh::Mesh& mesh, const Camera& camera, float line_width) const {
  const auto& gl = gl_;
  gl.UseProgram(program_);
  const glm::mat4 mvp = camera.projection * camera.view;
  gl.UniformMatrix4fv(u_mvp_, 1, GL_FALSE, glm::value_ptr(mvp));
  gl.UniformMatrix4fv(u_view_, 1, GL_FALSE, glm::value_ptr(camera.view));
  gl.UniformMatrix3fv(u_normal_, 1, GL_FALSE, glm::value_ptr(camera.normal));
  gl.LineWidth(line_width);

  // The plain primitives, then each instance's tile moved to its place.
  auto place = [&](const glm::vec3& shift) {
    const glm::mat4 view = glm::translate(camera.view, shift);
    const glm::mat4 moved = camera.projection * view;
    gl.UniformMatrix4fv(u_mvp_, 1, GL_FALSE, glm::value_ptr(moved));
    gl.UniformMatrix4fv(u_view_, 1, GL_FALSE, glm::value_ptr(view));
  };
  std::vector<std::pair<const mesh::Primitive*, const glm::vec3*>> draws;
  for (const auto& p : mesh.primitives) draws.emplace_back(&p, nullptr);
  for (const auto& group : mesh.instanced)
    for (const auto& t : group.translations)
      for (const auto& p : group.primitives) draws.emplace_back(&p, &t);
  for (const auto& [primitive, shift] : draws) {
    const mesh::Primitive& p = *primitive;
    if (p.positions.empty()) continue;
    if (shift != nullptr) place(*shift);
    const bool is_triangles = p.mode == mesh::Mode::triangles;
    const bool smooth = is_triangles && !p.normals.empty();
    gl.Uniform1i(u_shading_, !is_triangles ? 2 : smooth ? 0 : 1);
    gl.Uniform3fv(u_color_, 1, glm::value_ptr(mesh.materials[static_cast<std::size_t>(p.material)].base_color));

    // Client-side arrays (fine in a compatibility context): nothing is copied on our side.
    gl.EnableVertexAttribArray(0);
    gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, p.positions.data());
    if (smooth) {
      gl.EnableVertexAttribArray(1);
      gl.VertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 0, p.normals.data());
    } else {
      gl.DisableVertexAttribArray(1);
      gl.VertexAttrib3f(1, 0.0f, 0.0f, 1.0f);
    }
    if (!p.colors.empty()) {
      gl.EnableVertexAttribArray(2);
      gl.VertexAttribPointer(2, 3, GL_FLOAT, GL_FALSE, 0, p.colors.data());
    } else {
      gl.DisableVertexAttribArray(2);
      gl.VertexAttrib3f(2, 1.0f, 1.0f, 1.0f);
    }

    const GLenum mode = gl_mode(p.mode);
    const auto count = static_cast<GLsizei>(p.positions.size());
    if (p.indices.empty()) {
      gl.DrawArrays(mode, 0, count);
    } else {
      // In pieces that keep each count within GLsizei and whole triangles or segments in a
      // piece; a strip's next piece starts again at the last vertex of the one before.
      constexpr std::size_t piece = std::size_t{3} << 28;
      const std::size_t n = p.indices.size();
      for (std::size_t start = 0; start < n;) {
        const std::size_t end = std::min(n, start + piece);
        gl.DrawRangeElements(mode, 0, static_cast<GLuint>(count - 1), static_cast<GLsizei>(end - start),
                             GL_UNSIGNED_INT, p.indices.data() + start);
        if (end == n) break;
        start = p.mode == mesh::Mode::line_strip ? end - 1 : end;
      }
    }
  }
  gl.DisableVertexAttribArray(0);
  gl.DisableVertexAttribArray(1);
  gl.DisableVertexAttribArray(2);
  gl.UseProgram(0);
  check_gl(gl, "drawing the mesh");
}

}  // namespace knitc::render::detail

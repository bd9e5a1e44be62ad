#include "render.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "camera.hpp"
#include "draw.hpp"
#include "gl_context.hpp"
#include "image.hpp"

namespace knitc::render {

namespace {

constexpr int max_side = 16384;
// The supersampled frame is lowered to stay below this many pixels (about 20 bytes each
// between our buffer, Mesa's and the depth buffer).
constexpr long long max_frame_pixels = 40'000'000;

int grid_for(int samples) {
  int k = 1;
  while (k * k < samples && k < 16) ++k;
  return k;
}

}  // namespace

std::string png(const mesh::Mesh& mesh, const RenderOptions& options) {
  const int w = options.width, h = options.height;
  if (w < 1 || h < 1 || w > max_side || h > max_side)
    throw std::runtime_error("render: image size " + std::to_string(w) + " x " + std::to_string(h) +
                             " is not within 1 to " + std::to_string(max_side) + " pixels a side");
  const bool both = options.side == RenderOptions::Side::both;
  if (both && 2 * w > max_side)
    throw std::runtime_error("render: two views of width " + std::to_string(w) + " are wider than " +
                             std::to_string(max_side) + " pixels");
  detail::validate(mesh);

  detail::GlContext context;
  int k = grid_for(options.samples);
  while (k > 1 && (w * k > context.max_width() || h * k > context.max_height() ||
                   static_cast<long long>(w * k) * (h * k) > max_frame_pixels))
    --k;
  context.bind(w * k, h * k);
  const auto& gl = context.gl();
  const detail::MeshDrawer drawer(gl);

  gl.Viewport(0, 0, w * k, h * k);
  gl.Enable(GL_DEPTH_TEST);
  gl.DepthFunc(GL_LESS);
  gl.Disable(GL_CULL_FACE);  // winding is not part of the mesh's contract
  gl.Disable(GL_BLEND);
  gl.Disable(GL_DITHER);
  const auto clamp01 = [](float v) { return v < 0.0f ? 0.0f : v > 1.0f ? 1.0f : v; };
  gl.ClearColor(clamp01(options.background.r), clamp01(options.background.g), clamp01(options.background.b), 1.0f);
  gl.ClearDepth(1.0);
  detail::check_gl(gl, "setting up");

  detail::Image image;
  image.width = both ? 2 * w : w;
  image.height = h;
  image.rgb.assign(static_cast<std::size_t>(image.width) * static_cast<std::size_t>(h) * 3, 0);

  const mesh::Bounds box = mesh::bounds(mesh);
  const float aspect = static_cast<float>(w) / static_cast<float>(h);
  const auto draw_view = [&](bool from_back, int x0) {
    gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    drawer.draw(mesh, detail::frame(box, from_back, aspect), 1.5f * static_cast<float>(k));
    detail::resolve(context.finish(), w, h, k, image, x0);
  };
  switch (options.side) {
    case RenderOptions::Side::face: draw_view(false, 0); break;
    case RenderOptions::Side::back: draw_view(true, 0); break;
    case RenderOptions::Side::both:
      draw_view(false, 0);
      draw_view(true, w);
      break;
  }
  return detail::encode_png(image);
}

}  // namespace knitc::render

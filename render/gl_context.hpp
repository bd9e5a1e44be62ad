// An OSMesa context drawing into memory we own, and the OpenGL entry points we use, fetched
// from OSMesa itself (OSMesaGetProcAddress) so that a libGL linked into the same program can
// never take the calls.
#pragma once

#define GL_GLEXT_PROTOTYPES 1  // declarations only: gives decltype(&::glX) for every function
#include <GL/gl.h>
#include <GL/glext.h>

#include <cstdint>
#include <vector>

namespace knitc::render::detail {

struct GlFunctions {
#define KNITC_GL_FUNCTION(name) decltype(&::gl##name) name = nullptr;
#include "gl_functions.inc"
#undef KNITC_GL_FUNCTION
};

class GlContext {
 public:
  // Creates an RGBA context with a 24-bit depth buffer. Throws std::runtime_error on failure.
  GlContext();
  ~GlContext();
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  // The largest frame OSMesa accepts.
  int max_width() const { return max_width_; }
  int max_height() const { return max_height_; }

  // (Re)allocates the colour buffer, RGBA with 16 bits a channel (linear light needs more than
  // 8 for the shadows), and makes the context current on this thread. Throws on failure.
  void bind(int width, int height);

  // Waits for drawing to finish and returns the frame: width * height RGBA pixels, rows from
  // the bottom up as OpenGL numbers them.
  const std::vector<std::uint16_t>& finish();

  const GlFunctions& gl() const { return gl_; }

 private:
  void* context_ = nullptr;  // OSMesaContext
  std::vector<std::uint16_t> pixels_;
  int max_width_ = 0, max_height_ = 0;
  GlFunctions gl_;
};

// Throws std::runtime_error naming `what` when OpenGL reports an error.
void check_gl(const GlFunctions& gl, const char* what);

}  // namespace knitc::render::detail

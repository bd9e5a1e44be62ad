#include "gl_context.hpp"

#include <GL/osmesa.h>

#include <stdexcept>
#include <string>

namespace knitc::render::detail {

namespace {

OSMesaContext as_osmesa(void* p) { return static_cast<OSMesaContext>(p); }

template <typename F>
void load(F& f, const char* name) {
  const OSMESAproc p = OSMesaGetProcAddress(name);
  if (!p) throw std::runtime_error(std::string("render: OSMesa has no OpenGL function ") + name);
  f = reinterpret_cast<F>(p);
}

}  // namespace

GlContext::GlContext() {
  // RGBA, 24-bit depth, no stencil or accumulation buffer, nothing shared. Mesa gives a
  // compatibility-profile context of the highest version it has (4.5 on llvmpipe).
  context_ = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
  if (!context_) throw std::runtime_error("render: cannot create an OSMesa context");
#define KNITC_GL_FUNCTION(name) load(gl_.name, "gl" #name);
  try {
#include "gl_functions.inc"
  } catch (...) {
    OSMesaDestroyContext(as_osmesa(context_));
    throw;
  }
#undef KNITC_GL_FUNCTION
  GLint w = 0, h = 0;
  OSMesaGetIntegerv(OSMESA_MAX_WIDTH, &w);
  OSMesaGetIntegerv(OSMESA_MAX_HEIGHT, &h);
  max_width_ = w > 0 ? w : 4096;
  max_height_ = h > 0 ? h : 4096;
}

GlContext::~GlContext() { OSMesaDestroyContext(as_osmesa(context_)); }

void GlContext::bind(int width, int height) {
  if (width < 1 || height < 1 || width > max_width_ || height > max_height_)
    throw std::runtime_error("render: frame of " + std::to_string(width) + " x " + std::to_string(height) +
                             " pixels is beyond OSMesa's limit of " + std::to_string(max_width_) + " x " +
                             std::to_string(max_height_));
  pixels_.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4, 0);
  if (!OSMesaMakeCurrent(as_osmesa(context_), pixels_.data(), GL_UNSIGNED_SHORT, width, height))
    throw std::runtime_error("render: OSMesa cannot draw into a " + std::to_string(width) + " x " +
                             std::to_string(height) + " RGBA16 buffer");
  // Rows from the bottom up, the OpenGL order (the default; set so it cannot change under us).
  OSMesaPixelStore(OSMESA_Y_UP, 1);
  OSMesaPixelStore(OSMESA_ROW_LENGTH, 0);
}

const std::vector<std::uint16_t>& GlContext::finish() {
  gl_.Finish();  // OSMesa copies the frame into pixels_ here
  check_gl(gl_, "drawing");
  return pixels_;
}

void check_gl(const GlFunctions& gl, const char* what) {
  const GLenum e = gl.GetError();
  if (e == GL_NO_ERROR) return;
  // Drain the queue so the next check starts clean.
  for (int i = 0; i < 16 && gl.GetError() != GL_NO_ERROR; ++i) {
  }
  const char* name = e == GL_OUT_OF_MEMORY     ? "out of memory"
                     : e == GL_INVALID_VALUE     ? "invalid value"
                     : e == GL_INVALID_ENUM      ? "invalid enum"
                     : e == GL_INVALID_OPERATION ? "invalid operation"
                                                 : "error";
  throw std::runtime_error(std::string("render: OpenGL ") + name + " (" + std::to_string(e) + ") in " + what);
}

}  // namespace knitc::render::detail

// Mesa's OSMesa keeps a few hundred bytes per context and frame buffer until the process ends
// (Debian 12, Mesa 22.3), which LeakSanitizer reports at exit in sanitizer builds
// (KNITC_SANITIZE). Suppress leaks allocated inside libOSMesa only; ignored in other builds.
extern "C" __attribute__((visibility("default"), used)) const char* __lsan_default_suppressions() {
  return "leak:libOSMesa.so\n";
}

#include "gl_context.hpp"

#include <GL/osmesa.h>
#include <dlfcn.h>

#include <stdexcept>
#include <string>
#include <type_traits>

namespace knitc::render::detail {

namespace {

// OSMesa is opened when a picture is first drawn, not linked: it brings LLVM with it,
// and loading that took about 75 ms of every knitc run, a render or not
// (docs/performance.md).
struct OsMesa {
  decltype(&::OSMesaCreateContextExt) CreateContextExt = nullptr;
  decltype(&::OSMesaDestroyContext) DestroyContext = nullptr;
  decltype(&::OSMesaMakeCurrent) MakeCurrent = nullptr;
  decltype(&::OSMesaPixelStore) PixelStore = nullptr;
  decltype(&::OSMesaGetIntegerv) GetIntegerv = nullptr;
  decltype(&::OSMesaGetProcAddress) GetProcAddress = nullptr;
};

const OsMesa& osmesa() {
  static const OsMesa library = [] {
    // Debian 12's libosmesa6 (the soname), else whatever the development link names.
    void* handle = nullptr;
    for (const char* name : {"libOSMesa.so.8", "libOSMesa.so"})
      if (!handle) handle = dlopen(name, RTLD_NOW | RTLD_LOCAL);
    if (!handle)
      throw std::runtime_error(std::string("render: cannot load OSMesa (libOSMesa.so.8): ") + dlerror() +
                               "; on Debian 12 it is the package libosmesa6");
    OsMesa o;
    auto find = [&](auto& f, const char* name) {
      f = reinterpret_cast<std::remove_reference_t<decltype(f)>>(dlsym(handle, name));
      if (!f) throw std::runtime_error(std::string("render: OSMesa has no ") + name);
    };
    find(o.CreateContextExt, "OSMesaCreateContextExt");
    find(o.DestroyContext, "OSMesaDestroyContext");
    find(o.MakeCurrent, "OSMesaMakeCurrent");
    find(o.PixelStore, "OSMesaPixelStore");
    find(o.GetIntegerv, "OSMesaGetIntegerv");
    find(o.GetProcAddress, "OSMesaGetProcAddress");
    return o;  // never closed: Mesa's state lives as long as the process
  }();
  return library;
}

OSMesaContext as_osmesa(void* p) { return static_cast<OSMesaContext>(p); }

template <typename F>
void load(F& f, const char* name) {
  const OSMESAproc p = osmesa().GetProcAddress(name);
  if (!p) throw std::runtime_error(std::string("render: OSMesa has no OpenGL function ") + name);
  f = reinterpret_cast<F>(p);
}

}  // namespace

GlContext::GlContext() {
  // RGBA, 24-bit depth, no stencil or accumulation buffer, nothing shared. Mesa gives a
  // compatibility-profile context of the highest version it has (4.5 on llvmpipe).
  context_ = osmesa().CreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
  if (!context_) throw std::runtime_error("render: cannot create an OSMesa context");
#define KNITC_GL_FUNCTION(name) load(gl_.name, "gl" #name);
  try {
#include "gl_functions.inc"
  } catch (...) {
    osmesa().DestroyContext(as_osmesa(context_));
    throw;
  }
#undef KNITC_GL_FUNCTION
  GLint w = 0, h = 0;
  osmesa().GetIntegerv(OSMESA_MAX_WIDTH, &w);
  osmesa().GetIntegerv(OSMESA_MAX_HEIGHT, &h);
  max_width_ = w > 0 ? w : 4096;
  max_height_ = h > 0 ? h : 4096;
}

GlContext::~GlContext() { osmesa().DestroyContext(as_osmesa(context_)); }

void GlContext::bind(int width, int height) {
  if (width < 1 || height < 1 || width > max_width_ || height > max_height_)
    throw std::runtime_error("render: frame of " + std::to_string(width) + " x " + std::to_string(height) +
                             " pixels is beyond OSMesa's limit of " + std::to_string(max_width_) + " x " +
                             std::to_string(max_height_));
  pixels_.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4, 0);
  if (!osmesa().MakeCurrent(as_osmesa(context_), pixels_.data(), GL_UNSIGNED_SHORT, width, height))
    throw std::runtime_error("render: OSMesa cannot draw into a " + std::to_string(width) + " x " +
                             std::to_string(height) + " RGBA16 buffer");
  // Rows from the bottom up, the OpenGL order (the default; set so it cannot change under us).
  osmesa().PixelStore(OSMESA_Y_UP, 1);
  osmesa().PixelStore(OSMESA_ROW_LENGTH, 0);
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

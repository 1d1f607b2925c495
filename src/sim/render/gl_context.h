// gl_context.h: an OpenGL context for offscreen rendering without a display or GPU, behind
// one small interface so the platform layer can change (Mesa 25.1 removed OSMesa; EGL is
// its successor). Backends:
//   osmesa  Mesa's off-screen context (llvmpipe, software); the default
//   egl     EGL on Mesa's surfaceless platform (llvmpipe when there is no GPU), or the
//           default EGL display elsewhere; libEGL is loaded when first asked for
// MuJoCo resolves the GL functions once per process, through the first backend used, so a
// process uses one backend only (a second one throws std::logic_error).
#pragma once

#include <memory>
#include <string>

namespace pamsim {

enum class GlBackend { kOsmesa, kEgl };

const char* gl_backend_name(GlBackend backend);

// "osmesa" | "egl". Throws InputError "<source> must be osmesa or egl, got '<name>'".
GlBackend parse_gl_backend(const std::string& name, const std::string& source);

// The backend asked for by an option (`option_value`, "--backend"), else by the environment
// variable PAMSIM_GL_BACKEND, else osmesa. Throws InputError naming the one that is bad.
GlBackend choose_gl_backend(const std::string& option_value);

class GlContext {
 public:
  virtual ~GlContext() = default;
  // Makes this context current on the calling thread (MuJoCo's mjr_* calls need it).
  virtual void make_current() = 0;
};

// A context for rendering, current on return. MuJoCo draws into its own offscreen buffer;
// width x height is the size of the context's default framebuffer where the backend has one
// (osmesa; egl is surfaceless).
// Throws InputError when the backend is unavailable here (e.g. no libEGL) or the context
// cannot be created, naming the backend and the reason.
std::unique_ptr<GlContext> create_gl_context(GlBackend backend, int width, int height);

}  // namespace pamsim

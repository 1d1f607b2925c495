// gl_context.h: an OpenGL context for offscreen rendering without a display or GPU, behind
// one small interface so the platform layer can change (Mesa 25.1 removed OSMesa; EGL is
// its successor). Backends:
//   osmesa  Mesa's off-screen context (llvmpipe, software); the default
//   egl     an EGL device (EGL_EXT_platform_device): the one asked for (--gpu N,
//           EGL_DEVICE_ID or MUJOCO_EGL_DEVICE_ID), else the first GPU; without a GPU,
//           Mesa's surfaceless platform (llvmpipe), then the default EGL display; and when
//           EGL cannot give a context at all (no libEGL, no driver), osmesa, saying why.
//           libEGL is loaded when first asked for.
// The backend comes from --backend, else PAMSIM_GL_BACKEND, else MUJOCO_GL when it is egl or
// osmesa (as MuJoCo's Python bindings read it; its glfw needs a window), else osmesa. MuJoCo
// resolves the GL functions once per process, through the first backend used, so a process uses one
// backend only (a second one throws std::logic_error).
#pragma once

#include <memory>
#include <string>

namespace pamsim {

enum class GlBackend { kOsmesa, kEgl };

const char* gl_backend_name(GlBackend backend);

// "osmesa" | "egl". Throws InputError "<source> must be osmesa or egl, got '<name>'".
GlBackend parse_gl_backend(const std::string& name, const std::string& source);

// The backend asked for by an option (`option_value`, "--backend"), else by the environment
// variable PAMSIM_GL_BACKEND, else by MUJOCO_GL if it is egl or osmesa (other values, such as
// glfw, are MuJoCo's window systems and are passed over), else osmesa. Throws InputError
// naming the option or PAMSIM_GL_BACKEND when it is bad.
GlBackend choose_gl_backend(const std::string& option_value);

// An EGL device, by its index in eglQueryDevicesEXT's list, and where the choice came from.
struct EglDeviceChoice {
  int index = -1;      // -1: none asked for (the first GPU, else Mesa's surfaceless platform)
  std::string source;  // "--gpu", "EGL_DEVICE_ID", "MUJOCO_EGL_DEVICE_ID"
};

// The device asked for by an option (`option_value` >= 0, "--gpu"), else by EGL_DEVICE_ID,
// else MUJOCO_EGL_DEVICE_ID, else none. Throws InputError "<source> must be a device number
// >= 0, got '<value>'".
EglDeviceChoice choose_egl_device(int option_value);

class GlContext {
 public:
  virtual ~GlContext() = default;
  // Makes this context current on the calling thread (MuJoCo's mjr_* calls need it).
  virtual void make_current() = 0;
  // What was set up: "egl device 1 of 2 (/dev/dri/renderD128)", "egl surfaceless (Mesa)",
  // "osmesa", or "osmesa (egl unavailable: <why>)" after a fallback.
  virtual std::string description() const = 0;
  // The GL implementation drawing, from glGetString: "<vendor>, <renderer>, OpenGL <version>".
  virtual std::string renderer() const = 0;
  // A GL entry point of this context by name ("glBegin"), as its backend resolves it
  // (OSMesaGetProcAddress, eglGetProcAddress: the linked one may belong to another library);
  // null where missing.
  virtual void* gl_function(const char* name) const = 0;
};

// A context for rendering, current on return. MuJoCo draws into its own offscreen buffer;
// width x height is the size of the context's default framebuffer where the backend has one
// (osmesa; egl is surfaceless). `device` applies to egl only.
// Throws InputError when the backend is unavailable here (e.g. built without EGL), when the
// device asked for does not exist (the message lists those there are) or gives no context,
// or when the context cannot be created, naming the backend and the reason.
std::unique_ptr<GlContext> create_gl_context(GlBackend backend, int width, int height,
                                             const EglDeviceChoice& device = {});

}  // namespace pamsim

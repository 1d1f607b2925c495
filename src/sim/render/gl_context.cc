// gl_context.cc: see gl_context.h.
//
// Why libEGL is loaded with dlopen instead of linked: MuJoCo's GL loader looks for
// eglGetProcAddress in the process before OSMesaGetProcAddress. Were libEGL linked, the
// osmesa backend would get GLVND's EGL entry points, which draw nothing into an OSMesa
// context. Loaded on demand with RTLD_GLOBAL, it is visible to MuJoCo only in a process that
// chose egl, and MuJoCo then binds GL through eglGetProcAddress as it should.
#include "sim/render/gl_context.h"

#include <GL/osmesa.h>
#include <dlfcn.h>

#ifdef PAMSIM_HAVE_EGL
#include <EGL/egl.h>
#include <EGL/eglext.h>
#endif

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "pam_actuator/input_error.h"

namespace pamsim {
namespace {

constexpr const char* kBackendEnvVar = "PAMSIM_GL_BACKEND";

// MuJoCo binds GL functions once per process, through the first backend's loader. Throws if
// another backend already drew in this process; with `claim`, records this one.
void check_backend_for_process(GlBackend backend, bool claim) {
  static std::mutex mutex;
  static std::optional<GlBackend> claimed;
  std::lock_guard<std::mutex> lock(mutex);
  if (claimed && *claimed != backend) {
    throw std::logic_error(std::string("GL backend ") + gl_backend_name(backend) +
                           " requested after " + gl_backend_name(*claimed) +
                           ": MuJoCo binds GL functions once per process, use one backend");
  }
  if (claim) claimed = backend;
}

// ---- OSMesa ----

struct OsMesaContextDeleter {
  void operator()(std::remove_pointer_t<OSMesaContext>* ctx) const { OSMesaDestroyContext(ctx); }
};
using OsMesaContextPtr =
    std::unique_ptr<std::remove_pointer_t<OSMesaContext>, OsMesaContextDeleter>;

class OsMesaGlContext : public GlContext {
 public:
  OsMesaGlContext(int width, int height)
      : width_(width),
        height_(height),
        color_buffer_(4 * static_cast<std::size_t>(width) * height) {
    // RGBA, 24-bit depth, 8-bit stencil, 8-bit accumulation (DESIGN.md)
    context_.reset(OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 8, nullptr));
    if (!context_) throw InputError("--backend osmesa: OSMesaCreateContextExt failed");
    make_current();
  }

  void make_current() override {
    if (!OSMesaMakeCurrent(context_.get(), color_buffer_.data(), GL_UNSIGNED_BYTE, width_,
                           height_)) {
      throw InputError("--backend osmesa: OSMesaMakeCurrent failed for " +
                       std::to_string(width_) + "x" + std::to_string(height_));
    }
  }

 private:
  int width_;
  int height_;
  std::vector<unsigned char> color_buffer_;   // the default framebuffer, never read
  OsMesaContextPtr context_;
};

// ---- EGL ----

#ifdef PAMSIM_HAVE_EGL

// The EGL entry points, from libEGL loaded once with RTLD_GLOBAL (see the top of this file).
struct EglApi {
  PFNEGLGETPROCADDRESSPROC GetProcAddress = nullptr;
  PFNEGLQUERYSTRINGPROC QueryString = nullptr;
  PFNEGLGETDISPLAYPROC GetDisplay = nullptr;
  PFNEGLINITIALIZEPROC Initialize = nullptr;
  PFNEGLCHOOSECONFIGPROC ChooseConfig = nullptr;
  PFNEGLBINDAPIPROC BindAPI = nullptr;
  PFNEGLCREATECONTEXTPROC CreateContext = nullptr;
  PFNEGLMAKECURRENTPROC MakeCurrent = nullptr;
  PFNEGLGETCURRENTCONTEXTPROC GetCurrentContext = nullptr;
  PFNEGLDESTROYCONTEXTPROC DestroyContext = nullptr;
  PFNEGLGETERRORPROC GetError = nullptr;
  std::string load_error;   // why the API is unusable, empty when it is
};

const EglApi& egl_api() {
  static const EglApi api = [] {
    EglApi a;
    void* lib = dlopen("libEGL.so.1", RTLD_NOW | RTLD_GLOBAL);
    if (!lib) {
      const char* why = dlerror();
      a.load_error = std::string("cannot load libEGL.so.1 (") + (why ? why : "unknown") + ")";
      return a;
    }
    // each entry point, or the name of the first one missing
    auto load = [&](auto* fn, const char* name) {
      *fn = reinterpret_cast<std::remove_pointer_t<decltype(fn)>>(dlsym(lib, name));
      if (!*fn && a.load_error.empty()) a.load_error = std::string("libEGL.so.1 lacks ") + name;
    };
    load(&a.GetProcAddress, "eglGetProcAddress");
    load(&a.QueryString, "eglQueryString");
    load(&a.GetDisplay, "eglGetDisplay");
    load(&a.Initialize, "eglInitialize");
    load(&a.ChooseConfig, "eglChooseConfig");
    load(&a.BindAPI, "eglBindAPI");
    load(&a.CreateContext, "eglCreateContext");
    load(&a.MakeCurrent, "eglMakeCurrent");
    load(&a.GetCurrentContext, "eglGetCurrentContext");
    load(&a.DestroyContext, "eglDestroyContext");
    load(&a.GetError, "eglGetError");
    return a;
  }();
  return api;
}

bool has_extension(const char* extensions, const char* name) {
  if (!extensions) return false;
  const std::size_t n = std::strlen(name);
  for (const char* p = std::strstr(extensions, name); p; p = std::strstr(p + n, name)) {
    if ((p == extensions || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  }
  return false;
}

std::string egl_error(const EglApi& egl, const char* call) {
  char hex[16];
  std::snprintf(hex, sizeof(hex), "0x%04x", static_cast<unsigned>(egl.GetError()));
  return std::string("--backend egl: ") + call + " failed (EGL error " + hex + ")";
}

// Mesa's surfaceless platform needs neither a display server nor a GPU; other EGL
// implementations get their default display.
EGLDisplay open_display(const EglApi& egl) {
  const char* client_extensions = egl.QueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (has_extension(client_extensions, "EGL_MESA_platform_surfaceless")) {
    auto get_platform_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
        egl.GetProcAddress("eglGetPlatformDisplayEXT"));
    if (get_platform_display) {
      return get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    }
  }
  return egl.GetDisplay(EGL_DEFAULT_DISPLAY);
}

class EglGlContext : public GlContext {
 public:
  EglGlContext() : egl_(egl_api()) {
    if (!egl_.load_error.empty()) throw InputError("--backend egl: " + egl_.load_error);

    // display, then an RGBA config with depth and stencil for desktop OpenGL
    display_ = open_display(egl_);
    if (display_ == EGL_NO_DISPLAY) throw InputError(egl_error(egl_, "eglGetDisplay"));
    if (egl_.Initialize(display_, nullptr, nullptr) != EGL_TRUE) {
      throw InputError(egl_error(egl_, "eglInitialize"));
    }
    const EGLint config_attribs[] = {
        EGL_SURFACE_TYPE, EGL_PBUFFER_BIT,   EGL_RED_SIZE,        8, EGL_GREEN_SIZE, 8,
        EGL_BLUE_SIZE,    8,                 EGL_ALPHA_SIZE,      8, EGL_DEPTH_SIZE, 24,
        EGL_STENCIL_SIZE, 8,                 EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint n_configs = 0;
    if (egl_.ChooseConfig(display_, config_attribs, &config, 1, &n_configs) != EGL_TRUE ||
        n_configs < 1) {
      throw InputError("--backend egl: no RGBA config with depth and stencil for OpenGL");
    }

    // a desktop OpenGL context without a surface: MuJoCo draws into its own framebuffer
    if (egl_.BindAPI(EGL_OPENGL_API) != EGL_TRUE) throw InputError(egl_error(egl_, "eglBindAPI"));
    context_ = egl_.CreateContext(display_, config, EGL_NO_CONTEXT, nullptr);
    if (context_ == EGL_NO_CONTEXT) throw InputError(egl_error(egl_, "eglCreateContext"));
    try {
      make_current();
    } catch (...) {   // the destructor does not run for a constructor that throws
      egl_.DestroyContext(display_, context_);
      throw;
    }
  }

  ~EglGlContext() override {
    // the display stays initialised: EGL displays are shared by every context in the process
    if (egl_.GetCurrentContext() == context_) {
      egl_.MakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    }
    egl_.DestroyContext(display_, context_);
  }

  void make_current() override {
    if (egl_.MakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_) != EGL_TRUE) {
      throw InputError(egl_error(egl_, "eglMakeCurrent"));
    }
  }

 private:
  const EglApi& egl_;
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
};

#endif  // PAMSIM_HAVE_EGL

}  // namespace

const char* gl_backend_name(GlBackend backend) {
  return backend == GlBackend::kEgl ? "egl" : "osmesa";
}

GlBackend parse_gl_backend(const std::string& name, const std::string& source) {
  if (name == "osmesa") return GlBackend::kOsmesa;
  if (name == "egl") return GlBackend::kEgl;
  throw InputError(source + " must be osmesa or egl, got '" + name + "'");
}

GlBackend choose_gl_backend(const std::string& option_value) {
  if (!option_value.empty()) return parse_gl_backend(option_value, "--backend");
  const char* env = std::getenv(kBackendEnvVar);
  if (env && env[0] != '\0') return parse_gl_backend(env, kBackendEnvVar);
  return GlBackend::kOsmesa;
}

std::unique_ptr<GlContext> create_gl_context(GlBackend backend, int width, int height) {
  // checked before, claimed once the context exists: a backend that failed to start does not
  // block another
  check_backend_for_process(backend, false);
  std::unique_ptr<GlContext> context;
  if (backend == GlBackend::kOsmesa) {
    context = std::make_unique<OsMesaGlContext>(width, height);
  } else {
#ifdef PAMSIM_HAVE_EGL
    context = std::make_unique<EglGlContext>();
#else
    throw InputError("--backend egl: this pamsim was built without EGL (libegl-dev missing)");
#endif
  }
  check_backend_for_process(backend, true);
  return context;
}

}  // namespace pamsim

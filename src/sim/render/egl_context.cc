// egl_context.cc: the egl backend of gl_context.h: libEGL, its devices
// (EGL_EXT_platform_device), Mesa's surfaceless platform and the default display, and a
// desktop-OpenGL context without a surface on the first that gives one.
//
// Why libEGL is loaded with dlopen instead of linked: MuJoCo's GL loader looks for
// eglGetProcAddress in the process before OSMesaGetProcAddress. Were libEGL linked, the
// osmesa backend would get GLVND's EGL entry points, which draw nothing into an OSMesa
// context. So libEGL is loaded on demand, privately (RTLD_LOCAL), and made visible to the
// process (RTLD_NOLOAD | RTLD_GLOBAL) only once an EGL context exists: MuJoCo then binds GL
// through eglGetProcAddress as it should, and a process in which EGL failed can still fall
// back to OSMesa.
#ifdef PAMSIM_HAVE_EGL

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <dlfcn.h>

#include <atomic>
#include <cstdio>
#include <cstring>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "base/input_error.h"
#include "sim/render/gl_backends.h"

namespace pamsim {
namespace {

// The core EGL entry points pamsim calls, as X(name without "egl", its pointer type): the
// one list EglApi declares and egl_api() loads.
// clang-format off
#define PAMSIM_EGL_CORE_FUNCTIONS(X)                                                          \
  X(GetProcAddress, PFNEGLGETPROCADDRESSPROC) X(QueryString, PFNEGLQUERYSTRINGPROC)           \
  X(GetDisplay, PFNEGLGETDISPLAYPROC) X(Initialize, PFNEGLINITIALIZEPROC)                     \
  X(Terminate, PFNEGLTERMINATEPROC) X(ChooseConfig, PFNEGLCHOOSECONFIGPROC)                   \
  X(BindAPI, PFNEGLBINDAPIPROC) X(CreateContext, PFNEGLCREATECONTEXTPROC)                     \
  X(MakeCurrent, PFNEGLMAKECURRENTPROC) X(GetCurrentContext, PFNEGLGETCURRENTCONTEXTPROC)     \
  X(DestroyContext, PFNEGLDESTROYCONTEXTPROC) X(GetError, PFNEGLGETERRORPROC)
// clang-format on

// The EGL entry points, from libEGL loaded once, privately (RTLD_LOCAL) until a context exists
// (see the top of this file).
struct EglApi {
#define PAMSIM_EGL_DECLARE(name, type) type name = nullptr;
  PAMSIM_EGL_CORE_FUNCTIONS(PAMSIM_EGL_DECLARE)
#undef PAMSIM_EGL_DECLARE
  // EGL_EXT_device_enumeration, _device_query, _platform_device (null where missing)
  PFNEGLQUERYDEVICESEXTPROC QueryDevices = nullptr;
  PFNEGLQUERYDEVICESTRINGEXTPROC QueryDeviceString = nullptr;
  PFNEGLGETPLATFORMDISPLAYEXTPROC GetPlatformDisplay = nullptr;
  std::string load_error;  // why the API is unusable, empty when it is
};

bool has_extension(const char* extensions, const char* name) {
  if (!extensions) return false;
  const std::size_t n = std::strlen(name);
  for (const char* p = std::strstr(extensions, name); p; p = std::strstr(p + n, name)) {
    if ((p == extensions || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  }
  return false;
}

const EglApi& egl_api() {
  static const EglApi api = [] {
    EglApi a;
    void* lib = dlopen("libEGL.so.1", RTLD_NOW | RTLD_LOCAL);  // global once it works
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
#define PAMSIM_EGL_LOAD(name, type) load(&a.name, "egl" #name);
    PAMSIM_EGL_CORE_FUNCTIONS(PAMSIM_EGL_LOAD)
#undef PAMSIM_EGL_LOAD
    if (!a.load_error.empty()) return a;
    const char* client = a.QueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (has_extension(client, "EGL_EXT_platform_base")) {
      a.GetPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
          a.GetProcAddress("eglGetPlatformDisplayEXT"));
    }
    if (has_extension(client, "EGL_EXT_device_enumeration") &&
        has_extension(client, "EGL_EXT_platform_device")) {
      a.QueryDevices =
          reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(a.GetProcAddress("eglQueryDevicesEXT"));
      a.QueryDeviceString = reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(
          a.GetProcAddress("eglQueryDeviceStringEXT"));
    }
    return a;
  }();
  return api;
}

std::string egl_error(const EglApi& egl, const char* call) {
  char hex[16];
  std::snprintf(hex, sizeof(hex), "0x%04x", static_cast<unsigned>(egl.GetError()));
  return std::string(call) + " failed (EGL error " + hex + ")";
}

// One EGL device: its handle and what to call it.
struct EglDevice {
  EGLDeviceEXT handle = nullptr;
  std::string name;  // its DRM node, or "software" for Mesa's llvmpipe device
  bool software = false;
};

std::vector<EglDevice> egl_devices(const EglApi& egl) {
  std::vector<EglDevice> devices;
  if (!egl.QueryDevices || !egl.QueryDeviceString || !egl.GetPlatformDisplay) return devices;
  EGLint n = 0;
  if (egl.QueryDevices(0, nullptr, &n) != EGL_TRUE || n <= 0) return devices;
  std::vector<EGLDeviceEXT> handles(static_cast<std::size_t>(n));
  if (egl.QueryDevices(n, handles.data(), &n) != EGL_TRUE) return devices;
  for (EGLint i = 0; i < n; ++i) {
    EglDevice d;
    d.handle = handles[static_cast<std::size_t>(i)];
    const char* extensions = egl.QueryDeviceString(d.handle, EGL_EXTENSIONS);
    d.software = has_extension(extensions, "EGL_MESA_device_software");
    const char* node = has_extension(extensions, "EGL_EXT_device_drm")
                           ? egl.QueryDeviceString(d.handle, EGL_DRM_DEVICE_FILE_EXT)
                           : nullptr;
    d.name = node ? node : d.software ? "software" : "no DRM node";
    devices.push_back(d);
  }
  return devices;
}

// "0 (software), 1 (/dev/dri/renderD128)", or "none".
std::string device_list(const std::vector<EglDevice>& devices) {
  std::string list;
  for (std::size_t i = 0; i < devices.size(); ++i) {
    list += (i ? ", " : "") + std::to_string(i) + " (" + devices[i].name + ")";
  }
  return list.empty() ? "none" : list;
}

// A display with a desktop-OpenGL context on it, or the reason there is none.
struct EglSetup {
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;
  std::string description;
  std::string error;  // empty on success
};

// make_context's second half, on an initialised display.
EglSetup make_context_on(const EglApi& egl, EGLDisplay display, EglSetup setup) {
  const EGLint config_attribs[] = {EGL_SURFACE_TYPE,
                                   EGL_PBUFFER_BIT,
                                   EGL_RED_SIZE,
                                   8,
                                   EGL_GREEN_SIZE,
                                   8,
                                   EGL_BLUE_SIZE,
                                   8,
                                   EGL_ALPHA_SIZE,
                                   8,
                                   EGL_DEPTH_SIZE,
                                   24,
                                   EGL_STENCIL_SIZE,
                                   8,
                                   EGL_RENDERABLE_TYPE,
                                   EGL_OPENGL_BIT,
                                   EGL_NONE};
  EGLConfig config = nullptr;
  EGLint n_configs = 0;
  if (egl.ChooseConfig(display, config_attribs, &config, 1, &n_configs) != EGL_TRUE ||
      n_configs < 1) {
    setup.error = "no RGBA config with depth and stencil for OpenGL";
    return setup;
  }
  if (egl.BindAPI(EGL_OPENGL_API) != EGL_TRUE) {
    setup.error = egl_error(egl, "eglBindAPI");
    return setup;
  }
  EGLContext context = egl.CreateContext(display, config, EGL_NO_CONTEXT, nullptr);
  if (context == EGL_NO_CONTEXT) {
    setup.error = egl_error(egl, "eglCreateContext");
    return setup;
  }
  if (egl.MakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context) != EGL_TRUE) {
    setup.error = egl_error(egl, "eglMakeCurrent");
    egl.DestroyContext(display, context);
    return setup;
  }
  setup.display = display;
  setup.context = context;
  return setup;
}

// Whether an EGL context of this process exists (its display must then stay initialised).
std::atomic<bool> egl_context_made{false};

// Initialises `display` and makes an RGBA context with depth and stencil for desktop OpenGL,
// without a surface (MuJoCo draws into its own framebuffer), current on return. A display
// that gives no context is terminated again (unless another context of the process uses
// EGL), so trying several devices leaves nothing behind.
EglSetup make_context(const EglApi& egl, EGLDisplay display, std::string description) {
  EglSetup setup;
  setup.description = std::move(description);
  if (display == EGL_NO_DISPLAY) {
    setup.error = egl_error(egl, "eglGetDisplay");
    return setup;
  }
  if (egl.Initialize(display, nullptr, nullptr) != EGL_TRUE) {
    setup.error = egl_error(egl, "eglInitialize");
    return setup;
  }
  setup = make_context_on(egl, display, std::move(setup));
  if (!setup.error.empty() && !egl_context_made.load()) egl.Terminate(display);
  return setup;
}

// The context on the device asked for, else on the first GPU, else on Mesa's surfaceless
// platform (no display server, no GPU), else on the default display. Throws InputError for a
// device asked for that does not exist or gives no context, and when nothing gives one.
EglSetup open_egl(const EglApi& egl, const EglDeviceChoice& choice) {
  const std::vector<EglDevice> devices = egl_devices(egl);
  const auto on_device = [&](std::size_t i) {
    return make_context(egl,
                        egl.GetPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i].handle, nullptr),
                        "egl device " + std::to_string(i) + " of " +
                            std::to_string(devices.size()) + " (" + devices[i].name + ")");
  };
  if (choice.index >= 0) {
    if (static_cast<std::size_t>(choice.index) >= devices.size()) {
      throw InputError(choice.source + " " + std::to_string(choice.index) +
                       ": no such EGL device; the devices here: " + device_list(devices) +
                       (devices.empty()
                            ? " (without a device number, egl takes the surfaceless platform, "
                              "which can still reach a GPU)"
                            : ""));
    }
    EglSetup setup = on_device(static_cast<std::size_t>(choice.index));
    if (!setup.error.empty()) {
      throw InputError(choice.source + " " + std::to_string(choice.index) + ": " + setup.error);
    }
    return setup;
  }
  std::string errors;
  const auto tried = [&](const EglSetup& s) {
    errors += (errors.empty() ? "" : "; ") + s.description + ": " + s.error;
  };
  for (std::size_t i = 0; i < devices.size(); ++i) {
    if (devices[i].software) continue;
    EglSetup setup = on_device(i);
    if (setup.error.empty()) return setup;
    tried(setup);
  }
  // a platform without devices says why no GPU device was used: the GL string names the vendor
  const std::string no_device =
      " (no GPU device: " + (errors.empty() ? "EGL lists " + device_list(devices) : errors) + ")";
  const auto without_device = [&no_device](EglSetup setup) {
    setup.description += no_device;
    return setup;
  };
  const char* client = egl.QueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (egl.GetPlatformDisplay && has_extension(client, "EGL_MESA_platform_surfaceless")) {
    EglSetup setup = make_context(
        egl, egl.GetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr),
        "egl surfaceless");
    if (setup.error.empty()) return without_device(std::move(setup));
    tried(setup);
  }
  EglSetup setup = make_context(egl, egl.GetDisplay(EGL_DEFAULT_DISPLAY), "egl default display");
  if (setup.error.empty()) return without_device(std::move(setup));
  tried(setup);
  throw InputError("--backend egl: no context (" + errors + ")");
}

class EglGlContext : public GlContext {
 public:
  explicit EglGlContext(const EglDeviceChoice& choice) : egl_(egl_api()) {
    if (!egl_.load_error.empty()) throw InputError("--backend egl: " + egl_.load_error);
    EglSetup setup = open_egl(egl_, choice);
    display_ = setup.display;
    context_ = setup.context;
    description_ = setup.description;
    egl_context_made = true;
    // now MuJoCo may see libEGL (see the top of this file)
    if (!dlopen("libEGL.so.1", RTLD_NOW | RTLD_NOLOAD | RTLD_GLOBAL)) {
      egl_.MakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
      egl_.DestroyContext(display_, context_);
      throw InputError("--backend egl: cannot make libEGL.so.1 visible to MuJoCo");
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
      throw InputError("--backend egl: " + egl_error(egl_, "eglMakeCurrent"));
    }
  }

  std::string description() const override { return description_; }
  std::string renderer() const override {
    return gl_strings(reinterpret_cast<GlGetString>(egl_.GetProcAddress("glGetString")));
  }
  void* gl_function(const char* name) const override {
    return reinterpret_cast<void*>(egl_.GetProcAddress(name));
  }

 private:
  const EglApi& egl_;
  std::string description_;
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
};

}  // namespace

std::unique_ptr<GlContext> make_egl_context(const EglDeviceChoice& choice) {
  return std::make_unique<EglGlContext>(choice);
}

}  // namespace pamsim

#endif  // PAMSIM_HAVE_EGL

// gl_context.cc: see gl_context.h. The choice of backend, one backend per process, and the
// fallback from egl to osmesa; the backends themselves are osmesa_context.cc and
// egl_context.cc (which explains why libEGL is loaded with dlopen).
#include "sim/render/gl_context.h"

#include <GL/gl.h>

#include <charconv>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <optional>
#include <stdexcept>

#include "base/input_error.h"
#include "sim/render/gl_backends.h"

namespace pamsim {
namespace {

constexpr const char* kBackendEnvVar = "PAMSIM_GL_BACKEND";
constexpr const char* kMujocoBackendEnvVar = "MUJOCO_GL";  // as MuJoCo's Python bindings
constexpr const char* kDeviceEnvVars[] = {"EGL_DEVICE_ID", "MUJOCO_EGL_DEVICE_ID"};

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

}  // namespace

std::string gl_strings(GlGetString get_string) {
  if (!get_string) return "unknown (no glGetString)";
  const auto text = [&](unsigned int name) {
    const unsigned char* s = get_string(name);
    return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
  };
  return text(GL_VENDOR) + ", " + text(GL_RENDERER) + ", OpenGL " + text(GL_VERSION);
}

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
  const char* own = std::getenv(kBackendEnvVar);
  if (own && own[0] != '\0') return parse_gl_backend(own, kBackendEnvVar);
  // MuJoCo's own variable also names window systems (glfw) a headless renderer has no use
  // for: only its headless values count
  const char* mujoco = std::getenv(kMujocoBackendEnvVar);
  if (mujoco && (std::strcmp(mujoco, "egl") == 0 || std::strcmp(mujoco, "osmesa") == 0)) {
    return parse_gl_backend(mujoco, kMujocoBackendEnvVar);
  }
  return GlBackend::kOsmesa;
}

EglDeviceChoice choose_egl_device(int option_value) {
  if (option_value >= 0) return {option_value, "--gpu"};
  if (option_value != -1) {
    throw InputError("--gpu must be a device number >= 0, got '" + std::to_string(option_value) +
                     "'");
  }
  for (const char* var : kDeviceEnvVars) {
    const char* env = std::getenv(var);
    if (!env || env[0] == '\0') continue;
    int index = -1;
    const char* end = env + std::strlen(env);
    const auto [ptr, ec] = std::from_chars(env, end, index);
    if (ec != std::errc() || ptr != end || index < 0) {
      throw InputError(std::string(var) + " must be a device number >= 0, got '" + env + "'");
    }
    return {index, var};
  }
  return {};
}

std::unique_ptr<GlContext> create_gl_context(GlBackend backend, int width, int height,
                                             const EglDeviceChoice& device) {
  std::unique_ptr<GlContext> context;
  if (backend == GlBackend::kEgl) {
    // checked before, claimed once the context exists: a backend that failed to start does
    // not block another
    check_backend_for_process(GlBackend::kEgl, false);
#ifdef PAMSIM_HAVE_EGL
    try {
      context = make_egl_context(device);
      check_backend_for_process(GlBackend::kEgl, true);
      return context;
    } catch (const InputError& e) {
      if (device.index >= 0) throw;  // that device was asked for: no substitute
      check_backend_for_process(GlBackend::kOsmesa, false);
      context = make_osmesa_context(width, height, e.what());
    }
#else
    if (device.index >= 0) {
      throw InputError(device.source + ": this pamsim was built without EGL (libegl-dev missing)");
    }
    check_backend_for_process(GlBackend::kOsmesa, false);
    context = make_osmesa_context(width, height,
                                  "this pamsim was built without EGL (libegl-dev missing)");
#endif
  } else {
    check_backend_for_process(GlBackend::kOsmesa, false);
    context = make_osmesa_context(width, height);
  }
  check_backend_for_process(GlBackend::kOsmesa, true);
  return context;
}

}  // namespace pamsim
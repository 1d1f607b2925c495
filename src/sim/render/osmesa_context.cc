// osmesa_context.cc: the osmesa backend of gl_context.h, Mesa's off-screen context
// (llvmpipe, software) drawing into a buffer of its own, never read (MuJoCo draws into its
// framebuffer object).
#include <GL/osmesa.h>

#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "base/input_error.h"
#include "sim/render/gl_backends.h"

namespace pamsim {
namespace {

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
    // RGBA, 24-bit depth, 8-bit stencil, 8-bit accumulation
    context_.reset(OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 8, nullptr));
    if (!context_) throw InputError("--backend osmesa: OSMesaCreateContextExt failed");
    make_current();
  }

  void make_current() override {
    if (!OSMesaMakeCurrent(context_.get(), color_buffer_.data(), GL_UNSIGNED_BYTE, width_,
                           height_)) {
      throw InputError("--backend osmesa: OSMesaMakeCurrent failed for " + std::to_string(width_) +
                       "x" + std::to_string(height_));
    }
  }

  std::string description() const override {
    return fallback_reason_.empty() ? "osmesa"
                                    : "osmesa (egl unavailable: " + fallback_reason_ + ")";
  }
  std::string renderer() const override {
    return gl_strings(reinterpret_cast<GlGetString>(OSMesaGetProcAddress("glGetString")));
  }
  void* gl_function(const char* name) const override {
    return reinterpret_cast<void*>(OSMesaGetProcAddress(name));
  }
  void set_fallback_reason(std::string why) { fallback_reason_ = std::move(why); }

 private:
  std::string fallback_reason_;  // why egl, asked for, was not used
  int width_;
  int height_;
  std::vector<unsigned char> color_buffer_;  // the default framebuffer, never read
  OsMesaContextPtr context_;
};

}  // namespace

std::unique_ptr<GlContext> make_osmesa_context(int width, int height,
                                               const std::string& fallback_reason) {
  auto context = std::make_unique<OsMesaGlContext>(width, height);
  if (!fallback_reason.empty()) context->set_fallback_reason(fallback_reason);
  return context;
}

}  // namespace pamsim

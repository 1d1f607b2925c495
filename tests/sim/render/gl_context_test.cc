// gl_context_test.cc: choosing the GL backend (option over PAMSIM_GL_BACKEND over MUJOCO_GL's
// headless values over the default, one clear line for an unknown name), the EGL device (option
// over EGL_DEVICE_ID over MUJOCO_EGL_DEVICE_ID) and the one-backend-per-process rule.
#include "sim/render/gl_context.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <stdexcept>

#include "base/input_error.h"

namespace pamsim {
namespace {

// Sets an environment variable for one scope, unsets it after (also when a test fails).
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const char* value) : name_(name) { ::setenv(name, value, 1); }
  ~ScopedEnv() { ::unsetenv(name_); }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

 private:
  const char* name_;
};

TEST(GlContextTest, OptionBeatsEnvironmentBeatsDefault) {
  ::unsetenv("PAMSIM_GL_BACKEND");
  EXPECT_EQ(choose_gl_backend(""), GlBackend::kOsmesa);
  EXPECT_EQ(choose_gl_backend("egl"), GlBackend::kEgl);
  ScopedEnv env("PAMSIM_GL_BACKEND", "egl");
  EXPECT_EQ(choose_gl_backend(""), GlBackend::kEgl);
  EXPECT_EQ(choose_gl_backend("osmesa"), GlBackend::kOsmesa);
}

TEST(GlContextTest, UnknownBackendNamesWhereItCameFrom) {
  try {
    choose_gl_backend("vulkan");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "--backend must be osmesa or egl, got 'vulkan'");
  }
  ScopedEnv env("PAMSIM_GL_BACKEND", "glx");
  try {
    choose_gl_backend("");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "PAMSIM_GL_BACKEND must be osmesa or egl, got 'glx'");
  }
}

TEST(GlContextTest, MujocoGlCountsAfterPamsimGlBackendAndOnlyForHeadlessValues) {
  ::unsetenv("PAMSIM_GL_BACKEND");
  {
    ScopedEnv mujoco("MUJOCO_GL", "egl");
    EXPECT_EQ(choose_gl_backend(""), GlBackend::kEgl);
    EXPECT_EQ(choose_gl_backend("osmesa"), GlBackend::kOsmesa);
    ScopedEnv own("PAMSIM_GL_BACKEND", "osmesa");  // pamsim's own variable is the more specific
    EXPECT_EQ(choose_gl_backend(""), GlBackend::kOsmesa);
  }
  for (const char* window_system : {"glfw", "glx", "EGL"}) {  // MuJoCo's, not headless
    ScopedEnv mujoco("MUJOCO_GL", window_system);
    EXPECT_EQ(choose_gl_backend(""), GlBackend::kOsmesa) << window_system;
  }
}

TEST(GlContextTest, EglDeviceFromOptionThenEnvironment) {
  ::unsetenv("EGL_DEVICE_ID");
  ::unsetenv("MUJOCO_EGL_DEVICE_ID");
  EXPECT_EQ(choose_egl_device(-1).index, -1);
  EXPECT_EQ(choose_egl_device(2).index, 2);
  EXPECT_EQ(choose_egl_device(2).source, "--gpu");
  ScopedEnv mujoco("MUJOCO_EGL_DEVICE_ID", "3");
  EXPECT_EQ(choose_egl_device(-1).index, 3);
  {
    ScopedEnv own("EGL_DEVICE_ID", "1");
    EXPECT_EQ(choose_egl_device(-1).index, 1);
    EXPECT_EQ(choose_egl_device(-1).source, "EGL_DEVICE_ID");
    EXPECT_EQ(choose_egl_device(0).index, 0);
  }
  for (const char* bad : {"x", "-1", "1.5", "1 ", "99999999999"}) {
    ScopedEnv own("EGL_DEVICE_ID", bad);
    try {
      choose_egl_device(-1);
      FAIL() << bad;
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()),
                std::string("EGL_DEVICE_ID must be a device number >= 0, got '") + bad + "'");
    }
  }
  EXPECT_THROW(choose_egl_device(-2), InputError);
}

TEST(GlContextTest, OneBackendPerProcess) {
  // MuJoCo binds GL functions once per process: a second backend is refused
  auto first = create_gl_context(GlBackend::kOsmesa, 64, 64);
  first->make_current();
  auto second = create_gl_context(GlBackend::kOsmesa, 32, 32);
  EXPECT_THROW(create_gl_context(GlBackend::kEgl, 64, 64), std::logic_error);
}

}  // namespace
}  // namespace pamsim

// gl_context_test.cc: choosing the GL backend (option over environment over the default,
// one clear line for an unknown name) and the one-backend-per-process rule.
#include "sim/render/gl_context.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <stdexcept>

#include "pam_actuator/input_error.h"

namespace pamsim {
namespace {

// Sets PAMSIM_GL_BACKEND for one test, restores "unset" after it.
class GlBackendEnv {
 public:
  explicit GlBackendEnv(const char* value) { ::setenv("PAMSIM_GL_BACKEND", value, 1); }
  ~GlBackendEnv() { ::unsetenv("PAMSIM_GL_BACKEND"); }
};

TEST(GlContextTest, OptionBeatsEnvironmentBeatsDefault) {
  ::unsetenv("PAMSIM_GL_BACKEND");
  EXPECT_EQ(choose_gl_backend(""), GlBackend::kOsmesa);
  EXPECT_EQ(choose_gl_backend("egl"), GlBackend::kEgl);
  GlBackendEnv env("egl");
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
  GlBackendEnv env("glx");
  try {
    choose_gl_backend("");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "PAMSIM_GL_BACKEND must be osmesa or egl, got 'glx'");
  }
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

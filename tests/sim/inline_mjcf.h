// inline_mjcf.h: loading a test's MJCF text (MuJoCo's tests keep tiny models inline) through
// MuJoCo's virtual file system, with pamsim's error handlers and actuator callback installed.
#pragma once

#include <gtest/gtest.h>

#include <cstring>
#include <memory>

#include "sim/core/mujoco_util.h"

namespace pamsim_test {

// The model, or null with a test failure carrying MuJoCo's message. `name` is the virtual
// file's name (mjVFS is large: heap, not stack).
inline pamsim::MjModelPtr load_inline(const char* xml, const char* name) {
  pamsim::install_mujoco_handlers();
  auto vfs = std::make_unique<mjVFS>();
  mj_defaultVFS(vfs.get());
  const int size = static_cast<int>(std::strlen(xml));
  mj_makeEmptyFileVFS(vfs.get(), name, size);
  std::memcpy(vfs->filedata[vfs->nfile - 1], xml, size);
  char error[512] = "";
  pamsim::MjModelPtr m(mj_loadXML(name, vfs.get(), error, sizeof(error)));
  mj_deleteVFS(vfs.get());
  EXPECT_TRUE(m) << error;
  return m;
}

}  // namespace pamsim_test
